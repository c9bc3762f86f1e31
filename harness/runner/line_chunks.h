#pragma once
// Reads a stream a chunk of lines at a time, as std::getline would split
// it ('\n' ends a line; a last line without one still counts), keeping only
// the current chunk's text: memory stays the same however long the input.
#include <cstddef>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace snell {

class LineChunks {
 public:
  explicit LineChunks(std::istream& in);

  // Up to `maxLines` further lines; fewer at the end of the stream, or
  // when the stream has no more to give without waiting (a pipe whose
  // writer waits for the answers to what it sent): the lines it has are
  // returned then, and the line begun stays for the next call. None once
  // the stream is done. The views stay valid until the next call.
  const std::vector<std::string_view>& next(std::size_t maxLines);

  // The number (from 1) of the first line of the last chunk.
  std::size_t firstLineNumber() const { return first_; }

  // The errno of a read that failed, which ended the lines early (0: the
  // stream was read to its end).
  int readError() const { return readError_; }

  // Whether the last chunk's last line ended without a newline: the end
  // of the stream, or a read cut short (by a signal, say) inside a line.
  bool lastLineUnterminated() const { return lastUnterminated_; }

  // A line longer than this is not kept (its view is empty, and
  // tooLong(k) says so): one endless line would otherwise hold the whole
  // input in memory, and a server's memory for any client.
  static constexpr std::size_t kMaxLineBytes = std::size_t{16} << 20;
  // Whether line k of the last chunk was longer than kMaxLineBytes.
  bool tooLong(std::size_t k) const { return k < tooLong_.size() && tooLong_[k]; }

 private:
  bool fill();  // reads more text; false at the end of the stream
  // Whether reading on would not wait (the stream's buffer, or its
  // showmanyc(), has more, or its end is known).
  bool moreWithoutWaiting() const;

  std::istream& in_;
  std::string text_;       // this chunk's lines, then the start of the next
  std::size_t start_ = 0;  // where the unread text begins in text_
  bool ended_ = false;
  bool lastUnterminated_ = false;
  int readError_ = 0;
  std::vector<std::string_view> lines_;
  std::vector<bool> tooLong_;
  std::size_t first_ = 1, read_ = 0;
};

}  // namespace snell

#include "runner/line_chunks.h"

#include <cerrno>
#include <cstring>

namespace snell {
namespace {
constexpr std::size_t kReadBytes = 1 << 20;
}

LineChunks::LineChunks(std::istream& in) : in_(in) {}

bool LineChunks::fill() {
  if (ended_) return false;
  // Waits for the first byte (or the end), then takes only what is there
  // without waiting: a read of a whole kReadBytes would wait on a pipe
  // whose writer sent a line and waits for its answer.
  errno = 0;
  if (in_.peek() == std::istream::traits_type::eof()) {
    // Taken at once: later calls may change errno.
    if (in_.bad()) readError_ = errno != 0 ? errno : EIO;
    ended_ = true;
    return false;
  }
  const std::size_t size = text_.size();
  text_.resize(size + kReadBytes);
  std::size_t got = 0;
  while (got < kReadBytes) {
    const std::streamsize n =
        in_.readsome(text_.data() + size + got, static_cast<std::streamsize>(kReadBytes - got));
    if (n <= 0) break;
    got += static_cast<std::size_t>(n);
  }
  text_.resize(size + got);
  return got > 0;
}

bool LineChunks::moreWithoutWaiting() const {
  std::streambuf* buffer = in_.rdbuf();
  return ended_ || !in_.good() || buffer == nullptr || buffer->in_avail() != 0;
}

const std::vector<std::string_view>& LineChunks::next(std::size_t maxLines) {
  // Drop the text of the chunk before; keep what is not yet split.
  text_.erase(0, start_);
  start_ = 0;
  lines_.clear();
  tooLong_.clear();
  lastUnterminated_ = false;
  // Offsets first: text_ may move while it grows.
  std::vector<std::pair<std::size_t, std::size_t>> spans;
  std::size_t scanned = 0;
  while (spans.size() < maxLines) {
    const void* found = std::memchr(text_.data() + scanned, '\n', text_.size() - scanned);
    if (found) {
      const auto end = static_cast<std::size_t>(static_cast<const char*>(found) - text_.data());
      const bool over = end - start_ > kMaxLineBytes;  // its newline came in the same read
      if (over) {
        tooLong_.resize(spans.size() + 1);
        tooLong_.back() = true;
      }
      spans.emplace_back(start_, over ? 0 : end - start_);
      start_ = scanned = end + 1;
      continue;
    }
    scanned = text_.size();
    if (text_.size() - start_ > kMaxLineBytes) {
      // The line is dropped as it is read, up to its newline.
      tooLong_.resize(spans.size() + 1);
      tooLong_.back() = true;
      spans.emplace_back(start_, 0);
      for (;;) {
        text_.resize(start_);
        if (!fill()) break;
        const void* newline = std::memchr(text_.data() + start_, '\n', text_.size() - start_);
        if (!newline) continue;
        text_.erase(start_,
                    static_cast<std::size_t>(static_cast<const char*>(newline) - text_.data()) + 1 -
                        start_);
        break;
      }
      scanned = start_;
      continue;
    }
    // Whole lines now rather than a full chunk later: a co-process waits
    // for its answers before it writes more.
    if (!spans.empty() && !moreWithoutWaiting()) break;
    if (fill()) continue;
    if (start_ < text_.size()) {  // a last line with no newline
      spans.emplace_back(start_, text_.size() - start_);
      start_ = text_.size();
      lastUnterminated_ = true;
    }
    break;
  }
  first_ = read_ + 1;
  read_ += spans.size();
  for (const auto& [at, length] : spans) lines_.emplace_back(text_.data() + at, length);
  return lines_;
}

}  // namespace snell

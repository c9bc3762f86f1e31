// The pieces under `snell eval`'s streaming: lines split a chunk at a time
// as std::getline splits them, and a pool that runs every block once.
#include <gtest/gtest.h>

#include <atomic>
#include <istream>
#include <sstream>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "runner/block_pool.h"
#include "runner/line_chunks.h"

namespace snell {
namespace {

std::vector<std::string> byGetline(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> byChunks(const std::string& text, std::size_t chunk,
                                  std::vector<std::size_t>* firsts = nullptr) {
  std::istringstream in(text);
  LineChunks chunks(in);
  std::vector<std::string> lines;
  for (;;) {
    const auto& next = chunks.next(chunk);
    if (next.empty()) break;
    EXPECT_LE(next.size(), chunk);
    if (firsts) firsts->push_back(chunks.firstLineNumber());
    EXPECT_EQ(chunks.firstLineNumber(), lines.size() + 1);
    lines.insert(lines.end(), next.begin(), next.end());
  }
  return lines;
}

TEST(LineChunks, SplitsAsGetlineDoes) {
  for (const std::string text : {"", "a", "a\n", "a\nb", "\n\n", "a\r\n\nb\n", " \n x"}) {
    SCOPED_TRACE(text);
    EXPECT_EQ(byChunks(text, 1), byGetline(text));
    EXPECT_EQ(byChunks(text, 2), byGetline(text));
    EXPECT_EQ(byChunks(text, 1000), byGetline(text));
  }
}

// Lines across the reader's 1 MiB reads, one longer than a read.
TEST(LineChunks, SplitsLongInputAcrossReads) {
  std::string text;
  for (int k = 0; k < 40000; ++k) text += std::string(static_cast<std::size_t>(k % 97), 'x') + "\n";
  text += std::string(3 << 20, 'y') + "\n" + "last";
  const auto expected = byGetline(text);
  std::vector<std::size_t> firsts;
  EXPECT_EQ(byChunks(text, 4096, &firsts), expected);
  // Full chunks of the 40,001 whole lines; an in-memory stream has nothing
  // more to give at its end, so its whole lines come before the last,
  // unfinished one, which comes alone.
  EXPECT_EQ(firsts.size(), (expected.size() - 1 + 4095) / 4096 + 1);
  EXPECT_EQ(byChunks(text, 1 << 30), expected);
}

// A line past kMaxLineBytes is not kept: an endless line (eval /dev/zero)
// held the whole input in memory until the allocator gave up, a server's
// included. Its view is empty and tooLong() says so; the lines around it,
// its number and the end of the input stay as they were.
TEST(LineChunks, ALineTooLongIsDroppedToItsEndAndSaidSo) {
  const std::string tooLong(LineChunks::kMaxLineBytes + (3 << 20) + 5, 'x');
  for (const std::string& tail : {std::string("\nafter\n"), std::string()}) {
    std::istringstream in("before\n" + tooLong + tail);
    LineChunks chunks(in);
    const std::vector<std::string_view> lines = chunks.next(10);
    const std::vector<std::string_view> expected =
        tail.empty() ? std::vector<std::string_view>{"before", ""}
                     : std::vector<std::string_view>{"before", "", "after"};
    EXPECT_EQ(lines, expected);
    EXPECT_FALSE(chunks.tooLong(0));
    EXPECT_TRUE(chunks.tooLong(1));
    EXPECT_FALSE(chunks.tooLong(2));
    EXPECT_TRUE(chunks.next(10).empty());
  }
  EXPECT_EQ(byChunks(std::string(LineChunks::kMaxLineBytes, 'y') + "\nz", 5).front().size(),
            LineChunks::kMaxLineBytes);  // at the limit: kept
  // One byte over, its newline in the same read as its end.
  std::istringstream in(std::string(LineChunks::kMaxLineBytes + 1, 'y') + "\nz\n");
  LineChunks chunks(in);
  EXPECT_EQ(chunks.next(5), (std::vector<std::string_view>{"", "z"}));
  EXPECT_TRUE(chunks.tooLong(0));
  EXPECT_FALSE(chunks.tooLong(1));
}

// A pipe whose writer has sent some lines and waits for their answers
// before it sends more: a read past what was sent would wait forever.
class WaitingWriter : public std::streambuf {
 public:
  explicit WaitingWriter(std::string sent) { send(std::move(sent), false); }
  // Sends more, and with `close` ends the input after it.
  void send(std::string more, bool close) {
    sent_ = std::move(more);
    closed_ = close;
    setg(sent_.data(), sent_.data(), sent_.data() + sent_.size());
  }
  bool waitedOn() const { return waitedOn_; }

 protected:
  int_type underflow() override {
    if (!closed_) waitedOn_ = true;  // a real pipe would block here
    return traits_type::eof();
  }
  std::streamsize showmanyc() override { return closed_ ? -1 : 0; }

 private:
  std::string sent_;
  bool closed_ = false;
  bool waitedOn_ = false;
};

// `snell eval` as a co-process: the lines sent so far are answered without
// waiting for a full chunk (or the end of the input), which the writer
// would wait on in turn. The line begun stays for the next chunk.
TEST(LineChunks, AWriterThatWaitsGetsItsWholeLinesAtOnce) {
  WaitingWriter pipe("a\nb\nc");
  std::istream in(&pipe);
  LineChunks chunks(in);
  EXPECT_EQ(chunks.next(1000), (std::vector<std::string_view>{"a", "b"}));
  EXPECT_FALSE(pipe.waitedOn());
  EXPECT_FALSE(chunks.lastLineUnterminated());
  pipe.send("d\ne\n", true);
  EXPECT_EQ(chunks.next(1000), (std::vector<std::string_view>{"cd", "e"}));
  EXPECT_EQ(chunks.firstLineNumber(), 3u);
  EXPECT_TRUE(chunks.next(1000).empty());
  EXPECT_FALSE(pipe.waitedOn());
}

TEST(BlockPool, RunsEveryBlockOnceOnEveryThread) {
  for (unsigned threads : {1u, 2u, 5u}) {
    BlockPool pool(threads);
    EXPECT_EQ(pool.threads(), threads);
    for (std::size_t count : {0, 1, 255, 256, 1000}) {
      std::vector<std::atomic<int>> seen(count);
      bool firstOnCaller = false;
      const auto caller = std::this_thread::get_id();
      pool.run(
          count, 16,
          [&](std::size_t begin, std::size_t end) {
            EXPECT_LE(end - begin, 16u);
            for (std::size_t k = begin; k < end; ++k) ++seen[k];
          },
          [&] { firstOnCaller = std::this_thread::get_id() == caller; });
      EXPECT_TRUE(firstOnCaller);
      for (std::size_t k = 0; k < count; ++k) EXPECT_EQ(seen[k], 1) << k;
    }
  }
}

TEST(BlockPool, RethrowsOnTheCallerAndKeepsWorking) {
  BlockPool pool(3);
  EXPECT_THROW(pool.run(100, 1,
                        [](std::size_t begin, std::size_t) {
                          if (begin == 57) throw std::runtime_error("block 57");
                        }),
               std::runtime_error);
  EXPECT_THROW(
      pool.run(
          10, 1, [](std::size_t, std::size_t) {}, [] { throw std::runtime_error("the draw"); }),
      std::runtime_error);
  std::atomic<std::size_t> total = 0;
  pool.run(100, 7, [&](std::size_t begin, std::size_t end) { total += end - begin; });
  EXPECT_EQ(total, 100u);
}

}  // namespace
}  // namespace snell

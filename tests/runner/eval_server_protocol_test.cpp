// The request header and reply trailer of `snell serve`: each round-trips,
// and text that is not one of them is refused rather than taken as one;
// and a client does not wait forever on a server that never answers.
#include "runner/eval_server_protocol.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <sstream>
#include <string>

#include "core/errors.h"
#include "runner/eval_client.h"
#include "runner/unix_socket.h"

namespace {

using namespace snell;

TEST(EvalServerProtocol, RequestHeaderRoundTrips) {
  const std::string line = requestHeaderLine({"vk", "abc123"});
  ASSERT_EQ(line.back(), '\n');
  const EvalRequest request = parseRequestHeader(std::string_view(line).substr(0, line.size() - 1));
  EXPECT_EQ(request.backend, "vk");
  EXPECT_EQ(request.build, "abc123");
}

TEST(EvalServerProtocol, AHeaderThatIsNotOursIsRefused) {
  for (const char* text :
       {"", "{\"fn\":\"refract\"}", "{\"snell_eval\":2,\"backend\":\"gl\",\"build\":\"\"}",
        "{\"snell_eval\":1,\"backend\":3,\"build\":\"\"}", "not json",
        "{\"snell_eval\":\"1\",\"backend\":\"gl\",\"build\":\"\"}", "[1]"})
    EXPECT_THROW(parseRequestHeader(text), UsageError) << text;
}

TEST(EvalServerProtocol, TrailerRoundTripsAfterItsMark) {
  EvalReply reply;
  reply.summary.answered = 7;
  reply.summary.malformed = 1;
  reply.summary.outsideSpec = 2;
  reply.summary.firstMalformedLine = 5;
  reply.summary.firstMalformedReason = "not valid JSON (\x1e)";
  reply.error = "it broke";
  reply.serverStopped = true;
  const std::string line = replyTrailerLine(reply);
  ASSERT_EQ(line.front(), kEvalTrailerMark);
  EXPECT_EQ(line.find(kEvalTrailerMark, 1), std::string::npos) << "the mark is escaped inside";
  const EvalReply back = parseReplyTrailer(std::string_view(line).substr(1));
  EXPECT_EQ(back.summary.answered, 7u);
  EXPECT_EQ(back.summary.malformed, 1u);
  EXPECT_EQ(back.summary.outsideSpec, 2u);
  EXPECT_EQ(back.summary.firstMalformedLine, 5u);
  EXPECT_EQ(back.summary.firstMalformedReason, reply.summary.firstMalformedReason);
  EXPECT_EQ(back.error, "it broke");
  EXPECT_TRUE(back.serverStopped);
}

TEST(EvalServerProtocol, ATruncatedTrailerIsASetupError) {
  const std::string line = replyTrailerLine(EvalReply{});
  EXPECT_THROW(parseReplyTrailer(std::string_view(line).substr(1, line.size() / 2)), SetupError);
  EXPECT_THROW(parseReplyTrailer("{}"), SetupError);
}

}  // namespace

namespace {

// A server that takes the connection and never answers (a `snell serve`
// stopped by Ctrl-Z): the client waited forever. It gives up after the
// silence limit, saying why.
TEST(EvalClient, AServerThatSendsNothingIsGivenUpOn) {
  const std::string path =
      (std::filesystem::temp_directory_path() / fmt::format("snell-silent-{}.sock", ::getpid()))
          .string();
  const UniqueFd listening = listenAt(path);
  int input[2];
  ASSERT_EQ(::pipe(input), 0);
  const std::string line = R"({"fn":"reflect","I":[0.6,-0.8],"N":[0,1]})"
                           "\n";
  ASSERT_EQ(::write(input[1], line.data(), line.size()), static_cast<ssize_t>(line.size()));
  ::close(input[1]);
  std::ostringstream answers;
  const auto start = std::chrono::steady_clock::now();
  try {
    (void)evaluateOnServer(path, "gl", input[0], answers, std::chrono::milliseconds(1000));
    ADD_FAILURE() << "no error from a server that never answered";
  } catch (const SetupError& error) {
    EXPECT_NE(std::string(error.what())
                  .find(path + ": the server sent nothing for 1 s: it is "
                               "stopped (Ctrl-Z in its terminal"),
              std::string::npos)
        << error.what();
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(30));
  EXPECT_EQ(answers.str(), "");
  ::close(input[0]);
  std::filesystem::remove(path);
}

}  // namespace

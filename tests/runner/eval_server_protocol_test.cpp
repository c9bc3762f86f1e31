// The request header and reply trailer of `snell serve`: each round-trips,
// and text that is not one of them is refused rather than taken as one.
#include "runner/eval_server_protocol.h"

#include <gtest/gtest.h>

#include "core/errors.h"

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

// The GL info log's placed messages, from the logs the drivers wrote: the
// line a listing's pinned compile error is looked for at.
#include <gtest/gtest.h>

#include <string>

#include "backends/gl/gl_diagnostics.h"

namespace {

using snell::gl::parseInfoLog;

// llvmpipe (Mesa 22.3.6) on shaders/blog/fresnel-as-published/fresnel.frag.
constexpr const char* kMesaLog =
    "0:4(19): error: syntax error, unexpected NEW_IDENTIFIER, expecting '{'\n";

// NVIDIA 580.159.04 (H200, gl:gpu) on shaders/blog/chromatic-as-published/
// chromatic.frag, as `snell run` printed it there.
constexpr const char* kNvidiaLog =
    "0(6) : error C0000: syntax error, unexpected identifier, expecting '{' at token \"tex\"\n"
    "0(10) : warning C1503: undefined variable \"tex\"\n"
    "0(10) : warning C7623: implicit narrowing of type from \"vec3\" to \"float\"\n";

// NVIDIA's link log around a vertex warning.
constexpr const char* kNvidiaLinkLog =
    "Vertex info\n"
    "-----------\n"
    "0(3) : warning C7011: implicit cast from \"float\" to \"vec4\"\n";

TEST(GlInfoLog, MesaPlacesItsErrorAtTheLine) {
  const auto found = parseInfoLog("fragment", kMesaLog);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].stage, "fragment");
  EXPECT_EQ(found[0].line, 4);
  EXPECT_TRUE(found[0].error);
  EXPECT_EQ(found[0].message, "syntax error, unexpected NEW_IDENTIFIER, expecting '{'");
}

TEST(GlInfoLog, NvidiaPlacesItsErrorAtTheLineWithoutItsCode) {
  const auto found = parseInfoLog("fragment", kNvidiaLog);
  ASSERT_EQ(found.size(), 3u);
  EXPECT_EQ(found[0].line, 6);
  EXPECT_TRUE(found[0].error);
  EXPECT_EQ(found[0].message,
            "syntax error, unexpected identifier, expecting '{' at token \"tex\"");
  EXPECT_EQ(found[1].line, 10);
  EXPECT_FALSE(found[1].error);
  EXPECT_FALSE(found[2].error);
}

TEST(GlInfoLog, HeadingsAndUnplacedLinesPlaceNothing) {
  const auto found = parseInfoLog("link", kNvidiaLinkLog);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].line, 3);
  EXPECT_FALSE(found[0].error);
  EXPECT_TRUE(parseInfoLog("vertex",
                           "error: linking failed\n(6) : error C0000: x\n"
                           "0(x) : error C0000: y\n0:6: error: z\n")
                  .empty());
}

}  // namespace

namespace {

// A line number past int's range (a shader's own `#line 99999999999`) made
// std::stoi throw, and the compile error was a Crash: it now names no line.
TEST(GlInfoLog, ALineNumberPastIntsRangeNamesNoLine) {
  const auto found =
      parseInfoLog("vertex", "0:99999999999(3): error: syntax error, unexpected ';'\n");
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].line, 0);
  EXPECT_EQ(found[0].message, "syntax error, unexpected ';'");
}

}  // namespace

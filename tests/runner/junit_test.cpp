// The JUnit report: a failure is a <failure> with the reason, NotSupported
// a <skipped> with the manifest's reason, and a listing that must not
// compile passes with its diagnostic quoted.
#include "report/junit.h"

#include <gtest/gtest.h>

namespace snell {
namespace {

CaseResult result(const char* id, Status status, const char* message) {
  CaseResult r;
  r.caseId = id;
  r.backend = "gl";
  r.status = status;
  r.message = message;
  return r;
}

TEST(JUnit, StatusesBecomeFailuresSkipsAndQuotedDiagnostics) {
  const std::string xml = toJUnitXml({
      result("a/pass", Status::Pass, ""),
      result("b/fail", Status::Fail, "Refract: 3 of 99 components outside the spec interval"),
      result("c/unsupported", Status::NotSupported, "no legacy built-ins on Vulkan"),
      result("d/expected", Status::ExpectedCompileError,
             "does not compile, as expected:\n0:4(8): error: syntax error"),
  });
  EXPECT_NE(xml.find("tests=\"4\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("failures=\"1\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("skipped=\"1\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("Refract: 3 of 99 components outside the spec interval"), std::string::npos);
  EXPECT_NE(xml.find("<skipped message=\"no legacy built-ins on Vulkan\""), std::string::npos)
      << xml;
  EXPECT_NE(xml.find("0:4(8): error: syntax error"), std::string::npos) << xml;
}

// `time` is an xs:decimal in JUnit's schema: no exponent, however short the
// case (a NotSupported one takes microseconds).
TEST(JUnit, TimesAreDecimalsWithoutAnExponent) {
  CaseResult quick = result("a/unsupported", Status::NotSupported, "reason");
  quick.seconds = 4.057e-06;
  CaseResult slow = result("b/pass", Status::Pass, "");
  slow.seconds = 12.5;
  const std::string xml = toJUnitXml({quick, slow});
  EXPECT_NE(xml.find("time=\"0.000004\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("time=\"12.500000\""), std::string::npos) << xml;
  EXPECT_EQ(xml.find("e-0"), std::string::npos) << xml;
}

// XML 1.0 cannot carry most control characters, not even as &#1;: a
// crashed worker's stderr (an ESC of a coloured log) is spelled out instead,
// so every XML parser reads the file.
TEST(JUnit, ControlCharactersInMessagesAreSpelledOutNotWritten) {
  const std::string xml = toJUnitXml({
      result("a/crash", Status::Crash, "worker stderr: \x1b[31mabort\x1b[0m\x01 done\ttab"),
      result("b/unsupported", Status::NotSupported, "reason\x02"),
  });
  for (const char c : xml)
    EXPECT_FALSE(static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t' && c != '\r')
        << "a raw control character " << static_cast<int>(c);
  EXPECT_EQ(xml.find("&#"), std::string::npos) << xml;
  EXPECT_NE(xml.find("\\x1b[31mabort\\x1b[0m\\x01 done\ttab"), std::string::npos) << xml;
  EXPECT_NE(xml.find("reason\\x02"), std::string::npos) << xml;
}

// A byte that is not UTF-8 (a multibyte character cut short in a driver's
// log) makes the file unreadable to XML parsers as well: spelled out, while
// well-formed UTF-8 is kept.
TEST(JUnit, BytesThatAreNotUtf8AreSpelledOutAndUtf8IsKept) {
  const std::string xml = toJUnitXml(
      {result("a/crash", Status::Crash, "cut \xC3 here, \xFF, caf\xC3\xA9 \xE2\x82\xAC ok")});
  EXPECT_NE(xml.find("cut \\xc3 here, \\xff, caf\xC3\xA9 \xE2\x82\xAC ok"), std::string::npos)
      << xml;
}

}  // namespace
}  // namespace snell

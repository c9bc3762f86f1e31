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

}  // namespace
}  // namespace snell

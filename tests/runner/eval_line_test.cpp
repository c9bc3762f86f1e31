// What `snell eval` says about a line that is not a call: each message names
// what is wrong and what to write instead.
#include "runner/eval_line.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "core/errors.h"

namespace snell {
namespace {

// The UsageError a line gives, or "" when it is a call.
std::string refusal(const std::string& text) {
  try {
    parseEvalLine(text);
  } catch (const UsageError& error) {
    return error.what();
  }
  return "";
}

TEST(EvalLine, AMistakeIsNamedWithWhatToWrite) {
  for (const auto& [line, expected] : std::vector<std::pair<std::string, std::string>>{
           // A key in the wrong case is named: keys are case-sensitive.
           {R"({"fn":"refract","I":[0,-1],"N":[0,1],"Eta":1.5})",
            R"(refract needs a number "eta" (the line has "Eta": keys are case-sensitive))"},
           {R"({"fn":"reflect","I":[0,-1],"n":[0,1]})",
            R"(missing "N" (the line has "n": keys are case-sensitive))"},
           {R"({"Fn":"reflect","I":[0,-1],"N":[0,1]})",
            R"(missing "fn" (the line has "Fn": keys are case-sensitive))"},
           // Present, but no name of a function.
           {R"({"fn":5,"I":[0,-1],"N":[0,1]})", R"("fn" must be a string)"},
           // JSON leaves open which of two values counts.
           {R"({"fn":"reflect","I":[0,-1],"N":[0,1],"I":[1,0]})",
            R"("I" is given twice; give each key once)"},
           {R"({"fn":"fresnel","model":"exact","cos_i":0.8,"n1":1,"n2":1.5,"n2":1.3})",
            R"("n2" is given twice)"}}) {
    EXPECT_NE(refusal(line).find(expected), std::string::npos) << line << ": " << refusal(line);
  }
  // A finite number past the float range would be read as an infinity the
  // line did not write; the largest float and what rounds to it are read.
  EXPECT_NE(
      refusal(R"({"fn":"reflect","I":[1e39,-0.8],"N":[0,1]})")
          .find(R"("I" holds 1e+39, past the largest float (3.4028235e+38): it would be read )"
                R"(as an infinity; write "inf" or "-inf" for one)"),
      std::string::npos)
      << refusal(R"({"fn":"reflect","I":[1e39,-0.8],"N":[0,1]})");
  EXPECT_NE(refusal(R"({"fn":"refract","I":[0,-1],"N":[0,1],"eta":-3.4028235677973366e38})")
                .find(R"("eta" holds)"),
            std::string::npos);
  EXPECT_EQ(refusal(R"({"fn":"refract","I":[3.4028235677973362e38],"N":[1],"eta":1})"), "");
  // A value of megabytes is not echoed whole.
  EXPECT_LT(refusal(R"({"fn":")" + std::string(1 << 20, 'x') + R"(","I":[1],"N":[1]})").size(),
            400u);
  // A key twice inside a nested value is that value's business, not the line's.
  EXPECT_EQ(refusal(R"({"fn":"reflect","I":[0,-1],"N":[0,1],"note":{"a":1,"a":2}})"), "");
  EXPECT_EQ(refusal(R"({"fn":"refract","I":[0,-1],"N":[0,1],"eta":1.5})"), "");
}

}  // namespace
}  // namespace snell

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
  // A key twice inside a nested value is that value's business, not the line's.
  EXPECT_EQ(refusal(R"({"fn":"reflect","I":[0,-1],"N":[0,1],"note":{"a":1,"a":2}})"), "");
  EXPECT_EQ(refusal(R"({"fn":"refract","I":[0,-1],"N":[0,1],"eta":1.5})"), "");
}

}  // namespace
}  // namespace snell

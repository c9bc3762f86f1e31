// The fast reader of common eval lines gives what nlohmann and
// parseEvalObject give, bit for bit, or leaves the line to them.
#include "runner/eval_line_fast.h"

#include <gtest/gtest.h>

#include <cstring>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "core/errors.h"
#include "eval_input.h"
#include "runner/eval_line.h"

namespace snell {
namespace {

std::optional<BuiltinCall> slowPath(const std::string& text) {
  try {
    const nlohmann::json object = nlohmann::json::parse(text);
    return parseEvalObject(object);
  } catch (const nlohmann::json::exception&) {
  } catch (const UsageError&) {
  }
  return std::nullopt;
}

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (!sameBits(a[k], b[k])) return false;
  return true;
}

// Where the fast reader decides, it decides as the slow path does.
void expectAgrees(const std::string& text) {
  const std::optional<BuiltinCall> fast = parseCommonEvalLine(text);
  if (!fast) return;
  const std::optional<BuiltinCall> slow = slowPath(text);
  ASSERT_TRUE(slow) << "the fast reader accepted a line the slow path rejects: " << text;
  EXPECT_EQ(fast->fn, slow->fn) << text;
  EXPECT_TRUE(sameBits(fast->I, slow->I)) << text;
  EXPECT_TRUE(sameBits(fast->N, slow->N)) << text;
  EXPECT_TRUE(sameBits(fast->eta, slow->eta)) << text;
}

TEST(EvalLineFast, ReadsTheCommonShapeAsNlohmannDoes) {
  const std::vector<std::string> common = {
      R"({"fn":"refract","I":[0.3794646,0.02607892,-0.92483866],"N":[-0.49012497,-0.049920667,0.87022144],"eta":0.68945324})",
      R"({"fn":"reflect","I":[0.6,-0.8],"N":[0,1]})",
      R"({"fn":"reflect","I":[0.6,-0.8],"N":[0,1],"eta":3})",
      R"( { "eta" : 1.5E+0 , "N" : [ -0 , 1 ] , "I" : [ 1e-3 , -1 ] , "fn" : "refract" } )",
      R"({"fn":"refract","I":[-0],"N":[-0.0],"eta":-0})",
      R"({"fn":"refract","I":[1,2,3,4],"N":[9007199254740993,-9223372036854775808,18446744073709551615,1e-300],"eta":1})",
      R"({"fn":"refract","I":[3.4028235677973362e38,1e-46,0.1],"N":[0,1,0],"eta":0.66})",
      R"({"fn":"refract","I":[99999999999999999999999,-99999999999999999999999,0],"N":[0,1,0],"eta":1})",
      "{\"fn\":\"reflect\",\"I\":[1],\"N\":[1]}\r",
  };
  for (const std::string& text : common) {
    EXPECT_TRUE(parseCommonEvalLine(text)) << "left to the slow path: " << text;
    expectAgrees(text);
  }
  // Past the float range (the first value rounds up to an infinity): left
  // to the slow path, which refuses it.
  for (const std::string text :
       {R"({"fn":"refract","I":[3.4028235677973366e38],"N":[1],"eta":1})",
        R"({"fn":"refract","I":[1],"N":[-1e39],"eta":1})",
        R"({"fn":"refract","I":[1],"N":[1],"eta":340282356779733661637539395458142568448})"}) {
    EXPECT_FALSE(parseCommonEvalLine(text)) << text;
    EXPECT_THROW(parseEvalLine(text), UsageError) << text;
  }
  // Underflow: nlohmann reads 1e-400 as strtod does; either way, the same call.
  expectAgrees(R"({"fn":"refract","I":[1e-400],"N":[-1e-400],"eta":1})");
}

TEST(EvalLineFast, LeavesEverythingElseToTheSlowPath) {
  const std::vector<std::string> others = {
      R"({"fn":"refract","I":["nan",0,0],"N":[0,1,0],"eta":1})",
      R"({"fn":"refract","I":[0,0,0],"N":[0,1,0],"eta":1,"id":7})",
      R"({"fn":"refract","fn":"reflect","I":[0,0],"N":[0,1]})",
      R"({"fn":"refr\u0061ct","I":[0,0],"N":[0,1],"eta":1})",
      R"({"fn":"refract","I":[01],"N":[1],"eta":1})",
      R"({"fn":"refract","I":[.5],"N":[1],"eta":1})",
      R"({"fn":"refract","I":[5.],"N":[1],"eta":1})",
      R"({"fn":"refract","I":[+5],"N":[1],"eta":1})",
      R"({"fn":"refract","I":[1e400],"N":[1],"eta":1})",
      R"({"fn":"refract","I":[1,2],"N":[1],"eta":1})",
      R"({"fn":"refract","I":[1],"N":[1]})",
      R"({"fn":"refract","I":[],"N":[],"eta":1})",
      R"({"fn":"refract","I":[1,2,3,4,5],"N":[1,2,3,4,5],"eta":1})",
      R"({"fn":"fresnel","model":"exact","cos_i":0.8,"n1":1,"n2":1.5})",
      R"({"fn":"refract","I":[1],"N":[1],"eta":1} x)",
      R"({"fn":"refract","I":[1],"N":[1],"eta":1},)",
      R"([{"fn":"refract","I":[1],"N":[1],"eta":1}])",
      "\xEF\xBB\xBF{\"fn\":\"reflect\",\"I\":[1],\"N\":[1]}",
  };
  for (const std::string& text : others) EXPECT_FALSE(parseCommonEvalLine(text)) << text;
}

// Lines of every shape, each mutated many ways (a byte changed, dropped or
// doubled): wherever the fast reader accepts, it agrees.
TEST(EvalLineFast, AgreesWithTheSlowPathOnMutatedLines) {
  std::mt19937 random(13);
  const std::string alphabet = "{}[],:\"-+.eE0123456789 \tfnIrNaeclt";
  for (int k = 0; k < 200; ++k) {
    const std::string line = testing::evalLineOfEveryShape(k);
    expectAgrees(line);
    for (int m = 0; m < 100 && !line.empty(); ++m) {
      std::string mutated = line;
      const std::size_t at = random() % mutated.size();
      switch (random() % 3) {
        case 0:
          mutated[at] = alphabet[random() % alphabet.size()];
          break;
        case 1:
          mutated.erase(at, 1);
          break;
        default:
          mutated.insert(at, 1, mutated[at]);
      }
      expectAgrees(mutated);
    }
  }
}

}  // namespace
}  // namespace snell

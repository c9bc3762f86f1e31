#include "core/fragment_probes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "core/errors.h"

namespace snell {
namespace {

const char* kListing =
    "#version 140\n"                                       // 1
    "// void main() { in a comment }\n"                    // 2
    "uniform samplerCube cube;\n"                          // 3
    "in vec3 v;\n"                                         // 4
    "out vec4 color;\n"                                    // 5
    "void main()\n"                                        // 6
    "{\n"                                                  // 7
    "  vec3 r = refract(normalize(v), vec3(0, 0, 1),\n"    // 8
    "                   0.9);  // ends here\n"             // 9
    "  float f = r.z;\n"                                   // 10
    "  color = texture(cube, r);\n"                        // 11
    "}\n";                                                 // 12

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(FragmentProbes, WritesAfterTheStatementAndKeepsEveryLineNumber) {
  const std::vector<FragmentProbe> probes = {{"r", ValueType::Vec3, 9}, {"f", ValueType::Float, 10}};
  const std::string out = insertFragmentProbes(kListing, "x.frag", probes, ProbeOutputStyle::Outputs);
  const std::vector<std::string> before = linesOf(kListing), after = linesOf(out);
  ASSERT_EQ(after.size(), before.size());
  // Every published line is still there, on its own number.
  for (std::size_t k = 0; k < before.size(); ++k) {
    const std::string published = before[k].substr(0, before[k].find("//"));
    std::string code = published;
    code.erase(code.find_last_not_of(' ') + 1);
    EXPECT_NE(after[k].find(code), std::string::npos) << "line " << k + 1 << ": " << after[k];
  }
  EXPECT_EQ(after[5], "out vec4 snell_probe_1; out vec4 snell_probe_2; void main()");
  EXPECT_EQ(after[6], "{ snell_probe_1 = vec4(0.0); snell_probe_2 = vec4(0.0);");
  EXPECT_EQ(after[8],
            "                   0.9); snell_probe_1 = vec4((r), 1.0);  // ends here");
  EXPECT_EQ(after[9], "  float f = r.z; snell_probe_2 = vec4((f), 0.0, 0.0, 1.0);");
  EXPECT_EQ(after[1], before[1]);  // the comment's main() is left alone
}

TEST(FragmentProbes, LegacyOutputsMoveToFragData) {
  const std::string legacy =
      "varying vec3 v;\n"
      "void main() {\n"
      "  vec3 n = normalize(v);\n"
      "  gl_FragColor = vec4(n, 1.0);\n"
      "}\n";
  ASSERT_EQ(probeOutputStyleFor(legacy), ProbeOutputStyle::FragData);
  EXPECT_EQ(probeOutputStyleFor(kListing), ProbeOutputStyle::Outputs);
  const std::string out =
      insertFragmentProbes(legacy, "l.frag", {{"n", ValueType::Vec3, 3}}, ProbeOutputStyle::FragData);
  EXPECT_EQ(out,
            "varying vec3 v;\n"
            "void main() { gl_FragData[1] = vec4(0.0);\n"
            "  vec3 n = normalize(v); gl_FragData[1] = vec4((n), 1.0);\n"
            "  gl_FragData[0] = vec4(n, 1.0);\n"
            "}\n");
}

// The name a probe's output gets and the location it asks for go together.
TEST(FragmentProbes, OutputNamesGiveTheirLocations) {
  for (std::size_t index = 0; index < 7; ++index)
    EXPECT_EQ(probeOutputLocation(probeOutputName(index)), static_cast<int>(index) + 1);
  for (const char* other : {"FragColor", "snell_probe_", "snell_probe_0", "snell_probe_12",
                            "snell_probe_x", "my_snell_probe_1"})
    EXPECT_EQ(probeOutputLocation(other), std::nullopt) << other;
}

TEST(FragmentProbes, NoProbesLeavesTheSourceAlone) {
  EXPECT_EQ(insertFragmentProbes(kListing, "x.frag", {}, ProbeOutputStyle::FragData), kListing);
}

void expectUsageError(const std::string& source, FragmentProbe probe, const std::string& part) {
  try {
    insertFragmentProbes(source, "x.frag", {probe}, ProbeOutputStyle::Outputs);
    FAIL() << "no error for line " << probe.line;
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find(part), std::string::npos) << error.what();
  }
}

TEST(FragmentProbes, BadLinesAreClearErrors) {
  expectUsageError(kListing, {"r", ValueType::Vec3, 8}, "x.frag:8: capture `r` is read after this "
                                                        "line, which does not end a statement");
  expectUsageError(kListing, {"r", ValueType::Vec3, 4}, "x.frag:4: capture `r` is read after this "
                                                        "line, which is not inside main()");
  expectUsageError(kListing, {"r", ValueType::Vec3, 12}, "not inside main()");
  expectUsageError(kListing, {"r", ValueType::Vec3, 40}, "x.frag:40: no such line (the file has 12)");
  expectUsageError(kListing, {"r", ValueType::Vec4, 10}, "only float, vec2 and vec3");
  expectUsageError("// void main() {}\n", {"r", ValueType::Vec3, 1}, "x.frag: no `void main(`");
  expectUsageError("void main() {\n  float x = 1.0;\n", {"x", ValueType::Float, 2},
                   "x.frag:1: main() has no closing brace");
}

}  // namespace
}  // namespace snell

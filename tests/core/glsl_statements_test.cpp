#include "core/glsl_statements.h"

#include <gtest/gtest.h>

namespace snell {
namespace {

TEST(GlslStatements, MainsOwnStatementsWithTheirLines) {
  const std::string source = R"(uniform float k; // a comment; with a semicolon
float helper(float x) { return x; }
void main()
{
    vec3 a = vec3(1.0,
                  2.0, 3.0);  /* ; */
    for (int i = 0; i < 3; ++i) { a += 1.0; }
    if (k > 0.0) {
        vec3 hidden = a;
    }
    vec3 b = a.xyz * helper(k);
}
)";
  const std::vector<GlslStatement> s = mainStatements(source);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[0].text.substr(0, 8), "vec3 a =");
  EXPECT_EQ(s[0].firstLine, 5);
  EXPECT_EQ(s[0].lastLine, 6);
  EXPECT_EQ(s[0].depth, 0);
  EXPECT_EQ(s[1].text, "a += 1.0");  // the loop's body, not its header
  EXPECT_EQ(s[1].depth, 1);
  EXPECT_EQ(s[2].text, "vec3 hidden = a");
  EXPECT_EQ(s[2].lastLine, 9);
  EXPECT_EQ(s[2].depth, 1);
  EXPECT_EQ(s[3].text, "vec3 b = a.xyz * helper(k)");
  EXPECT_EQ(s[3].firstLine, 11);
  EXPECT_EQ(s[3].lastLine, 11);
  EXPECT_EQ(s[3].depth, 0);
  EXPECT_TRUE(mainStatements("void helper() { int a; }").empty());
}

TEST(GlslStatements, IdentifiersSkipNumbersAndSwizzles) {
  EXPECT_EQ(identifiersIn("vec3 b = a.xyz * 1.5e2 + helper(k, a)"),
            (std::vector<std::string>{"vec3", "b", "a", "helper", "k"}));
}

}  // namespace
}  // namespace snell

namespace snell {
namespace {

TEST(GlslStatements, MainIsFoundOnlyAsVoidMainWithItsBody) {
  EXPECT_EQ(mainBody("void main(void) {}"), 17u);
  EXPECT_EQ(mainBody("void\n  main ( )\n{ }"), 17u);
  EXPECT_EQ(mainBody("void mainly() {} float main2() {}"), std::string::npos);
  EXPECT_EQ(mainBody("int main() {}"), std::string::npos);
  EXPECT_EQ(mainBody("void main();"), std::string::npos);  // a prototype has no body
  EXPECT_EQ(mainBody("void main();\nvoid main() { }"), 26u);
}

}  // namespace
}  // namespace snell

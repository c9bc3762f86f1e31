#pragma once
// The global declarations of a GLSL source, read as text: enough to check a
// manifest against the listing it describes before any driver is loaded
// (a uniform bound by the manifest that the shader does not declare, a
// captured output that does not exist, a mat3 bound to a mat4).
#include <string>
#include <vector>

namespace snell {

struct GlslDeclaration {
  std::string qualifier;  // "uniform", "in", "out", "attribute", "varying"
  std::string type;       // "mat4", "vec3", "samplerCube", ...
  std::string name;
  int line = 0;
};

// The source with every comment replaced by spaces, character for
// character, newlines kept: positions and line numbers stay as they were.
std::string withoutComments(const std::string& source);

// Global `uniform/in/out/attribute/varying TYPE NAME[, NAME...];`
// declarations outside comments and blocks; layout(...) and precision
// qualifiers are skipped.
std::vector<GlslDeclaration> readGlobalDeclarations(const std::string& source);

}  // namespace snell

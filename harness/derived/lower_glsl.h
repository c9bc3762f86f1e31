#pragma once
// The derived oracle's front end: glslang parses the listing as published
// and its AST (main() and the functions it calls) is lowered into a
// Program (ir.h). The AST rather than SPIR-V, because the AST keeps what
// the precision rules depend on: the expression as written (a
// matrix * vector, a dot(), a refract() stays one built-in with its
// inherited precision) and the source lines for messages.
//
// Constant expressions: glslang folds `const` values in double, which would
// leave only the folded value and hide the fp32 evaluation a driver may
// equally use (GLSL 4.60 section 4.3.3 allows either). The front end blanks
// the `const` qualifiers before parsing (same length, so lines and columns
// stay), so that a constant reaches the oracle as its expression over its
// literals, and Interval's literal tracking (oracle/interval.h) gives both
// the run-time and the folded values, as a hand-written oracle does.
//
// A construct outside the subset is refused with a UsageError naming it and
// its line: while loops, discard, switch, non-constant ints, out parameters
// and early returns at once; values that cannot be derived (a texture lookup
// in a gated program, a built-in such as gl_FragCoord) only when a requested
// output depends on them.
#include <string>
#include <vector>

#include "derived/ir.h"

namespace snell::derived {

enum class Stage { Vertex, Fragment };

struct ShaderSource {
  std::string file;  // for messages
  std::string text;
  Stage stage = Stage::Vertex;
};

// A value the program computes: an `out`/varying variable, gl_Position,
// gl_FragColor or a local of main(), as it stands after the statement on
// `afterLine` of main() (a fragment capture's line), or at the end of main()
// when 0.
struct OutputRequest {
  std::string name;
  int afterLine = 0;
};

struct LowerOptions {
  // The reference image's program, evaluated in double only: texture()
  // lookups (samplerCube, sampler2D) and inverse() are followed. A gated
  // program (false) refuses any requested value that depends on them: a
  // lookup's result is a colour, which the image check gates, and GLSL 4.60
  // section 4.7.1 gives inverse() no precision, so no interval bounds it.
  bool doubleOnly = false;
  // The text as a Vulkan driver's compiler preprocesses it, with VULKAN
  // defined (GL_KHR_vulkan_glsl): a shader that tests it is another text
  // there, and its vk results are held against that one.
  bool vulkanMacros = false;
};

// Whether the text names VULKAN, the macro the two APIs' compilers set
// differently: its derived oracle is then lowered once for each.
bool testsVulkanMacro(const std::string& text);

// The program computing `outputs`; none means every output variable the
// shader writes. Operations no output needs are dropped. In a fragment
// stage, a requested value the oracle cannot follow at its line (it reads
// gl_FragCoord, or a function with an early return) becomes an input of
// that name instead, fed with the value read back there: it is left out of
// the outputs and joins the inputs.
Program lowerOutputs(const ShaderSource& source, const std::vector<OutputRequest>& outputs,
                     LowerOptions options = {});
// The same, every name at the end of main().
Program lowerShader(const ShaderSource& source, const std::vector<std::string>& outputs = {},
                    LowerOptions options = {});

}  // namespace snell::derived

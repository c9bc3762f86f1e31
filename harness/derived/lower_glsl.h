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
// its line: loops, if/else, ?:, discard, int values, out parameters and
// early returns at once; values that cannot be derived (a texture lookup,
// a legacy built-in such as gl_ModelViewMatrix) only when a requested
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

// The program computing `outputs` (names of `out`/varying variables,
// gl_Position, or locals of main(), at the end of main()); empty means every
// output variable the shader writes. Operations no output needs are dropped.
Program lowerShader(const ShaderSource& source, const std::vector<std::string>& outputs = {});

}  // namespace snell::derived

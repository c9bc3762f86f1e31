#pragma once
// glslang folds every operation whose operands are all literals, in double,
// before the AST is built: `1e-8 + 1.0 - 1.0`, `1.0 / 3.0` and `exp(1.0)`
// reach the lowering as one number. GLSL 4.60 section 4.3.3 lets a driver
// fold a constant expression that way or evaluate it in fp32 at run time,
// where `1e-8 + 1.0 - 1.0` is 0 and `1.0 / 3.0` has its 2.5 ULP; a folded
// number alone would reject those. So the text glslang parses has each float
// literal renamed to a uniform declared for it, which glslang cannot fold,
// and the lowering reads each such uniform back as its literal: Interval's
// literal tracking (oracle/interval.h) then gives both the folded and the
// run-time values, as for a hand-written oracle.
//
// Lines stay where they are (the declarations go on the line of the first
// token outside any #if block, before it), so messages keep the listing's
// line numbers. Where the renamed text does not compile (a literal used
// before that token), the lowering parses the text as written instead.
#include <map>
#include <string>

namespace snell::derived {

struct NamedLiterals {
  std::string text;
  // Each uniform's name and the literal's value (the decimal as a double).
  std::map<std::string, double> values;
};

// The text with its float literals renamed. Literals in preprocessor lines
// other than #define bodies, `lf` (double) literals, and, for GLSL ES
// (which allows only constant initializers for globals), literals outside
// function bodies and #define bodies are left as they are.
NamedLiterals withLiteralsNamed(const std::string& text);

}  // namespace snell::derived

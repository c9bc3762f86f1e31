#pragma once
// How `snell sweep` sets a listing's eta: the listing's own eta constants
// (`const float Eta = 0.66;` in the shader and `constants` in the manifest,
// which the oracle reads) or literal eta uniforms (the Cg tutorial's
// etaRatio). A listing with several (EtaR, EtaG, EtaB) keeps their ratios:
// all are scaled so that the main one takes the swept value. No graphics
// API here.
#include <optional>
#include <string>
#include <vector>

#include "core/manifest.h"

namespace snell::sweep {

struct EtaBinding {
  std::vector<std::string> constants;  // manifest constants named eta* (any case)
  std::vector<std::string> uniforms;   // literal float uniforms named eta*
  std::string main;                    // the one the swept value is given to
  double published = 0;                // its value as published
  bool empty() const { return constants.empty() && uniforms.empty(); }
};

// The listing's eta names; `main` is Eta (or etaRatio) when present, else
// EtaG (the middle of a dispersion triple), else the first.
EtaBinding etaBinding(const Manifest& manifest);

// The manifest and program with every eta scaled so the main one is `eta`;
// std::nullopt with `why` set when a constant is not written as
// `const float NAME = number;` in the program (the oracle and the shader
// would disagree).
struct EtaVariant {
  Manifest manifest;
  ProgramSource program;
};
std::optional<EtaVariant> withEta(const Manifest& manifest, const ProgramSource& program,
                                  const EtaBinding& binding, double eta, std::string& why);

// A GLSL float literal that rounds to the same float as `value` does.
std::string glslFloat(double value);

}  // namespace snell::sweep

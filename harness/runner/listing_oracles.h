#pragma once
// The oracles a listing's manifest names (core/manifest.h `oracle`), made
// for the checks: the hand-written one by its registered name (oracle/),
// the one derived from the listing's own text (derived/), or both. Every
// check asks here, so a manifest that names no oracle needs no C++.
#include <memory>
#include <string>
#include <vector>

#include "core/manifest.h"
#include "oracle/reference/fragment_oracle.h"
#include "oracle/vertex_oracle.h"

namespace snell {

inline constexpr const char* kDerivedOracleLabel = "derived";

struct NamedOracle {
  std::string label;  // the hand-written oracle's name, or "derived"
  std::unique_ptr<VertexOracle> oracle;
  // What its answers depend on besides their input: the build of its code
  // and its name, or the listing's text and requests for the derived one.
  // The key of its stored results (runner/oracle_store); empty where the
  // code's build cannot be told apart, and nothing is stored.
  std::string identity;
};

enum class CaptureStage { Vertex, Fragment };

// The oracles gating a stage's captured vectors, the hand-written one
// first. For the vertex stage they compute `capture.vertex`; for the
// fragment stage they read some of `capture.fragment` and compute the rest,
// each at its line. Throws UsageError naming the manifest's `oracle` line
// for an unknown name, or the shader's file and line for a construct the
// derived oracle cannot follow.
std::vector<NamedOracle> vectorOracles(const Manifest& m, CaptureStage stage);

// The parts that draw the CPU reference image: the hand-written oracle's
// when it has a fragment part, otherwise the derived ones.
struct DrawingOracles {
  std::string label;
  std::unique_ptr<VertexOracle> vertex;
  std::unique_ptr<FragmentOracle> fragment;
  std::string identity;  // as NamedOracle::identity, for both parts
};
DrawingOracles drawingOracles(const Manifest& m);

// "orange_book_fresnel", "derived" or "orange_book_fresnel + derived".
std::string oracleLabel(const Manifest& m);

}  // namespace snell

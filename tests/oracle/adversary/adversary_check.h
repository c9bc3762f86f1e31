#pragma once
// Holds the adversarial machine's results against the oracle: for a
// built-in formula, a catalog listing or a derived program (the oracle of
// a shader's own text), the oracle's intervals are
// computed once per input, the machine is run several times with fresh
// choices, and every vector it returns must fit one of the oracle's
// alternatives whole (or lie in an undefined component).
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/values.h"
#include "derived/lower_glsl.h"
#include "oracle/interval.h"
#include "oracle/precision_rules.h"

namespace snell::adversary {

struct Tally {
  std::uint64_t evaluations = 0;  // machine evaluations held against the oracle
  std::uint64_t escapes = 0;      // results outside every alternative
  // Of the derived programs' outputs: the components held against the
  // oracle, and those it bounds (not undefined), so that a check passing
  // on undefined components only shows.
  std::uint64_t components = 0;
  std::uint64_t boundedComponents = 0;
  std::vector<std::string> firstEscapes;  // at most kEscapesKept, with a reproduction each
  static constexpr std::size_t kEscapesKept = 8;
  void add(const Tally& other);
};

// The built-in formulas the catalog uses, over float inputs.
enum class Formula {
  Reflect,       // I[3], N[3]
  Refract,       // I[3], N[3], eta
  Normalize,     // x[3]
  Length,        // x[3]
  Dot,           // x[4], y[4]
  Pow,           // x, y
  Exp2,          // x
  Log2,          // x
  Sqrt,          // x
  InverseSqrt,   // x
  Mix,           // x[3], y[3], a
  Clamp,         // x, lo, hi (max then min)
  Divide,        // a, b
  MatrixVector,  // m[16], v[4]
  FresnelRatio,  // the Orange Book's Ratio: F + (1 - F) * pow(1 - dot(-i, n), power); i[3], n[3],
                 // power
};

inline constexpr Formula kAllFormulas[] = {
    Formula::Reflect, Formula::Refract,      Formula::Normalize,   Formula::Length,
    Formula::Dot,     Formula::Pow,          Formula::Exp2,        Formula::Log2,
    Formula::Sqrt,    Formula::InverseSqrt,  Formula::Mix,         Formula::Clamp,
    Formula::Divide,  Formula::MatrixVector, Formula::FresnelRatio};

const char* formulaName(Formula f);
int formulaInputs(Formula f);

// Whether a machine's vector fits one of the oracle's ways whole (NaN fits
// only an undefined component).
bool fitsOneWay(const std::vector<std::vector<Interval>>& ways, std::span<const float> values);

// Runs the machine `runs` times on `inputs` (seeds from `seed`) and counts.
void checkFormula(Formula f, std::span<const float> inputs, PrecisionRules rules, int runs,
                  std::uint64_t seed, Tally& tally);

// A catalog listing with the inputs of one of its scenes.
struct ListingInputs {
  std::string oracle;  // registry name
  UniformMap uniforms;
  ConstantMap constants;
  AttributeMap attributes;
  std::size_t vertexCount = 0;
};

// The vertex oracles the machine can run (every registered one).
std::vector<std::string> machineListings();

// Checks the given vertices of a listing (`attributes` already holds only
// them), `runs` machine evaluations each.
void checkListing(const ListingInputs& inputs, PrecisionRules rules, int runs, std::uint64_t seed,
                  Tally& tally);

// A catalog listing's stage as the derived oracle reads it (its own GLSL
// text and the captures it computes), with the inputs of one of its scenes
// bound by GLSL name.
struct DerivedListingInputs {
  derived::ShaderSource source;
  std::vector<derived::OutputRequest> outputs;
  ListingInputs bindings;   // `oracle` holds the manifest's id
  std::string handWritten;  // the manifest's hand-written oracle, if it has one
};

// The derived program run on the machine, `runs` evaluations for each
// vertex of `in.bindings`, each held against the derived oracle's
// intervals for each of `in.outputs`. Throws UsageError
// where the text is outside the derived oracle's subset.
void checkDerivedListing(const DerivedListingInputs& in, PrecisionRules rules, int runs,
                         std::uint64_t seed, Tally& tally);
// One machine evaluation of the derived program at one vertex of
// `in.bindings`: each output's components, output after output.
std::vector<float> derivedOnMachine(const DerivedListingInputs& in, std::size_t vertex,
                                    PrecisionRules rules, std::uint64_t seed);

// The manifest's hand-written listing run on the machine, each output the
// derived oracle computes under the same name held against it: the derived
// oracle read from the text must allow what an implementation of the
// listing as published may return (its lowering included, which the check
// above cannot see, the machine and the oracle reading one program there).
// Nothing where the manifest has no hand-written oracle.
void checkHandWrittenAgainstDerived(const DerivedListingInputs& in, PrecisionRules rules, int runs,
                                    std::uint64_t seed, Tally& tally);

// The same with the machine running another text than the oracle reads:
// for the check's own test, an edited listing must escape.
void checkDerivedListing(const DerivedListingInputs& in, const derived::ShaderSource& machineSource,
                         PrecisionRules rules, int runs, std::uint64_t seed, Tally& tally);

}  // namespace snell::adversary

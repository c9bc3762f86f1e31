#pragma once
// Runs a derived Program (ir.h) over a batch of samples: each operation is
// evaluated over all samples at once (a register holds one value per
// sample, or one value for all when it depends on uniforms and literals
// only), so the interpreter's dispatch is paid once per operation, not once
// per sample. The arithmetic is the hand-written oracles' own:
// oracle/glsl for double and float, interval.h and interval_builtins.h for
// Interval, under the precision rules active on the thread.
//
// A condition the intervals cannot decide (inside refract(), an if/else,
// a comparison turned into a number) takes the hull of both ways over the
// batch; evaluateVaryings then runs each such sample again once per way
// (sample_ways.h), so that the ways are kept apart as alternatives, as the
// hand-written oracles keep them.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/expected_values.h"
#include "core/values.h"
#include "derived/ir.h"
#include "oracle/precision_rules.h"
#include "oracle/reference/fragment_oracle.h"

namespace snell::derived {

// Throws UsageError naming a uniform or input the program reads that is
// missing, has the wrong number of components or too few samples.
void checkBindings(const Program& program, const UniformMap& uniforms, const AttributeMap& inputs,
                   std::size_t sampleCount);

// Each output's components for every sample, sample-major
// (sampleCount * components values), in the number type T (double, float
// or Interval). Expects checked bindings.
// `undecided`, when given, gets a flag per sample: 1 where a branch (an
// if/else, ?:, float(bool) or refract()'s k < 0) may go either way
// (Interval only).
template <class T>
std::vector<std::vector<T>> evaluateProgram(const Program& program, const UniformMap& uniforms,
                                            const AttributeMap& inputs, std::size_t sampleCount,
                                            std::vector<std::uint8_t>* undecided = nullptr);

// The bound uniforms, with GL's derived state (gl_NormalMatrix, ...) that a
// legacy program reads, computed from the bound matrices as GL does.
UniformMap withLegacyState(const Program& program, const UniformMap& bound);

// What a reference evaluation's lookups ran into, a flag per sample: a
// direction or coordinate the spec leaves undefined, a cube lookup on a face
// edge (oracle/glsl/texture.h).
struct LookupFindings {
  std::vector<std::uint8_t> undefined;
  std::vector<std::uint8_t> faceEdge;
};

// The reference image's evaluation of a LowerOptions::doubleOnly program:
// double only, the lookups sampling `textures` (may be null when the
// program has none). Expects checked bindings.
std::vector<std::vector<double>> evaluateReference(
    const Program& program, const UniformMap& uniforms, const AttributeMap& inputs,
    std::size_t sampleCount, const FragmentBindings* textures, LookupFindings* findings);

// The three number types together, as a listing oracle reports them, under
// `rules`. Checks the bindings first. A program that reads legacy
// fixed-function state gets GL's derived state (gl_NormalMatrix,
// gl_ModelViewProjectionMatrix) from core/legacy_builtins.h.
std::vector<OracleVarying> evaluateVaryings(const Program& program, const UniformMap& uniforms,
                                            const AttributeMap& inputs, std::size_t sampleCount,
                                            PrecisionRules rules);

}  // namespace snell::derived

#pragma once
// What a person needs to find the cause of a vector failure: the worst
// samples (by slack, each once) with the inputs that led to them, the
// listing line that assigns the output, and first of all a constant the
// manifest gives differently from the listing's own `const` line.
#include <string>
#include <vector>

#include "compare/vector_check.h"
#include "core/case.h"
#include "core/program_source.h"
#include "runner/case_result.h"

namespace snell {

// "VERT:LINE: `const float Eta = 0.7;` but the manifest's constants give Eta
// = 0.66 (...)", one line per disagreement; empty when they agree.
std::string constantsDisagreement(const Manifest& m, const ProgramSource& program);

// The last line of `source` that assigns `name` (`name =`, `name.xy =`,
// `name +=`), 0 when none does.
int lineAssigning(const std::string& source, const std::string& name);

// "a = (x, y, z), b = 1.5": the per-sample inputs at `sample`, then the
// uniforms that are numbers or vectors.
std::string sampleInputs(const AttributeMap& inputs, const UniformMap& uniforms,
                         std::size_t sample);

// Why a case whose checks examined nothing (or whose captures the spec leaves
// undefined beyond the manifest's max_undefined) fails; empty when it did
// examine enough. An expected compile error or NotSupported runs no check
// and is not judged here.
std::string nothingCheckedReasons(const Manifest& m, const CaseResult& result);

// The failure text of a vertex capture.
std::string describeVertexFailures(const Manifest& m, const ProgramSource& program,
                                   const ResolvedBindings& bindings,
                                   const std::vector<VaryingCheck>& checks);

}  // namespace snell

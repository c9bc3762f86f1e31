#pragma once
// Checks a manifest against the listing it describes, as text, so that a
// misspelt uniform or a mat3 bound to a mat4 is a clear error naming the
// manifest line before any driver runs, not a silent "uniform ignored".
#include "core/case.h"
#include "core/program_source.h"

namespace snell {

// Throws UsageError "MANIFEST:LINE: ..." for a bound uniform or input the
// program does not declare, a type that does not match, or a captured
// output the vertex stage does not declare. Bindings to fixed-function
// built-ins (gl_ModelViewMatrix, "gl_TextureMatrix[1]", gl_Vertex) are
// held against core/legacy_builtins.h instead: a name snell does not set,
// derived state, a core profile or a wrong type is an error too.
void checkManifestAgainstProgram(const Manifest& manifest, const ProgramSource& program,
                                 const ResolvedBindings& bindings);

}  // namespace snell

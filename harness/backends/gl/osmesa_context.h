#pragma once
#include <memory>

#include "backends/gl/gl_context_provider.h"

namespace snell {

// An OSMesa context (libOSMesa loaded at run time). Core: the requested
// version, then 3.3 (softpipe stops there); compatibility: the highest the
// driver offers. Throws SetupError saying what to install or check.
std::unique_ptr<GlContext> createOsmesaContext(const GlContextRequest& request);

}  // namespace snell

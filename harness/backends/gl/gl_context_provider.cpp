#include "backends/gl/gl_context_provider.h"

#include "backends/gl/egl_context.h"
#include "backends/gl/osmesa_context.h"

namespace snell {

GlContext::~GlContext() {
  if (lastMadeCurrent == this) lastMadeCurrent = nullptr;
}

std::unique_ptr<GlContext> createGlContext(GlProviderKind kind, const GlContextRequest& request) {
  switch (kind) {
    case GlProviderKind::Osmesa:
      return createOsmesaContext(request);
    case GlProviderKind::EglSurfaceless:
      return createEglContext(false, request);
    case GlProviderKind::EglDevice:
      return createEglContext(true, request);
  }
  return createOsmesaContext(request);
}

const char* glProviderName(GlProviderKind kind) {
  switch (kind) {
    case GlProviderKind::Osmesa:
      return "osmesa";
    case GlProviderKind::EglSurfaceless:
      return "egl";
    case GlProviderKind::EglDevice:
      return "egl-device";
  }
  return "osmesa";
}

}  // namespace snell

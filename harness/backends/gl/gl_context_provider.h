#pragma once
// Where an OpenGL context comes from: OSMesa (off-screen Mesa) or EGL
// (surfaceless, or a device for machines with GPUs). Either way the
// context has no default framebuffer that snell uses: every draw and every
// capture goes to a framebuffer object, so the code above is the same.
#include <memory>
#include <string>

#include "core/program_source.h"

namespace snell {

class GlContext {
 public:
  virtual ~GlContext();
  // Cheap when already current; sets the GL function table the calls use.
  virtual void makeCurrent() = 0;
  virtual std::string what() const = 0;  // "OpenGL 4.5 core through EGL", for messages

 protected:
  // OSMesa and EGL share one GL dispatch (libglapi) but each keeps its own
  // notion of the current context, so "my provider says I am current" is
  // not enough once both are in one process: makeCurrent trusts it only
  // when this context was also the last one made current.
  bool wasMadeCurrentLast() const { return lastMadeCurrent == this; }
  void madeCurrent() { lastMadeCurrent = this; }

 private:
  static inline const GlContext* lastMadeCurrent = nullptr;
};

enum class GlProviderKind { Osmesa, EglSurfaceless, EglDevice };

struct GlContextRequest {
  Profile profile = Profile::Core;
  int coreMajor = 4, coreMinor = 5;  // the highest core version to ask for; 3.3 is the fallback
  std::string device;                // EglDevice: the device index ("" picks the first GPU)
};

// Loads the provider's library (dlopen) on first use. Throws SetupError
// naming what to install or check.
std::unique_ptr<GlContext> createGlContext(GlProviderKind kind, const GlContextRequest& request);

// "osmesa", "egl", "egl-device": for `--gl-provider` and messages.
const char* glProviderName(GlProviderKind kind);

}  // namespace snell

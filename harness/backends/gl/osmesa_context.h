#pragma once
#include <string>
#include <vector>

#include "backends/backend.h"
#include "backends/gl/gl_api.h"

namespace snell {

// One OSMesa context plus the small colour buffer it is made current on.
// Pixels are read from framebuffer objects, never from this buffer; it
// exists only because OSMesaMakeCurrent needs one.
class OsmesaContext {
 public:
  // Core: 4.5 on llvmpipe, 3.3 under GALLIUM_DRIVER=softpipe or when 4.5 is
  // refused. Compatibility: the highest version the driver offers.
  // Throws SetupError saying what to install or check.
  static OsmesaContext create(Profile profile);

  OsmesaContext(OsmesaContext&& other) noexcept;
  OsmesaContext& operator=(OsmesaContext&&) = delete;
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;
  ~OsmesaContext();

  // Cheap when already current; every GL call on this context's objects
  // must follow one, since several backends may share the thread.
  void makeCurrent();

 private:
  OsmesaContext(OSMesaContext handle, std::string what);

  OSMesaContext handle_ = nullptr;
  std::string what_;  // "OpenGL 4.5 core", for messages
  std::vector<unsigned char> colour_;
};

}  // namespace snell

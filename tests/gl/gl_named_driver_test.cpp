// A GL backend runs the driver its name says, or is refused: the renderer
// strings below are the ones the drivers gave.
#include "backends/gl/gl_named_driver.h"

#include <gtest/gtest.h>

#include <string>

#include "backends/gl/gl_driver_info.h"

namespace snell {
namespace {

const DriverInfo kLlvmpipe =
    parseGlDriverInfo("4.5 (Core Profile) Mesa 22.3.6", "llvmpipe (LLVM 15.0.6, 256 bits)");
const DriverInfo kSoftpipe = parseGlDriverInfo("3.3 (Core Profile) Mesa 22.3.6", "softpipe");
const DriverInfo kZink =
    parseGlDriverInfo("4.6 (Core Profile) Mesa 22.3.6", "zink (llvmpipe (LLVM 15.0.6, 256 bits))");
// gl:zink on an H200 whose libEGL loads NVIDIA's driver alone.
const DriverInfo kNvidia = parseGlDriverInfo("4.6.0 NVIDIA 580.159.04", "NVIDIA H200/PCIe/SSE2");

TEST(GlNamedDriver, TheNamedDriverRuns) {
  EXPECT_EQ(whyNotTheNamedDriver("gl", "llvmpipe", kLlvmpipe, {}), "");
  // gl:softpipe and gl:zink set GALLIUM_DRIVER themselves: no user value.
  EXPECT_EQ(whyNotTheNamedDriver("gl:softpipe", "softpipe", kSoftpipe, {}), "");
  EXPECT_EQ(whyNotTheNamedDriver("gl:zink", "zink", kZink, {}), "");
  EXPECT_EQ(whyNotTheNamedDriver("gl:gpu", "", kNvidia, {}), "");
}

TEST(GlNamedDriver, AnotherMesaDriverNamesTheVariableThatChoseIt) {
  const std::string why =
      whyNotTheNamedDriver("gl", "llvmpipe", kSoftpipe, {"softpipe", "", "", ""});
  EXPECT_NE(why.find("gl is llvmpipe, but its context came up on softpipe"), std::string::npos)
      << why;
  EXPECT_NE(why.find("GALLIUM_DRIVER=softpipe chose it; unset it"), std::string::npos) << why;
  EXPECT_NE(whyNotTheNamedDriver("gl:zink", "zink", kLlvmpipe, {}).find("`snell devices`"),
            std::string::npos);
}

// llvmpipe at a width the user chose is not the backend's driver either.
TEST(GlNamedDriver, AVectorWidthTheUserSetIsSentToItsOwnBackend) {
  const DriverInfo narrow =
      parseGlDriverInfo("4.5 (Core Profile) Mesa 22.3.6", "llvmpipe (LLVM 15.0.6, 128 bits)");
  const std::string why = whyNotTheNamedDriver("gl", "llvmpipe", narrow, {"", "128", "", ""});
  EXPECT_NE(why.find("LP_NATIVE_VECTOR_WIDTH=128 is set in the environment"), std::string::npos)
      << why;
  EXPECT_NE(why.find("gl:llvmpipe-128"), std::string::npos) << why;
  EXPECT_EQ(whyNotTheNamedDriver("gl:llvmpipe-128", "llvmpipe", narrow, {}), "");
  EXPECT_EQ(whyNotTheNamedDriver("gl:softpipe", "softpipe", kSoftpipe, {"", "128", "", ""}), "");
  // zink runs on lavapipe, which has no backend of its own for that width.
  const DriverInfo narrowZink = parseGlDriverInfo("4.6 (Core Profile) Mesa 22.3.6",
                                                  "zink (llvmpipe (LLVM 15.0.6, 128 bits))");
  const std::string zink = whyNotTheNamedDriver("gl:zink", "zink", narrowZink, {"", "128", "", ""});
  EXPECT_NE(zink.find("gl:zink is zink on lavapipe at its native vector width"), std::string::npos)
      << zink;
  EXPECT_EQ(zink.find("gl:llvmpipe-128"), std::string::npos) << zink;
}

// In one process with several backends (`snell bench`), a variable another
// backend set for its own driver may reach a later one: the refusal names
// that backend instead of telling the user to unset it.
TEST(GlNamedDriver, AVariableAnotherBackendSetNamesThatBackend) {
  const DriverInfo narrow =
      parseGlDriverInfo("4.5 (Core Profile) Mesa 22.3.6", "llvmpipe (LLVM 15.0.6, 128 bits)");
  const std::string width =
      whyNotTheNamedDriver("gl", "llvmpipe", narrow, {"", "128", "", "gl:llvmpipe-128"});
  EXPECT_NE(width.find("which gl:llvmpipe-128 set for its own driver earlier in this process"),
            std::string::npos)
      << width;
  EXPECT_EQ(width.find("unset it"), std::string::npos) << width;
  const std::string gallium =
      whyNotTheNamedDriver("gl", "llvmpipe", kSoftpipe, {"softpipe", "", "gl:softpipe", ""});
  EXPECT_NE(gallium.find("GALLIUM_DRIVER=softpipe, which gl:softpipe set for its own driver "
                         "earlier in this process, chose it; run gl in a command of its own"),
            std::string::npos)
      << gallium;
}

TEST(GlNamedDriver, AnotherVendorsDriverIsSentToGlGpu) {
  const std::string why = whyNotTheNamedDriver("gl:zink", "zink", kNvidia, {});
  EXPECT_NE(why.find("gl:zink is zink, but its context came up on NVIDIA H200/PCIe/SSE2 "
                     "(OpenGL 4.6.0 NVIDIA 580.159.04)"),
            std::string::npos)
      << why;
  EXPECT_NE(why.find("run a GPU's own driver as gl:gpu"), std::string::npos) << why;
}

}  // namespace
}  // namespace snell

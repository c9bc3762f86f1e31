// The backend registry: every driver profile is registered once, with its
// environment, capabilities and golden key; names it does not know are a
// usage error naming the ones it does.
#include "backends/backend_registry.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <set>

#include "core/errors.h"

namespace snell {
namespace {

TEST(BackendRegistry, HasTheDriverMatrixUnderUniqueNames) {
  const std::vector<std::string> names = backendRegistry().names();
  const std::set<std::string> unique(names.begin(), names.end());
  EXPECT_EQ(unique.size(), names.size());
  for (const char* name : {"gl", "gl:egl", "gl:llvmpipe-128", "gl:softpipe", "gl:zink", "vk"})
    EXPECT_TRUE(unique.count(name)) << name;
}

TEST(BackendRegistry, EveryEntryIsComplete) {
  for (const BackendEntry& e : backendRegistry().entries()) {
    EXPECT_FALSE(e.description.empty()) << e.name;
    EXPECT_TRUE(e.family == "gl" || e.family == "vk") << e.name;
    EXPECT_FALSE(e.goldenKey.empty()) << e.name;
    EXPECT_EQ(e.goldenKey.find_first_of(":/"), std::string::npos) << e.name;  // a file name
    EXPECT_FALSE(e.capabilities.api.empty()) << e.name;
    EXPECT_TRUE(static_cast<bool>(e.make)) << e.name;
  }
}

TEST(BackendRegistry, OneDriverOneGoldenKey) {
  // OSMesa and EGL on llvmpipe are the same driver: one set of goldens.
  EXPECT_EQ(backendRegistry().find("gl").goldenKey, backendRegistry().find("gl:egl").goldenKey);
  EXPECT_NE(backendRegistry().find("gl").goldenKey,
            backendRegistry().find("gl:softpipe").goldenKey);
  EXPECT_NE(backendRegistry().find("gl").goldenKey, backendRegistry().find("gl:zink").goldenKey);
}

TEST(BackendRegistry, DriverEnvironmentIsData) {
  const auto has = [](const std::string& backend, const std::string& name,
                      const std::string& value) {
    for (const auto& [n, v] : backendRegistry().find(backend).environment)
      if (n == name && v == value) return true;
    return false;
  };
  EXPECT_TRUE(has("gl:softpipe", "GALLIUM_DRIVER", "softpipe"));
  EXPECT_TRUE(has("gl:zink", "GALLIUM_DRIVER", "zink"));
  EXPECT_TRUE(has("gl:zink", "LIBGL_ALWAYS_SOFTWARE", "1"));
  EXPECT_TRUE(has("gl:llvmpipe-128", "LP_NATIVE_VECTOR_WIDTH", "128"));
  EXPECT_TRUE(backendRegistry().find("gl").environment.empty());
}

TEST(BackendRegistry, ApplyingAnEntrySetsItsEnvironment) {
  unsetenv("LP_NATIVE_VECTOR_WIDTH");
  applyBackendEnvironment(backendRegistry().find("gl:llvmpipe-128"));
  ASSERT_NE(std::getenv("LP_NATIVE_VECTOR_WIDTH"), nullptr);
  EXPECT_STREQ(std::getenv("LP_NATIVE_VECTOR_WIDTH"), "128");
  unsetenv("LP_NATIVE_VECTOR_WIDTH");
}

TEST(BackendRegistry, UnknownNameIsAUsageErrorListingTheNames) {
  try {
    backendRegistry().find("d3d");
    FAIL() << "expected UsageError";
  } catch (const UsageError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("'d3d'"), std::string::npos) << message;
    EXPECT_NE(message.find("gl:softpipe"), std::string::npos) << message;
  }
}

TEST(BackendCapabilities, ReadsTheVersionLine) {
  EXPECT_EQ(glslVersionOf("#version 140\nvoid main() {}\n"), 140);
  EXPECT_EQ(glslVersionOf("// a comment\n  #version 450 core\n"), 450);
  EXPECT_EQ(glslVersionOf("void main() { gl_Position = ftransform(); }\n"), 110);
}

TEST(BackendCapabilities, SoftpipeCannotRunWhatNeedsMoreThan33) {
  const BackendCapabilities& softpipe = backendRegistry().find("gl:softpipe").capabilities;
  EXPECT_EQ(whyBackendCannotRun(softpipe, 140, false), "");
  EXPECT_EQ(whyBackendCannotRun(softpipe, 330, false), "");
  const std::string why = whyBackendCannotRun(softpipe, 450, false);
  EXPECT_NE(why.find("GLSL 450"), std::string::npos) << why;
  EXPECT_NE(why.find("3.3"), std::string::npos) << why;
  EXPECT_EQ(whyBackendCannotRun(backendRegistry().find("gl").capabilities, 450, false), "");
}

TEST(BackendCapabilities, NoCompatibilityProfileIsAReason) {
  BackendCapabilities coreOnly = backendRegistry().find("gl").capabilities;
  coreOnly.compatibilityProfile = false;
  EXPECT_NE(whyBackendCannotRun(coreOnly, 110, true), "");
  EXPECT_EQ(whyBackendCannotRun(coreOnly, 140, false), "");
}

}  // namespace
}  // namespace snell

// Bringing up OSMesa fails with a SetupError that says what to fix, never
// with a crash inside Mesa.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "backends/gl/gl_backend.h"
#include "core/errors.h"

namespace snell {
namespace {

// Sets an environment variable for one scope and puts the old value back,
// so the other tests in the same process are unaffected.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old, hadOld_ = true;
    setenv(name, value, 1);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;
  ~ScopedEnv() {
    if (hadOld_) setenv(name_, old_.c_str(), 1);
    else unsetenv(name_);
  }

 private:
  const char* name_;
  std::string old_;
  bool hadOld_ = false;
};

TEST(GlContextSetup, UnknownGalliumDriverIsASetupErrorNamingIt) {
  ScopedEnv driver("GALLIUM_DRIVER", "zink");
  try {
    makeGlBackend({});
    FAIL() << "expected SetupError";
  } catch (const SetupError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("GALLIUM_DRIVER=zink"), std::string::npos) << message;
    EXPECT_NE(message.find("llvmpipe"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace snell

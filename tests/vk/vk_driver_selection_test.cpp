#include "backends/vk/vk_driver_selection.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "backends/driver_variables.h"

namespace snell::vk {
namespace {

// Puts an environment variable back as it was when the test ends.
class SavedVariable {
 public:
  explicit SavedVariable(const char* name) : name_(name) {
    if (const char* value = std::getenv(name)) value_ = value;
  }
  ~SavedVariable() {
    if (value_) {
      ::setenv(name_, value_->c_str(), 1);
    } else {
      ::unsetenv(name_);
    }
  }

 private:
  const char* name_;
  std::optional<std::string> value_;
};

std::optional<std::string> variable(const char* name) {
  const char* value = std::getenv(name);
  return value ? std::optional<std::string>(value) : std::nullopt;
}

class VkDriverSelection : public ::testing::Test {
 protected:
  SavedVariable files_{"VK_DRIVER_FILES"};
  SavedVariable icds_{"VK_ICD_FILENAMES"};
};

TEST_F(VkDriverSelection, DefaultsToLavapipe) {
  ::unsetenv("VK_DRIVER_FILES");
  ::unsetenv("VK_ICD_FILENAMES");
  selectLavapipeUnlessOverridden();
  if (std::filesystem::exists(kLavapipeManifest)) {
    EXPECT_EQ(variable("VK_DRIVER_FILES"), std::string(kLavapipeManifest));
  } else {
    EXPECT_EQ(variable("VK_DRIVER_FILES"), std::nullopt);
  }
  EXPECT_EQ(variable("VK_ICD_FILENAMES"), std::nullopt);
}

TEST_F(VkDriverSelection, AUserChosenDriverFileWins) {
  ::setenv("VK_DRIVER_FILES", "/opt/my_icd.json", 1);
  ::unsetenv("VK_ICD_FILENAMES");
  selectLavapipeUnlessOverridden();
  EXPECT_EQ(variable("VK_DRIVER_FILES"), std::string("/opt/my_icd.json"));
  EXPECT_NE(describeDriverSelection().find("/opt/my_icd.json"), std::string::npos);
}

TEST_F(VkDriverSelection, TheOlderIcdVariableWinsToo) {
  ::unsetenv("VK_DRIVER_FILES");
  ::setenv("VK_ICD_FILENAMES", "/opt/old_icd.json", 1);
  selectLavapipeUnlessOverridden();
  EXPECT_EQ(variable("VK_DRIVER_FILES"), std::nullopt);
  EXPECT_NE(describeDriverSelection().find("VK_ICD_FILENAMES=/opt/old_icd.json"),
            std::string::npos);
}

// lavapipe at a width LP_NATIVE_VECTOR_WIDTH forces is not the driver vk's
// goldens were blessed on: the user is told to unset it, or, where another
// backend in this process set it (`snell bench`), which one and what to do.
TEST(LavapipeWidth, TheRefusalSaysWhoSetTheVariable) {
  const std::string lavapipe = "llvmpipe (LLVM 15.0.6, 128 bits)";
  const std::string user = whyNotAtNativeVectorWidth("vk", "lavapipe", lavapipe, "128", "", "");
  EXPECT_EQ(user,
            "vk is lavapipe at its native vector width, and LP_NATIVE_VECTOR_WIDTH=128 is set in "
            "the environment (llvmpipe (LLVM 15.0.6, 128 bits)): unset it");
  const std::string leaked =
      whyNotAtNativeVectorWidth("vk", "lavapipe", lavapipe, "128", "gl:llvmpipe-128", "");
  EXPECT_NE(leaked.find("which gl:llvmpipe-128 set for its own driver earlier in this process, "
                        "reached it (llvmpipe (LLVM 15.0.6, 128 bits)): run vk in a command of "
                        "its own"),
            std::string::npos)
      << leaked;
}

}  // namespace
}  // namespace snell::vk

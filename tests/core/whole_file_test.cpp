#include "core/whole_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <string>

namespace snell {
namespace {

namespace fs = std::filesystem;

class WholeFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("snell-whole-file-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(WholeFile, ReadsEveryByteOfALargeBinaryFile) {
  std::string bytes(3 << 20, '\0');
  for (std::size_t k = 0; k < bytes.size(); ++k) bytes[k] = static_cast<char>(k * 131 % 251);
  std::ofstream(dir_ / "big", std::ios::binary) << bytes;
  const std::optional<std::string> read = readWholeFile(dir_ / "big");
  ASSERT_TRUE(read);
  EXPECT_EQ(*read, bytes);
}

TEST_F(WholeFile, AnEmptyFileIsEmptyAndAMissingOneIsNothing) {
  std::ofstream(dir_ / "empty").flush();
  EXPECT_EQ(readWholeFile(dir_ / "empty"), std::optional<std::string>(""));
  EXPECT_FALSE(readWholeFile(dir_ / "missing"));
  EXPECT_FALSE(readWholeFile(dir_));  // a folder has no bytes to read
}

}  // namespace
}  // namespace snell

// Every driver of the matrix through the command a user runs: one case on
// each, OpenGL through EGL giving OSMesa's results, a driver with no goldens
// starting from "no golden yet", a driver that cannot come up being one
// message and exit 2, and the version and device listings.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "snell_process.h"

namespace {

namespace fs = std::filesystem;

struct Outcome {
  int code = -1;
  std::string out;                                  // stdout and stderr together
  std::map<std::string, nlohmann::json> byBackend;  // the --json results of one case
};

class DriverMatrix : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / fmt::format("snell-driver-matrix-{}", getpid());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  Outcome snell(const std::string& args, const std::string& env = "") {
    const fs::path json = dir_ / "results.jsonl";
    fs::remove(json);
    const snell::testing::Outcome run = snell::testing::runSnell(args, env);
    Outcome outcome;
    outcome.code = run.code;
    outcome.out = run.out;
    std::ifstream in(json);
    for (std::string line; std::getline(in, line);) {
      const nlohmann::json r = nlohmann::json::parse(line);
      outcome.byBackend[r.at("backend").get<std::string>()] = r;
    }
    return outcome;
  }

  std::string runArgs(const std::string& backends, const std::string& filter,
                      const std::string& golden = SNELL_SOURCE_ROOT "/golden") const {
    return fmt::format("run --backend {} --filter '{}' -j 2 --golden {} --out {} --json {}",
                       backends, filter, golden, (dir_ / "out").string(),
                       (dir_ / "results.jsonl").string());
  }

  fs::path dir_;
};

// A vertex-stage case every driver runs, softpipe (3.3 core) included.
TEST_F(DriverMatrix, OneCaseRunsOnEveryDriver) {
  const std::vector<std::string> drivers = {"gl",          "gl:egl",  "gl:llvmpipe-128",
                                            "gl:softpipe", "gl:zink", "vk"};
  const Outcome o =
      snell(runArgs(fmt::format("{}", fmt::join(drivers, ",")), "orange-book/14.1-fresnel/sweep"));
  EXPECT_EQ(o.code, 0) << o.out;
  for (const std::string& driver : drivers) {
    ASSERT_TRUE(o.byBackend.count(driver)) << driver << "\n" << o.out;
    const nlohmann::json& r = o.byBackend.at(driver);
    EXPECT_EQ(r.at("status"), "Pass") << driver;
    EXPECT_GT(r.at("components_checked").get<double>(), 0) << driver;
  }
  EXPECT_NE(
      o.byBackend.at("gl:softpipe").at("driver").at("renderer").get<std::string>().find("softpipe"),
      std::string::npos);
  EXPECT_NE(o.byBackend.at("gl:zink").at("driver").at("renderer").get<std::string>().find("zink"),
            std::string::npos);
  EXPECT_NE(o.byBackend.at("gl:llvmpipe-128")
                .at("driver")
                .at("renderer")
                .get<std::string>()
                .find("128 bits"),
            std::string::npos);
}

// EGL on llvmpipe is the same driver as OSMesa: it passes against the same
// goldens, with the same image error against the reference.
TEST_F(DriverMatrix, EglProviderMatchesOsmesaOnLlvmpipe) {
  const Outcome o = snell(runArgs("gl,gl:egl", "orange-book/14.1-fresnel/sphere"));
  EXPECT_EQ(o.code, 0) << o.out;
  ASSERT_TRUE(o.byBackend.count("gl") && o.byBackend.count("gl:egl")) << o.out;
  const auto imageError = [&](const std::string& backend, const std::string& against) {
    for (const nlohmann::json& c : o.byBackend.at(backend).at("images"))
      if (c.at("against") == against) return c.at("max_error").get<double>();
    ADD_FAILURE() << backend << " has no comparison against " << against;
    return -1.0;
  };
  EXPECT_EQ(imageError("gl:egl", "reference"), imageError("gl", "reference"));
  EXPECT_EQ(imageError("gl:egl", "golden"), 0.0);
  EXPECT_EQ(o.byBackend.at("gl:egl").at("status"), "Pass");
}

TEST_F(DriverMatrix, GlProviderFlagRunsGlThroughEgl) {
  const Outcome o = snell(runArgs("gl", "orange-book/14.1-fresnel/sweep") + " --gl-provider egl");
  EXPECT_EQ(o.code, 0) << o.out;
  ASSERT_TRUE(o.byBackend.count("gl")) << o.out;
  EXPECT_EQ(o.byBackend.at("gl").at("status"), "Pass");
}

// No goldens under the driver's key: the reference still gates it, and the
// message says there is no golden yet instead of failing against llvmpipe's.
TEST_F(DriverMatrix, NewDriverStartsWithNoGoldenYet) {
  const Outcome o = snell(runArgs("gl:llvmpipe-128", "orange-book/14.1-fresnel/sphere"));
  EXPECT_EQ(o.code, 0) << o.out;
  ASSERT_TRUE(o.byBackend.count("gl:llvmpipe-128")) << o.out;
  const nlohmann::json& r = o.byBackend.at("gl:llvmpipe-128");
  EXPECT_EQ(r.at("status"), "Pass");
  EXPECT_NE(r.at("message").get<std::string>().find("no golden yet"), std::string::npos) << r;
  bool heldAgainstReference = false;
  for (const nlohmann::json& c : r.at("images"))
    heldAgainstReference |= c.at("against") == "reference" && c.at("verdict") == "pass";
  EXPECT_TRUE(heldAgainstReference) << r;
}

// Bless writes the driver's own goldens only, under its key.
TEST_F(DriverMatrix, BlessWritesOnlyThatDriversGoldens) {
  const fs::path golden = dir_ / "golden";
  fs::create_directories(golden);
  const Outcome o =
      snell(fmt::format("bless --backend gl:llvmpipe-128 --filter "
                        "'orange-book/14.1-fresnel/sphere' --golden {} --out {}",
                        golden.string(), (dir_ / "out").string()));
  EXPECT_EQ(o.code, 0) << o.out;
  const fs::path dir = golden / "orange-book/14.1-fresnel/sphere";
  EXPECT_TRUE(fs::exists(dir / "gl-llvmpipe-128.exr")) << o.out;
  EXPECT_FALSE(fs::exists(dir / "gl.exr"));
  // Blessed, the next run compares against it.
  const Outcome again =
      snell(runArgs("gl:llvmpipe-128", "orange-book/14.1-fresnel/sphere", golden.string()));
  EXPECT_EQ(again.code, 0) << again.out;
  EXPECT_EQ(
      again.byBackend.at("gl:llvmpipe-128").at("message").get<std::string>().find("no golden yet"),
      std::string::npos);
}

TEST_F(DriverMatrix, ADriverThatCannotComeUpIsOneMessageAndExit2) {
  const Outcome o =
      snell(runArgs("vk", "orange-book/14.1-fresnel/*"), "VK_DRIVER_FILES=/nonexistent/icd.json");
  EXPECT_EQ(o.code, 2) << o.out;
  EXPECT_NE(o.out.find("backend vk cannot be brought up"), std::string::npos) << o.out;
  EXPECT_EQ(o.out.find("Crash"), std::string::npos) << o.out;
  EXPECT_TRUE(o.byBackend.empty());
}

TEST_F(DriverMatrix, AnOsmesaDriverItCannotLoadIsExit2Too) {
  const Outcome o = snell(runArgs("gl", "orange-book/14.1-fresnel/*"), "GALLIUM_DRIVER=nosuch");
  EXPECT_EQ(o.code, 2) << o.out;
  EXPECT_NE(o.out.find("GALLIUM_DRIVER=nosuch"), std::string::npos) << o.out;
  EXPECT_EQ(o.out.find("Crash"), std::string::npos) << o.out;
}

// A backend's name is its driver, and its goldens and expectations are
// kept under that name: Mesa's variables left in the environment that
// choose another driver refuse it, naming the variable and the backend for
// that driver, where gl ran softpipe (or 128-bit llvmpipe) under llvmpipe's
// goldens.
TEST_F(DriverMatrix, AVariableThatChoosesAnotherDriverRefusesTheBackend) {
  const Outcome softpipe =
      snell(runArgs("gl", "orange-book/14.1-fresnel/*"), "GALLIUM_DRIVER=softpipe");
  EXPECT_EQ(softpipe.code, 2) << softpipe.out;
  EXPECT_NE(softpipe.out.find("gl is llvmpipe, but its context came up on softpipe"),
            std::string::npos)
      << softpipe.out;
  EXPECT_NE(softpipe.out.find("GALLIUM_DRIVER=softpipe chose it; unset it"), std::string::npos)
      << softpipe.out;
  EXPECT_TRUE(softpipe.byBackend.empty());
  const Outcome narrow =
      snell(runArgs("gl", "orange-book/14.1-fresnel/*"), "LP_NATIVE_VECTOR_WIDTH=128");
  EXPECT_EQ(narrow.code, 2) << narrow.out;
  EXPECT_NE(narrow.out.find("LP_NATIVE_VECTOR_WIDTH=128 is set in the environment"),
            std::string::npos)
      << narrow.out;
  EXPECT_NE(narrow.out.find("gl:llvmpipe-128"), std::string::npos) << narrow.out;
  // lavapipe reads the same variable: vk came up 128 bits wide under the
  // 256-bit goldens' key.
  const Outcome narrowVk =
      snell(runArgs("vk", "orange-book/14.1-fresnel/*"), "LP_NATIVE_VECTOR_WIDTH=128");
  EXPECT_EQ(narrowVk.code, 2) << narrowVk.out;
  EXPECT_NE(narrowVk.out.find("vk is lavapipe at its native vector width, and "
                              "LP_NATIVE_VECTOR_WIDTH=128 is set in the environment"),
            std::string::npos)
      << narrowVk.out;
  EXPECT_TRUE(narrowVk.byBackend.empty());
  // The backends named for those drivers run as before.
  EXPECT_EQ(
      snell(runArgs("gl:softpipe", "orange-book/14.1-fresnel/sweep"), "GALLIUM_DRIVER=softpipe")
          .code,
      0);
}

TEST_F(DriverMatrix, UnknownBackendNamesTheKnownOnes) {
  const Outcome o = snell("run --backend gl:nosuch");
  EXPECT_EQ(o.code, 2) << o.out;
  EXPECT_NE(o.out.find("gl:softpipe"), std::string::npos) << o.out;
}

TEST_F(DriverMatrix, VersionAndDrivers) {
  const Outcome plain = snell("--version");
  EXPECT_EQ(plain.code, 0) << plain.out;
  EXPECT_EQ(plain.out.rfind("snell ", 0), 0u) << plain.out;
  const Outcome drivers = snell("--version --drivers");
  EXPECT_EQ(drivers.code, 0) << drivers.out;
  EXPECT_NE(drivers.out.find("softpipe | OpenGL 3.3"), std::string::npos) << drivers.out;
  EXPECT_NE(drivers.out.find("zink ("), std::string::npos) << drivers.out;
}

TEST_F(DriverMatrix, DevicesListsEveryApisDevicesAndBackends) {
  const Outcome o = snell("devices");
  EXPECT_EQ(o.code, 0) << o.out;
  for (const char* what :
       {"Vulkan physical devices", "EGL devices", "llvmpipe", "softpipe", "zink", "gl:zink", "vk "})
    EXPECT_NE(o.out.find(what), std::string::npos) << what << "\n" << o.out;
}

TEST_F(DriverMatrix, VulkanDeviceByIndexNameAndId) {
  for (const char* device : {"0", "llvmpipe", "10005:0000"}) {
    const Outcome o =
        snell(runArgs("vk", "orange-book/14.1-fresnel/sweep") + " --device " + device);
    EXPECT_EQ(o.code, 0) << device << "\n" << o.out;
  }
  const Outcome wrong = snell(runArgs("vk", "orange-book/14.1-fresnel/sweep") + " --device 7");
  EXPECT_EQ(wrong.code, 2) << wrong.out;
  EXPECT_NE(wrong.out.find("no Vulkan device matches --device 7"), std::string::npos) << wrong.out;
}

}  // namespace

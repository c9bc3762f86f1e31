// `snell sweep --quick` on gl and vk as a user runs it: every backend's
// critical angles match asin(1 / eta), the bad inputs (NaN, infinity,
// denormals, huge values, zero vectors) crash nothing, and the JSON, table,
// charts and wall time are there.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <thread>

#include "snell_process.h"

namespace snell::testing {
namespace {

namespace fs = std::filesystem;

TEST(SweepCli, QuickSweepOnGlAndVkFindsTheClosedFormCriticalAngles) {
  const fs::path out = fs::temp_directory_path() / fmt::format("snell-sweep-{}", ::getpid());
  const Outcome o =
      runSnell(fmt::format("sweep --quick --backend gl,vk --listings '' --out {}", out.string()));
  ASSERT_TRUE(o.code == 0 || o.code == 1) << o.out;
  EXPECT_NE(o.out.find("wall time:"), std::string::npos);
  EXPECT_NE(o.out.find("critical angles"), std::string::npos);
  const nlohmann::json result = nlohmann::json::parse(readText(out / "sweep.json"));

  std::set<std::string> backends;
  for (const auto& c : result.at("critical_angles")) {
    const std::string backend = c.at("backend").get<std::string>();
    backends.insert(backend);
    const double eta = c.at("eta").get<double>();
    SCOPED_TRACE(fmt::format("{} eta {}", backend, eta));
    const double closed = std::asin(1.0 / eta) * 180.0 / std::numbers::pi;
    EXPECT_NEAR(c.at("closed_form_deg").get<double>(), closed, 1e-12);
    EXPECT_TRUE(c.at("agrees").get<bool>());
    // fp32 rounding of eta and of I.y moves the switch by up to
    // 2^-24 (tan + 1/tan) of the critical angle (critical_angle.h).
    const double tangent = std::tan(closed * std::numbers::pi / 180.0);
    const double inputRounding = std::ldexp(tangent + 1 / tangent, -24) * 180.0 / std::numbers::pi;
    EXPECT_NEAR(c.at("found_deg").get<double>(), closed,
                0.5 * c.at("resolution_deg").get<double>() + c.at("spec_band_deg").get<double>() +
                    inputRounding);
    if (eta == 1.5) {
      EXPECT_NEAR(c.at("found_deg").get<double>(), 41.81, 0.005);
    }
  }
  EXPECT_EQ(backends, (std::set<std::string>{"oracle", "gl", "vk"}));

  bool nanInputSeen = false;
  for (const auto& b : result.at("breaks")) {
    EXPECT_NE(b.at("kind"), "crash") << b.dump();
    if (b.contains("input") && b.at("input") == "nan-I") {
      nanInputSeen = true;
      EXPECT_EQ(b.at("class"), "undefined") << b.dump();
    }
  }
  EXPECT_TRUE(nanInputSeen);
  for (const char* chart : {"sweep-refract-slack", "sweep-method-error", "sweep-map-refract"}) {
    EXPECT_TRUE(fs::exists(out / (std::string(chart) + ".svg"))) << chart;
    EXPECT_TRUE(fs::exists(out / (std::string(chart) + ".png"))) << chart;
  }
  fs::remove_all(out);
}

// The Cg tutorial's listings drawn at the sweep's points: the published
// glass-to-air eta switches to the zero vector at asin(1 / eta) on both
// drivers, the stretched model shows its normal turned by the model matrix
// (total internal reflection where physics refracts: the method's), and
// no bad input crashes a driver.
TEST(SweepCli, ListingsAreDrawnAtTheSweepPoints) {
  const fs::path out = fs::temp_directory_path() / fmt::format("snell-sweep-l-{}", ::getpid());
  const Outcome o =
      runSnell(fmt::format("sweep --quick --no-builtins --no-charts --backend gl,vk --listings "
                           "'cg-tutorial/*' --out {}",
                           out.string()));
  ASSERT_TRUE(o.code == 0 || o.code == 1) << o.out;
  const nlohmann::json listings =
      nlohmann::json::parse(readText(out / "sweep.json")).at("listings");
  EXPECT_EQ(listings.at("swept").size(), 4u) << listings.at("swept").dump();
  int published = 0;
  for (const auto& c : listings.at("critical_angles")) {
    if (c.at("listing") != "cg-tutorial/c7e3v-refraction-glass-to-air" || c.at("frame") != "unit")
      continue;
    if (std::abs(c.at("eta").get<double>() - 1.4995501) > 1e-6) continue;
    ++published;
    ASSERT_TRUE(c.at("found").get<bool>());
    const double resolution =
        c.at("first_zero_deg").get<double>() - c.at("last_refracted_deg").get<double>();
    EXPECT_LT(resolution, 1e-4);
    EXPECT_NEAR(c.at("found_deg").get<double>(), c.at("closed_form_deg").get<double>(), resolution);
  }
  EXPECT_EQ(published, 2);  // gl and vk
  bool stretchedTir = false;
  for (const auto& b : listings.at("breaks")) {
    EXPECT_NE(b.at("kind"), "crash") << b.dump();
    EXPECT_NE(b.at("class"), "implementation") << b.dump();
    stretchedTir = stretchedTir || (b.at("kind") == "zero_where_physics_refracts" &&
                                    b.at("frame") == "stretched" && b.at("class") == "method");
  }
  EXPECT_TRUE(stretchedTir);
  fs::remove_all(out);
}

// One listing on one driver, charts on: its map over angle x eta is drawn
// beside the others, SVG and PNG, a curve per kind coloured by class.
TEST(SweepCli, EachListingGetsAMapPerBackend) {
  const fs::path out = fs::temp_directory_path() / fmt::format("snell-sweep-m-{}", ::getpid());
  const Outcome o =
      runSnell(fmt::format("sweep --quick --no-builtins --backend gl --listings "
                           "'cg-tutorial/c7e3v-refraction-glass-to-air' --out {}",
                           out.string()));
  ASSERT_TRUE(o.code == 0 || o.code == 1) << o.out;
  const std::string stem = "sweep-map-listing-cg-tutorial-c7e3v-refraction-glass-to-air-gl";
  ASSERT_TRUE(fs::exists(out / (stem + ".png"))) << o.out;
  EXPECT_GT(fs::file_size(out / (stem + ".png")), 1000u);
  const std::string svg = readText(out / (stem + ".svg"));
  EXPECT_NE(svg.find("zero_where_physics_refracts, stretched (method)"), std::string::npos)
      << "the stretched model's total internal reflection, the method's";
  // Each kind its own colour, the first blue; red is the implementation's
  // alone, and this listing's one kind is the method's.
  EXPECT_NE(svg.find("rgb( 31, 119, 180)"), std::string::npos) << "the first kind in blue";
  EXPECT_EQ(svg.find("rgb(214,  39,  40)"), std::string::npos) << "red is for drivers' breaks";
  EXPECT_NE(o.out.find("chart: " + (out / (stem + ".svg")).string()), std::string::npos);
  fs::remove_all(out);
}

TEST(SweepCli, DeviceReachesTheDrivers) {
  const Outcome o =
      runSnell("sweep --quick --no-charts --backend vk --device 99 --out /tmp/snell-sweep-device");
  EXPECT_EQ(o.code, 2) << o.out;
  EXPECT_NE(o.out.find("--device 99"), std::string::npos) << o.out;
}

TEST(SweepCli, ATimeoutOutOfRangeSaysTheRange) {
  for (const char* timeout : {"-1", "0", "1e9"}) {
    const Outcome o = runSnell(
        fmt::format("sweep --quick --no-charts --timeout {} --out /tmp/snell-sweep-t", timeout));
    EXPECT_EQ(o.code, 2) << o.out;
    // CLI11's wording; the range itself must be the readable one.
    EXPECT_NE(o.out.find("--timeout: Value " + std::string(timeout)), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("0.001"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("86400"), std::string::npos) << o.out;
  }
}

// Listings named with --listings of which none can be swept (here one that
// reads back from the fragment stage only): the sweep would check nothing
// the user asked for. It says why with exit 2 before sweeping anything: it
// exited 0, then 2 only after the built-ins' sweep had written its results.
TEST(SweepCli, NamedListingsNoneOfWhichCanBeSweptAreExit2BeforeAnySweep) {
  const std::filesystem::path out = "/tmp/snell-sweep-none";
  std::filesystem::remove_all(out);
  for (const std::string builtins : {"--no-builtins ", ""}) {
    const Outcome o =
        runSnell("sweep --quick " + builtins +
                 "--no-charts --backend gl --listings 'cs381/glass' --out " + out.string());
    EXPECT_EQ(o.code, 2) << o.out;
    EXPECT_NE(o.out.find("no listing that --listings 'cs381/glass' names can be swept: "
                         "cs381/glass: reads back from the fragment stage only"),
              std::string::npos)
        << o.out;
    EXPECT_FALSE(std::filesystem::exists(out)) << builtins << o.out;
  }
  // It names the scenes `snell run` covers such a listing on: a shadertoy
  // listing is drawn full screen only.
  const Outcome lens = runSnell(
      "sweep --quick --no-builtins --no-charts --backend gl --listings "
      "'shadertoy/lens' --out " +
      out.string());
  EXPECT_EQ(lens.code, 2) << lens.out;
  EXPECT_NE(lens.out.find("`snell run` covers it on its scene (fullscreen)"), std::string::npos)
      << lens.out;
  // With --no-builtins and no --listings, every listing of a catalog that
  // has none that can be swept.
  const std::filesystem::path shaders = "/tmp/snell-sweep-none-shaders/cs381";
  std::filesystem::remove_all(shaders.parent_path());
  std::filesystem::create_directories(shaders);
  std::filesystem::copy(std::filesystem::path(SNELL_SOURCE_ROOT) / "shaders/cs381/glass",
                        shaders / "glass", std::filesystem::copy_options::recursive);
  const Outcome all = runSnell("sweep --quick --no-builtins --no-charts --backend gl --shaders " +
                               shaders.parent_path().string() + " --out " + out.string());
  EXPECT_EQ(all.code, 2) << all.out;
  EXPECT_NE(all.out.find("nothing to sweep: --no-builtins leaves the listings, and none of them "
                         "can be: cs381/glass: reads back"),
            std::string::npos)
      << all.out;
  EXPECT_FALSE(std::filesystem::exists(out)) << all.out;
}

// --json on the file the sweep writes its own input to, in --out: one
// overwrote the other, with exit 0.
TEST(SweepCli, JsonOnTheSweepsOwnInputFileIsRefused) {
  const fs::path out = fs::temp_directory_path() / fmt::format("snell-sweep-own-{}", ::getpid());
  fs::create_directories(out);
  const Outcome o =
      runSnell(fmt::format("sweep --quick --backend gl --no-charts --out {0} --json "
                           "{0}/sweep-input.jsonl",
                           out.string()));
  EXPECT_EQ(o.code, 2) << o.out;
  EXPECT_NE(o.out.find("a file of this name is the sweep's own (its input)"), std::string::npos)
      << o.out;
  fs::remove_all(out);
}

// --json in --out on a file the sweep writes or removes there was lost
// with exit 0: named like an earlier sweep's chart it was removed as one,
// like one of this sweep's charts, gnuplot's script or log, or a driver's
// batch of points it was overwritten. Each is refused before the sweep.
TEST(SweepCli, JsonOnAFileTheSweepWritesOrRemovesInOutIsRefused) {
  const fs::path out = fs::temp_directory_path() / fmt::format("snell-sweep-ownj-{}", ::getpid());
  fs::remove_all(out);
  fs::create_directories(out);
  for (const char* name : {"sweep-map-old.svg", "sweep-refract-slack.svg", "sweep-map-refract.png",
                           "charts.gp", "gnuplot.log", "sweep-input-40-300.jsonl"}) {
    const fs::path json = out / name;
    std::ofstream(json) << "mine";
    const Outcome o =
        runSnell(fmt::format("sweep --quick --backend vk --listings '' --out {} --json {}",
                             out.string(), json.string()));
    EXPECT_EQ(o.code, 2) << name << ": " << o.out;
    EXPECT_NE(o.out.find(fmt::format("--json {}: ", json.string())), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("name a file of another name"), std::string::npos) << o.out;
    EXPECT_EQ(readText(json), "mine") << name;
  }
  fs::remove_all(out);
}

TEST(SweepCli, AnUnknownBackendIsAUsageError) {
  const Outcome o = runSnell("sweep --quick --backend nosuch --no-charts --out /tmp/snell-sweep-x");
  EXPECT_EQ(o.code, 2) << o.out;
}

// Without the built-ins their charts were drawn empty, reading as "no
// breaks": they are left out, and the listings' maps drawn.
TEST(SweepCli, WithoutTheBuiltinsTheirChartsAreNotDrawn) {
  const fs::path out = fs::temp_directory_path() / fmt::format("snell-sweep-nb-{}", ::getpid());
  fs::remove_all(out);
  const Outcome o = runSnell(fmt::format(
      "sweep --backend vk --quick --no-builtins --listings 'orange-book/14.1-fresnel' --out {}",
      out.string()));
  ASSERT_EQ(o.code, 0) << o.out;
  for (const char* chart : {"sweep-refract-slack", "sweep-reflect-slack", "sweep-map-refract"})
    EXPECT_FALSE(fs::exists(out / (std::string(chart) + ".png"))) << chart;
  EXPECT_TRUE(fs::exists(out / "sweep-map-listing-orange-book-14.1-fresnel-vk.png"));
  fs::remove_all(out);
}

// A listing with no eta (diffraction) is drawn at eta 0, which the table
// printed as its eta; it says there is none.
TEST(SweepCli, AListingWithNoEtaShowsNoneInTheTable) {
  const fs::path out = fs::temp_directory_path() / fmt::format("snell-sweep-de-{}", ::getpid());
  const Outcome o = runSnell(fmt::format(
      "sweep --backend vk --quick --no-builtins --no-charts --listings 'blog/diffraction' --out {}",
      out.string()));
  ASSERT_TRUE(o.code == 0 || o.code == 1) << o.out;
  std::istringstream lines(o.out);
  int rows = 0;
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("blog/diffraction ", 0) == 0) {
      ++rows;
      EXPECT_EQ(line.back(), '-') << line;
    }
  EXPECT_GT(rows, 0) << o.out;
  fs::remove_all(out);
}

// Every point out of time read as a driver that hangs everywhere: the
// note names the limit.
TEST(SweepCli, EveryPointOutOfTimeNamesTheLimit) {
  const fs::path out = fs::temp_directory_path() / fmt::format("snell-sweep-to-{}", ::getpid());
  const Outcome o = runSnell(
      fmt::format("sweep --backend vk --quick --listings '' --no-charts --timeout 0.001 --out {}",
                  out.string()));
  EXPECT_EQ(o.code, 1) << o.out;
  EXPECT_NE(o.out.find("every point on vk ran out of time: is --timeout 0.001 s too short"),
            std::string::npos)
      << o.out;
  fs::remove_all(out);
}

// The listings' draws were cut at 120 s whatever --timeout said: they
// are cut at --timeout, as the built-ins' points are.
TEST(SweepCli, ListingDrawsAreCutAtTheTimeout) {
  const fs::path out = fs::temp_directory_path() / fmt::format("snell-sweep-lto-{}", ::getpid());
  const Outcome o =
      runSnell(fmt::format("sweep --backend vk --quick --no-builtins --no-charts --listings "
                           "'orange-book/14.1-fresnel' --timeout 0.001 --out {}",
                           out.string()));
  EXPECT_EQ(o.code, 1) << o.out;
  const nlohmann::json listings =
      nlohmann::json::parse(readText(out / "sweep.json")).at("listings");
  int timeouts = 0;
  for (const auto& b : listings.at("breaks")) timeouts += b.at("kind") == "timeout";
  EXPECT_GT(timeouts, 0) << o.out;
  fs::remove_all(out);
}

// A sweep into the folder of an earlier one left that one's charts and
// data of another backend beside its own results, contradicting them: the
// sweep's own charts (sweep-*.svg, .png) it did not draw, and its data
// folder, are replaced; other files are not touched.
TEST(SweepCli, AnEarlierSweepsChartsDoNotStayBesideANewOnesResults) {
  const fs::path out = fs::temp_directory_path() / fmt::format("snell-sweep-re-{}", ::getpid());
  fs::remove_all(out);
  const auto sweep = [&](const char* backends) {
    return runSnell(
        fmt::format("sweep --backend {} --quick --listings 'orange-book/14.1-fresnel' "
                    "--out {}",
                    backends, out.string()));
  };
  const Outcome both = sweep("gl,vk");
  ASSERT_TRUE(both.code == 0 || both.code == 1) << both.out;
  const fs::path glMap = out / "sweep-map-listing-orange-book-14.1-fresnel-gl.png";
  ASSERT_TRUE(fs::exists(glMap));
  std::ofstream(out / "sweep-notes.txt") << "mine";
  std::ofstream(out / "mine.png") << "mine";
  const Outcome vkOnly = sweep("vk");
  ASSERT_TRUE(vkOnly.code == 0 || vkOnly.code == 1) << vkOnly.out;
  EXPECT_FALSE(fs::exists(glMap));
  EXPECT_TRUE(fs::exists(out / "sweep-map-listing-orange-book-14.1-fresnel-vk.png"));
  for (const auto& entry : fs::directory_iterator(out / "sweep-data"))
    EXPECT_EQ(entry.path().filename().string().find("-gl-"), std::string::npos) << entry.path();
  EXPECT_TRUE(fs::exists(out / "sweep-notes.txt"));
  EXPECT_TRUE(fs::exists(out / "mine.png"));
  // A sweep that draws no charts and writes its results elsewhere leaves
  // the earlier ones: they go with the sweep.json in --out, not rewritten.
  const Outcome elsewhere = runSnell(
      fmt::format("sweep --backend vk --quick --no-builtins --listings 'orange-book/14.1-fresnel' "
                  "--no-charts --out {0} --json {0}-elsewhere.json",
                  out.string()));
  ASSERT_TRUE(elsewhere.code == 0 || elsewhere.code == 1) << elsewhere.out;
  EXPECT_TRUE(fs::exists(out / "sweep-map-listing-orange-book-14.1-fresnel-vk.png"));
  fs::remove(out.string() + "-elsewhere.json");
  // Nor is --json taken inside the charts' data folder, which every sweep
  // replaces.
  const Outcome inData = runSnell(fmt::format(
      "sweep --backend vk --quick --no-builtins --no-charts --out {0} --json {0}/sweep-data/x.json",
      out.string()));
  EXPECT_EQ(inData.code, 2) << inData.out;
  EXPECT_NE(inData.out.find("the charts' own folder"), std::string::npos) << inData.out;
  // A sweep that draws no charts leaves none of the earlier ones either.
  const Outcome noCharts = runSnell(
      fmt::format("sweep --backend vk --quick --no-builtins --listings 'orange-book/14.1-fresnel' "
                  "--no-charts --out {}",
                  out.string()));
  ASSERT_TRUE(noCharts.code == 0 || noCharts.code == 1) << noCharts.out;
  EXPECT_TRUE(fs::exists(out / "sweep.json"));
  EXPECT_FALSE(fs::exists(out / "sweep-map-listing-orange-book-14.1-fresnel-vk.png"));
  EXPECT_FALSE(fs::exists(out / "sweep-data"));
  EXPECT_FALSE(fs::exists(out / "charts.gp"));
  EXPECT_FALSE(fs::exists(out / "gnuplot.log"));
  for (const auto& entry : fs::directory_iterator(out))
    EXPECT_FALSE(entry.path().filename().string().starts_with("sweep-") &&
                 (entry.path().extension() == ".svg" || entry.path().extension() == ".png"))
        << entry.path();
  EXPECT_TRUE(fs::exists(out / "sweep-notes.txt"));
  EXPECT_TRUE(fs::exists(out / "mine.png"));
  fs::remove_all(out);
}

// Ctrl-C stopped a sweep with no word and left its input and job files
// in --out, beside an earlier sweep's results; a bench lost the methods it
// had measured without a word. Each now says what became of its work, exit
// 130, and leaves nothing half written: the sweep removes the --out folder
// it made, the bench writes no bench.json for the ladder it was in.
TEST(SweepCli, InterruptedSweepAndBenchSayWhatBecameOfTheirWork) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-sweep-int-{}", ::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto interrupted = [&](const std::vector<std::string>& args, const char* name) {
    const fs::path err = dir / (std::string(name) + ".err");
    const pid_t pid = spawnSnell(args, err.string());
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    ::kill(pid, SIGINT);
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFEXITED(status)) << name << " ended by the signal itself";
    EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT) << name;
    return readText(err);
  };
  const std::string sweep =
      interrupted({"sweep", "--backend", "vk", "--out", (dir / "sweep").string()}, "sweep");
  EXPECT_NE(sweep.find("sweep interrupted by SIGINT: sweep.json and the charts are written when "
                       "the sweep ends, so none was written"),
            std::string::npos)
      << sweep;
  EXPECT_FALSE(fs::exists(dir / "sweep")) << "the --out folder it made is left";

  const std::string bench = interrupted(
      {"bench", "--methods", std::string(SNELL_SOURCE_ROOT) + "/shaders/methods/fresnel",
       "--backends", "gl", "--no-ablation", "--out", (dir / "bench").string()},
      "bench");
  EXPECT_NE(bench.find("bench interrupted by SIGINT after "), std::string::npos) << bench;
  EXPECT_FALSE(fs::exists(dir / "bench" / "bench.json"));
  fs::remove_all(dir);
}

// Ctrl-C on a sweep into the folder of an earlier one removed that one's
// sweep-input.jsonl, which its sweep.json and charts go with: the input is
// put in place only when the sweep ends, and the earlier files stay as
// they were.
TEST(SweepCli, AnInterruptedSweepLeavesTheEarlierOnesInput) {
  const fs::path out = fs::temp_directory_path() / fmt::format("snell-sweep-intin-{}", ::getpid());
  fs::remove_all(out);
  fs::create_directories(out);
  std::ofstream(out / "sweep-input.jsonl") << "earlier input";
  std::ofstream(out / "sweep.json") << "earlier results";
  const fs::path err = out.string() + ".err";
  const pid_t pid = spawnSnell({"sweep", "--backend", "vk", "--out", out.string()}, err.string());
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  ::kill(pid, SIGINT);
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 128 + SIGINT) << readText(err);
  EXPECT_EQ(readText(out / "sweep-input.jsonl"), "earlier input") << readText(err);
  EXPECT_EQ(readText(out / "sweep.json"), "earlier results");
  std::set<std::string> left;
  for (const auto& entry : fs::directory_iterator(out)) left.insert(entry.path().filename());
  EXPECT_EQ(left, (std::set<std::string>{"sweep-input.jsonl", "sweep.json"}));
  fs::remove_all(out);
  fs::remove(err);
}

}  // namespace
}  // namespace snell::testing

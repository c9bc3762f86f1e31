// `snell report --sweep`: each listing of the report gets its breaks from a
// sweep's JSON beside it, counted per backend and class, with its map
// embedded; a listing the sweep did not cover says so; a malformed sweep
// JSON is one clear error, exit 2.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "compare/image_io.h"
#include "core/image.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::pair<int, std::string> shell(const std::string& command) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  std::string out;
  std::array<char, 4096> buffer;
  while (std::size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) out.append(buffer.data(), n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

json record(const std::string& caseId, const std::string& backend) {
  return {{"case", caseId},
          {"backend", backend},
          {"status", "Pass"},
          {"message", ""},
          {"title", "a listing"},
          {"source", {{"file", "000.txt"}, {"where", "Listing 1"}}},
          {"driver",
           {{"api", "OpenGL"},
            {"api_version", "4.5"},
            {"renderer", "llvmpipe"},
            {"driver_version", "Mesa"},
            {"device_type", "cpu"}}},
          {"vertices", 0},
          {"varyings", json::array()},
          {"images", json::array()},
          {"compile_log", ""},
          {"seconds", 0.1},
          {"backend_seconds", 0.1},
          {"oracle_seconds", 0.0}};
}

json listingBreak(const std::string& backend, const std::string& cls, const std::string& kind,
                  double angle, double eta, const std::string& detail, json value) {
  return {{"listing", "orange-book/14.1-fresnel"},
          {"output", "Refract"},
          {"backend", backend},
          {"frame", "unit"},
          {"input", "grid"},
          {"eta", eta},
          {"angle_deg", angle},
          {"kind", kind},
          {"class", cls},
          {"detail", detail},
          {"value", value}};
}

class SweepSection : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / fmt::format("snell-report-sweep-{}", getpid());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "sweep");
    fs::create_directories(dir_ / "images");  // a run that kept no images
    std::ofstream(dir_ / "results.jsonl")
        << record("orange-book/14.1-fresnel/sphere", "gl").dump() << "\n"
        << record("cg-tutorial/c7e3v-refraction-glass-to-air/sphere", "gl").dump() << "\n"
        << record("blog/chromatic/sphere", "gl").dump() << "\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::pair<int, std::string> report() const {
    return shell(fmt::format("{} report {} -o {} --images {} --sweep {}", SNELL_BINARY,
                             (dir_ / "results.jsonl").string(), (dir_ / "html").string(),
                             (dir_ / "images").string(), (dir_ / "sweep").string()));
  }

  fs::path dir_;
};

TEST_F(SweepSection, EachListingShowsItsBreaksPerBackendAndClass) {
  // gl: 3 method breaks and 1 undefined; vk: 2 implementation breaks.
  json breaks = json::array();
  for (double angle : {45.0, 60.0, 75.0})
    breaks.push_back(listingBreak("gl", "method", "zero_where_physics_refracts", angle, 0.66,
                                  fmt::format("{} deg from the physical direction", angle / 10),
                                  {0, 0, 0}));
  breaks.push_back(
      listingBreak("gl", "undefined", "nan", 90, 1.5, "NaN in the output", {"nan", 0, 0}));
  breaks.push_back(listingBreak("vk", "implementation", "outside_interval", 30, 0.9,
                                "2.5 outside the interval", {0.1, 0.2, 0.3}));
  breaks.push_back(listingBreak("vk", "implementation", "outside_interval", 31, 0.9,
                                "7.25 outside the interval", {0.1, 0.2, 0.3}));
  const json sweep = {{"listings",
                       {{"swept", {"orange-book/14.1-fresnel", "blog/chromatic"}},
                        {"not_swept",
                         {{{"listing", "cg-tutorial/c7e3v-refraction-glass-to-air"},
                           {"why", "no refracted output captured"}}}},
                        {"breaks", breaks}}}};
  std::ofstream(dir_ / "sweep" / "sweep.json") << sweep.dump(1);
  // A map for gl (the sweep draws one per listing and backend).
  snell::Image map(8, 8);
  snell::writeImageAtomically(dir_ / "sweep" / "sweep-map-listing-orange-book-14.1-fresnel-gl.png",
                              map);

  const auto [code, out] = report();
  ASSERT_EQ(code, 0) << out;
  const std::string html = readText(dir_ / "html" / "index.html");
  const std::size_t section = html.find("id=\"sweep-orange-book-14-1-fresnel\"");
  ASSERT_NE(section, std::string::npos) << "no sweep section for the listing";
  const std::string fresnel =
      html.substr(section, html.find("<div class=\"case\"", section) - section);
  EXPECT_NE(fresnel.find("6 breakdown points"), std::string::npos) << fresnel;
  EXPECT_NE(fresnel.find("<td>gl</td><td class=\"method\">method</td><td class=\"num\">3</td>"
                         "<td>3 zero_where_physics_refracts</td>"),
            std::string::npos)
      << fresnel;
  EXPECT_NE(fresnel.find("<td>gl</td><td class=\"undefined\">undefined</td><td "
                         "class=\"num\">1</td>"),
            std::string::npos)
      << fresnel;
  EXPECT_NE(fresnel.find("<td>vk</td><td class=\"implementation\">implementation</td><td "
                         "class=\"num\">2</td>"),
            std::string::npos)
      << fresnel;
  // The first points in order, with angle and eta; the worst by its measure.
  EXPECT_NE(fresnel.find("45 deg, eta 0.66: zero_where_physics_refracts"), std::string::npos);
  EXPECT_NE(fresnel.find("<td>75 deg, eta 0.66"), std::string::npos) << "worst of gl method";
  EXPECT_NE(fresnel.find("<td>31 deg, eta 0.9: outside_interval (7.25 outside"), std::string::npos)
      << "worst of vk";
  EXPECT_NE(fresnel.find("value (nan, 0, 0)"), std::string::npos);
  // Its map is embedded; vk's was not drawn and is left out.
  EXPECT_NE(fresnel.find("src=\"data:image/png;base64,iVBORw0K"), std::string::npos);
  EXPECT_EQ(fresnel.find("fresnel on vk"), std::string::npos);
  // Swept with no breaks; not swept, and why.
  EXPECT_NE(html.find("Swept: no breaks found."), std::string::npos);
  EXPECT_NE(html.find("Not swept: no refracted output captured"), std::string::npos);
  EXPECT_NE(html.find("href=\"#sweep-orange-book-14-1-fresnel\""), std::string::npos);
}

TEST_F(SweepSection, AListingTheSweepDidNotCoverSaysSo) {
  std::ofstream(dir_ / "sweep" / "sweep.json")
      << json{{"listings",
               {{"swept", json::array()}, {"not_swept", json::array()}, {"breaks", json::array()}}}}
             .dump();
  const auto [code, out] = report();
  ASSERT_EQ(code, 0) << out;
  const std::string html = readText(dir_ / "html" / "index.html");
  std::size_t said = 0;
  for (std::size_t at = html.find("did not cover this listing"); at != std::string::npos;
       at = html.find("did not cover this listing", at + 1))
    ++said;
  EXPECT_EQ(said, 3u);
}

TEST_F(SweepSection, AMalformedSweepJsonIsOneClearErrorExit2) {
  std::ofstream(dir_ / "sweep" / "sweep.json") << "{\"listings\": {\"swept\": [\n  oops\n}";
  const auto [code, out] = report();
  EXPECT_EQ(code, 2) << out;
  EXPECT_NE(out.find((dir_ / "sweep" / "sweep.json").string()), std::string::npos) << out;
  EXPECT_NE(out.find("line 2"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir_ / "html" / "index.html"));

  // Valid JSON of the wrong shape is the same kind of error.
  std::ofstream(dir_ / "sweep" / "sweep.json") << R"({"listings": {"swept": 3}})";
  const auto [code2, out2] = report();
  EXPECT_EQ(code2, 2) << out2;
  EXPECT_NE(out2.find("not a sweep's JSON"), std::string::npos) << out2;
}

TEST_F(SweepSection, ASweepWithoutListingsIsAnError) {
  std::ofstream(dir_ / "sweep" / "sweep.json") << R"({"points": 10, "breaks": []})";
  const auto [code, out] = report();
  EXPECT_EQ(code, 2) << out;
  EXPECT_NE(out.find("--listings"), std::string::npos) << out;
}

}  // namespace

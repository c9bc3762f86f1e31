// `snell report` on a run with a few-pixel image failure, opened in
// headless chromium with every host unreachable: the page renders (the
// screenshot is not blank), every image is embedded and decodes, and the
// failure is named and circled. The screenshot is kept beside the test.
#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "compare/image_io.h"
#include "core/image.h"

namespace {

namespace fs = std::filesystem;

constexpr const char* kCase = "orange-book/14.1-fresnel/sphere";  // fail threshold 0.004

std::pair<int, std::string> shell(const std::string& command) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  std::string out;
  std::array<char, 4096> buffer;
  while (std::size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) out.append(buffer.data(), n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

// `snell report` on results files in `dir` (by name), its page written to
// DIR/html from the images in DIR/images; `extra` options after them.
std::pair<int, std::string> reportIn(const fs::path& dir,
                                     const std::vector<std::string>& results = {"results.jsonl"},
                                     const std::string& extra = "") {
  std::string files;
  for (const std::string& name : results) files += (dir / name).string() + " ";
  return shell(fmt::format("{} report {}-o {} --images {} {}", SNELL_BINARY, files,
                           (dir / "html").string(), (dir / "images").string(), extra));
}

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

nlohmann::json record(const std::string& backend, const std::string& status,
                      std::size_t failedPixels) {
  const nlohmann::json driver = {{"api", backend == "gl" ? "OpenGL" : "Vulkan"},
                                 {"api_version", "4.5"},
                                 {"renderer", backend == "gl" ? "softpipe" : "llvmpipe"},
                                 {"driver_version", "Mesa 22.3.6"},
                                 {"device_type", "cpu"}};
  const nlohmann::json varying = {{"name", "Refract"},
                                  {"checked", 3000},
                                  {"undefined", 12},
                                  {"failed", 0},
                                  {"worst_slack", 0.73},
                                  {"worst_vertex", 17},
                                  {"slack_histogram", {900, 1200, 500, 300, 80, 20, 0, 0}},
                                  {"first_failures", nlohmann::json::array()}};
  const nlohmann::json image = {{"against", "reference"},
                                {"verdict", failedPixels ? "fail" : "pass"},
                                {"max_error", failedPixels ? 0.02 : 0.0005},
                                {"mean_error", 1e-5},
                                {"rms_error", 1e-4},
                                {"psnr", 80.0},
                                {"max_x", 20},
                                {"max_y", 30},
                                {"compared", 4000},
                                {"failed", failedPixels},
                                {"warned", 0},
                                {"masked", {{"Silhouette", 96}}},
                                {"problem", ""}};
  return {{"case", kCase},
          {"backend", backend},
          {"status", status},
          {"message", failedPixels ? "13 pixels over 0.004 against the reference" : ""},
          {"title", "Fresnel reflection and refraction"},
          {"source", {{"file", "000.txt"}, {"where", "Listing 14.1"}}},
          {"driver", driver},
          {"vertices", 1000},
          {"varyings", {varying}},
          {"images", {image}},
          {"compile_log", ""},
          {"seconds", 0.5},
          {"backend_seconds", 0.3},
          {"oracle_seconds", 0.1}};
}

// A 64x64 scene: a gradient; the "gl" render is off by 0.02 on 13 pixels
// (over the 0.004 threshold), "vk" by 0.0005 everywhere.
void writeImages(const fs::path& dir) {
  fs::create_directories(dir);
  snell::Image reference(64, 64), gl(64, 64), vk(64, 64), mask(64, 64);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      for (int c = 0; c < 4; ++c) {
        const float v = c == 3 ? 1.0f : (x + y * (c + 1)) / 256.0f;
        reference.at(x, y)[c] = v;
        gl.at(x, y)[c] = v;
        vk.at(x, y)[c] = c == 3 ? v : v + 0.0005f;
      }
  for (int k = 0; k < 13; ++k) gl.at(10 + 3 * k, 40)[1] += 0.02f;
  for (int x = 0; x < 64; ++x) mask.at(x, 0)[0] = 1;  // one row masked: grey
  snell::writeImageAtomically(dir / "reference.exr", reference);
  snell::writeImageAtomically(dir / "reference.png", reference);
  snell::writeImageAtomically(dir / "gl.exr", gl);
  snell::writeImageAtomically(dir / "gl.png", gl);
  snell::writeImageAtomically(dir / "vk.exr", vk);
  snell::writeImageAtomically(dir / "vk.png", vk);
  snell::writeImageAtomically(dir / "mask.exr", mask);
}

// An interrupted run was said on stderr only: the page, read later and
// elsewhere, showed its missing cases as if the run had none.
TEST(HtmlReport, AnInterruptedRunIsSaidAtTheTopOfThePage) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-report-int-{}", getpid());
  fs::remove_all(dir);
  fs::create_directories(dir / "images");
  for (const bool interrupted : {true, false}) {
    {
      nlohmann::json r = record("gl", "Pass", 0);
      if (interrupted) r["incomplete"] = true;
      std::ofstream(dir / "results.jsonl") << r.dump() << "\n";
    }
    const auto [code, out] = reportIn(dir);
    ASSERT_EQ(code, 0) << out;
    const std::string html = readText(dir / "html" / "index.html");
    EXPECT_EQ(html.find("is an interrupted run: the cases it did not reach are missing") !=
                  std::string::npos,
              interrupted)
        << html.substr(0, 3000);
  }
  fs::remove_all(dir);
}

// A report of a failing run given the images of an earlier, passing one
// (a stale --images folder) put the passing run's pictures under the
// failing run's numbers, with heat-map captions that contradicted them.
// The images are not shown when their error against the reference is not
// the one the run recorded, and the page says why.
TEST(HtmlReport, AnotherRunsImagesAreNotShownUnderThisRunsNumbers) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-report-other-{}", getpid());
  fs::remove_all(dir);
  writeImages(dir / "images" / kCase);  // gl's image: 13 pixels off by 0.02
  const auto reportOf = [&](const nlohmann::json& gl) {
    std::ofstream(dir / "results.jsonl") << gl.dump() << "\n";
    const auto [code, out] = reportIn(dir);
    EXPECT_EQ(code, 0) << out;
    return std::pair(out, readText(dir / "html" / "index.html"));
  };
  // This run's own numbers: max error 0.02, its images shown.
  const auto [ownOut, own] = reportOf(record("gl", "Fail", 13));
  EXPECT_NE(own.find("gl against the reference: 13 pixels over 0.004"), std::string::npos);
  EXPECT_EQ(own.find("is another run&apos;s"), std::string::npos);
  EXPECT_EQ(ownOut.find("another run"), std::string::npos) << ownOut;
  // A run whose gl image was within 0.0005 of the reference: not these.
  const auto [otherOut, other] = reportOf(record("gl", "Pass", 0));
  EXPECT_EQ(other.find("gl against the reference:"), std::string::npos);
  EXPECT_EQ(other.find("gl rendered"), std::string::npos);
  EXPECT_NE(other.find("No pictures: the gl image in " + (dir / "images").string() +
                       " is another run&apos;s. Its largest difference from the reference there "
                       "is 0.02; this run recorded 0.0005."),
            std::string::npos)
      << other.substr(other.find("<h2 id=\"cases\">"));
  EXPECT_NE(otherOut.find("holds another run's images of 1 result(s) of the last run"),
            std::string::npos)
      << otherOut;
  fs::remove_all(dir);
}

// A report whose --images holds none of its runs' images said so on stderr
// alone: the page, read later and elsewhere, showed failing image cases
// with no picture as if that were all.
TEST(HtmlReport, AFolderWithoutTheRunsImagesIsSaidOnThePage) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-report-none-{}", getpid());
  fs::remove_all(dir);
  fs::create_directories(dir / "images");
  std::ofstream(dir / "results.jsonl") << record("gl", "Fail", 13).dump() << "\n";
  const auto [code, out] = reportIn(dir);
  ASSERT_EQ(code, 0) << out;
  EXPECT_NE(readText(dir / "html" / "index.html")
                .find("No pictures or heat maps: " + (dir / "images").string() +
                      " (--images) holds none of these runs&apos; images"),
            std::string::npos);
  // With the images there, no such line.
  writeImages(dir / "images" / kCase);
  ASSERT_EQ(reportIn(dir).first, 0);
  EXPECT_EQ(readText(dir / "html" / "index.html").find("No pictures or heat maps"),
            std::string::npos);
  fs::remove_all(dir);
}

// A failure by the golden showed no picture of it: the golden and the heat
// map of the image against it are drawn, when --golden holds the golden
// the run compared with, and said not to be drawn when it holds another.
TEST(HtmlReport, AComparisonWithTheGoldenIsPictured) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-report-gold-{}", getpid());
  fs::remove_all(dir);
  writeImages(dir / "images" / kCase);
  fs::create_directories(dir / "golden" / kCase);
  // The golden is the reference: gl is off it by 0.02 on 13 pixels.
  fs::copy_file(dir / "images" / kCase / "reference.exr", dir / "golden" / kCase / "gl.exr");
  fs::copy_file(dir / "images" / kCase / "reference.png", dir / "golden" / kCase / "gl.png");
  nlohmann::json r = record("gl", "Fail", 13);
  nlohmann::json golden = r["images"][0];
  golden["against"] = "golden";
  r["images"].push_back(golden);
  std::ofstream(dir / "results.jsonl") << r.dump() << "\n";
  const auto reportWith = [&](const fs::path& goldenDir) {
    const auto [code, out] = reportIn(dir, {"results.jsonl"}, "--golden " + goldenDir.string());
    EXPECT_EQ(code, 0) << out;
    return readText(dir / "html" / "index.html");
  };
  const std::string html = reportWith(dir / "golden");
  EXPECT_NE(html.find("gl against its golden: 13 pixels over 0.004"), std::string::npos);
  EXPECT_NE(html.find("golden (gl)"), std::string::npos);
  // Another golden (vk's image in its place) is not drawn under this run's
  // numbers.
  fs::copy_file(dir / "images" / kCase / "vk.exr", dir / "golden" / kCase / "gl.exr",
                fs::copy_options::overwrite_existing);
  const std::string other = reportWith(dir / "golden");
  EXPECT_EQ(other.find("gl against its golden"), std::string::npos);
  EXPECT_NE(other.find("is not the golden this run compared with"), std::string::npos);
  fs::remove_all(dir);
}

// HTML forbids C0 control characters: one in a title or a driver's message
// (a log's ESC, a manifest's U+0001) is spelled out, not written raw.
TEST(HtmlReport, ControlCharactersAreSpelledOut) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-report-ctl-{}", getpid());
  fs::remove_all(dir);
  fs::create_directories(dir / "images");
  nlohmann::json r = record("gl", "Fail", 0);
  r["title"] = "Fresnel \x01 <b>&";
  r["message"] = "worker stderr: \x1b[31mabort\x1b[0m \xc2\x9b csi";
  std::ofstream(dir / "results.jsonl") << r.dump() << "\n";
  const auto [code, out] = reportIn(dir);
  ASSERT_EQ(code, 0) << out;
  const std::string html = readText(dir / "html" / "index.html");
  for (const char c : html)
    EXPECT_FALSE(static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t' && c != '\r')
        << "a raw control character " << static_cast<int>(c);
  EXPECT_NE(html.find("Fresnel \\x01 &lt;b&gt;&amp;"), std::string::npos);
  EXPECT_NE(html.find("\\x1b[31mabort\\x1b[0m \\xc2\\x9b csi"), std::string::npos);
  EXPECT_EQ(html.find("\xc2\x9b"), std::string::npos) << "a raw C1 control character";
  fs::remove_all(dir);
}

// A report of two runs showed neither regressions nor fixes: every case
// that failed in either run had the failing border and came first, and the
// tally added both runs' counts. The page now says what changed from the
// first run to the last, as `snell compare` does, counts each run apart,
// and marks a case by the last run.
TEST(HtmlReport, TwoRunsShowTheirRegressionsAndFixes) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-report-two-{}", getpid());
  fs::remove_all(dir);
  fs::create_directories(dir / "images");
  std::ofstream(dir / "passing.jsonl") << record("gl", "Pass", 0).dump() << "\n";
  std::ofstream(dir / "failing.jsonl") << record("gl", "Fail", 13).dump() << "\n";
  const auto reportOf = [&](const char* first, const char* second) {
    const auto [code, out] = reportIn(dir, {first, second});
    EXPECT_EQ(code, 0) << out;
    return readText(dir / "html" / "index.html");
  };
  const std::string row = fmt::format(
      "<td>gl</td><td><a href=\"#case-orange-book-14-1-fresnel-sphere\">{}</a></td>", kCase);
  const std::string regressed = reportOf("passing.jsonl", "failing.jsonl");
  EXPECT_NE(regressed.find("1 regressions, 0 fixes"), std::string::npos);
  EXPECT_NE(regressed.find("<td>regression</td>" + row), std::string::npos) << regressed;
  EXPECT_NE(regressed.find("<div class=\"case failing\""), std::string::npos);
  const std::string passingLabel =
      "<b>" + (dir / "passing.jsonl").string() + "</b>: <span class=\"Pass\">1 Pass</span>";
  EXPECT_NE(regressed.find(passingLabel), std::string::npos) << regressed.substr(0, 4000);
  const std::string fixed = reportOf("failing.jsonl", "passing.jsonl");
  EXPECT_NE(fixed.find("0 regressions, 1 fixes"), std::string::npos);
  EXPECT_NE(fixed.find("<td>fix</td>" + row), std::string::npos) << fixed;
  EXPECT_EQ(fixed.find("<div class=\"case failing\""), std::string::npos)
      << "fixed in the last run, yet marked failing";
  // A timeout that passed on its rerun is a flake, as run and merge judge
  // it: no regression, not marked failing, and its page says what happened.
  nlohmann::json flake = record("gl", "Timeout", 0);
  flake["reruns"] = {"Pass"};
  std::ofstream(dir / "flaky.jsonl") << flake.dump() << "\n";
  const std::string flaky = reportOf("passing.jsonl", "flaky.jsonl");
  EXPECT_NE(flaky.find("0 regressions, 0 fixes, 0 changes, 1 flakes"), std::string::npos) << flaky;
  EXPECT_NE(flaky.find("<td>flake (a rerun passed)</td>" + row +
                       "<td class=\"Timeout\">Timeout</td><td class=\"Pass\">Pass</td>"),
            std::string::npos)
      << flaky;
  EXPECT_EQ(flaky.find("<div class=\"case failing\""), std::string::npos);
  EXPECT_NE(flaky.find("<span class=\"Flake\">&nbsp;Timeout, then Pass on a rerun (Flake)&nbsp;"),
            std::string::npos)
      << flaky;
  fs::remove_all(dir);
}

TEST(HtmlReport, RendersInHeadlessChromiumWithEveryImageEmbedded) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-report-test-{}", getpid());
  fs::remove_all(dir);
  writeImages(dir / "images" / kCase);
  {
    std::ofstream out(dir / "results.jsonl");
    out << record("gl", "Fail", 13).dump() << "\n" << record("vk", "Pass", 0).dump() << "\n";
  }
  const auto [code, out] = reportIn(dir);
  ASSERT_EQ(code, 0) << out;
  const std::string html = readText(dir / "html" / "index.html");
  // The failure is named, with its count, in the heat map's caption.
  EXPECT_NE(html.find("gl against the reference: 13 pixels over 0.004"), std::string::npos);
  // The backend pair names its run, and says the run did not compare it:
  // gl's image is off the reference, so the gate held no pair with it.
  EXPECT_NE(html.find(fmt::format("vk against gl ({}): 13 pixels over 0.004",
                                  (dir / "results.jsonl").string())),
            std::string::npos);
  EXPECT_NE(html.find("not compared by the run, one image being off the reference"),
            std::string::npos);
  EXPECT_NE(html.find("softpipe"), std::string::npos);
  // The matrix cell of the failing image says what failed (its slack alone
  // read as a passing case's), and the passing one does not.
  EXPECT_NE(html.find("slack 0.73 · reference 0.02 (13 px over fail)"), std::string::npos);
  EXPECT_EQ(html.find("reference 0.0005 ("), std::string::npos);
  // Every image is embedded and decodes: PNGs start with the PNG signature,
  // charts are SVG.
  const std::regex img("<img[^>]*src=\"([^\"]*)\"");
  std::size_t images = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), img); it != std::sregex_iterator();
       ++it) {
    const std::string src = (*it)[1];
    ++images;
    ASSERT_EQ(src.rfind("data:", 0), 0u) << src.substr(0, 80);
    if (src.rfind("data:image/png;base64,", 0) == 0) {
      EXPECT_EQ(src.substr(22, 8), "iVBORw0K") << "not a PNG";
    } else {
      ASSERT_EQ(src.rfind("data:image/svg+xml;base64,", 0), 0u) << src.substr(0, 80);
      EXPECT_EQ(src.find("<svg"), std::string::npos);
    }
  }
  // Histograms for gl and vk; reference, two renders, two heat maps against
  // it, one backend pair.
  EXPECT_EQ(images, 2u + 6u);
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);

  // A real browser, with every host unreachable.
  const fs::path screenshot = fs::path(SNELL_SCREENSHOT_DIR) / "report-screenshot.png";
  fs::remove(screenshot);
  const auto [browserCode, browserOut] = shell(fmt::format(
      "chromium --headless --no-sandbox --disable-gpu --no-first-run --user-data-dir={} "
      "--host-resolver-rules='MAP * ~NOTFOUND' --hide-scrollbars --window-size=1280,2400 "
      "--screenshot={} file://{}",
      (dir / "profile").string(), screenshot.string(), (dir / "html" / "index.html").string()));
  ASSERT_TRUE(fs::exists(screenshot))
      << "chromium (Debian package chromium, ci/packages.txt): " << browserCode << "\n"
      << browserOut;
  // The screenshot may have 3 or 4 channels.
  auto input = OIIO::ImageInput::open(screenshot.string());
  ASSERT_TRUE(input) << OIIO::geterror();
  const OIIO::ImageSpec& spec = input->spec();
  const int channels = spec.nchannels;
  std::vector<float> shot(static_cast<std::size_t>(spec.width) * spec.height * channels);
  ASSERT_TRUE(input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, shot.data()));
  // Not blank: dark text on the light page, and colour (statuses, charts,
  // heat maps).
  std::size_t dark = 0, coloured = 0;
  const std::size_t pixels = shot.size() / channels;
  for (std::size_t p = 0; p < pixels; ++p) {
    const float* px = &shot[p * channels];
    if (px[0] + px[1] + px[2] < 0.6f) ++dark;
    if (std::abs(px[0] - px[1]) > 0.1f || std::abs(px[1] - px[2]) > 0.1f) ++coloured;
  }
  EXPECT_GT(dark, pixels / 200) << "no text or images drawn";
  EXPECT_GT(coloured, pixels / 100) << "no status colours, charts or heat maps drawn";
  fs::remove_all(dir);
}

}  // namespace

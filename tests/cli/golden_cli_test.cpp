// Goldens through the command a user runs: a changed golden fails, a damaged
// one is a clear error and stays as it was, bless writes only what it ran
// and never a wrong image.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "compare/image_io.h"
#include "golden/golden_store.h"
#include "snell_process.h"

namespace snell {
namespace {

namespace fs = std::filesystem;
using testing::readText;

const std::string kCase = "orange-book/14.1-fresnel/sphere";

class GoldenCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / fmt::format("snell-golden-cli-{}", getpid());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "shaders");
    fs::copy(SNELL_SOURCE_ROOT "/shaders/orange-book/14.1-fresnel", dir_ / "shaders" / "fresnel");
    fs::copy(SNELL_SOURCE_ROOT "/golden", dir_ / "golden", fs::copy_options::recursive);
  }
  void TearDown() override { fs::remove_all(dir_); }

  struct Outcome {
    int code;
    std::string output;
    nlohmann::json result;  // the gl result of kCase, when there is one
  };

  Outcome snell(const std::string& command, const std::string& extra = "") {
    const fs::path json = dir_ / "results.jsonl", log = dir_ / "log.txt";
    const std::string line = fmt::format(
        "{} {} --backend gl -j 1 --filter '{}' --shaders {} --golden {} --out {} --json {} {} >{} "
        "2>&1",
        SNELL_BINARY, command, kCase, (dir_ / "shaders").string(), (dir_ / "golden").string(),
        (dir_ / "out").string(), json.string(), extra, log.string());
    const int status = std::system(line.c_str());
    Outcome outcome{WIFEXITED(status) ? WEXITSTATUS(status) : -1, "", {}};
    std::ifstream logIn(log);
    outcome.output.assign(std::istreambuf_iterator<char>(logIn), {});
    std::ifstream in(json);
    for (std::string text; std::getline(in, text);) outcome.result = nlohmann::json::parse(text);
    return outcome;
  }

  fs::path goldenExr() const { return goldenFiles(dir_ / "golden", kCase, "gl").image; }

  void nudgeOnePixel(float by) {
    Image image = readImage(goldenExr());
    // A pixel in the middle of the sphere, off every mask.
    image.at(128, 128)[1] += by;
    writeImageAtomically(goldenExr(), image);
  }

  fs::path dir_;
};

TEST_F(GoldenCli, RepositoryGoldensPass) {
  const Outcome o = snell("run");
  EXPECT_EQ(o.code, 0) << o.output;
  EXPECT_EQ(o.result["status"], "Pass") << o.output;
}

TEST_F(GoldenCli, OnePixelBeyondFailFails) {
  nudgeOnePixel(0.005f);
  const Outcome o = snell("run");
  EXPECT_EQ(o.code, 1);
  EXPECT_EQ(o.result["status"], "Fail");
  EXPECT_NE(o.output.find("image vs golden: fail"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("at (128, 128), 1 of"), std::string::npos) << o.output;
  // The failure names the heat map that shows it (the message named none).
  const fs::path heatMap = dir_ / "out" / kCase / "gl-vs-golden.png";
  EXPECT_NE(o.output.find("pixels over 0.004; heat map " + heatMap.string()), std::string::npos)
      << o.output;
  EXPECT_TRUE(fs::exists(heatMap));
  // It names the golden and the command that blesses the image, should the
  // change be intended, as a missing golden's message does.
  const std::string advice = fmt::format(
      "golden {}: if the change is intended, bless the new image with `snell bless --backend gl "
      "--shaders {} --golden {} --filter '{}'`",
      goldenExr().string(), (dir_ / "shaders").string(), (dir_ / "golden").string(), kCase);
  EXPECT_NE(o.output.find(advice), std::string::npos) << o.output;
  // The summary's image error is the golden's, by which the row fails (0.005
  // on one pixel), not the reference's.
  EXPECT_NE(o.output.find("5.00e-03"), std::string::npos) << o.output;
}

TEST_F(GoldenCli, OnePixelBetweenWarnAndFailIsAQualityWarning) {
  nudgeOnePixel(0.003f);
  const Outcome o = snell("run");
  EXPECT_EQ(o.code, 0) << o.output;
  EXPECT_EQ(o.result["status"], "QualityWarning") << o.output;
}

TEST_F(GoldenCli, TruncatedGoldenIsAClearErrorAndIsLeftAsItWas) {
  fs::resize_file(goldenExr(), fs::file_size(goldenExr()) / 3);
  std::ifstream before(goldenExr(), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(before)), {});
  const Outcome o = snell("run");
  EXPECT_EQ(o.code, 1);
  EXPECT_EQ(o.result["status"], "Fail");
  EXPECT_NE(o.output.find(goldenExr().string()), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("snell bless"), std::string::npos) << o.output;
  std::ifstream after(goldenExr(), std::ios::binary);
  EXPECT_EQ(std::string((std::istreambuf_iterator<char>(after)), {}), bytes);
}

// The advice is a command the user can paste: it names their own folders,
// not the repository's.
TEST_F(GoldenCli, MissingGoldenAdviceRepeatsTheUsersOwnFolders) {
  const GoldenFiles files = goldenFiles(dir_ / "golden", kCase, "gl");
  for (const fs::path& file : {files.image, files.preview, files.metadata}) fs::remove(file);
  const Outcome o = snell("run");
  EXPECT_EQ(o.code, 1) << o.output;
  EXPECT_EQ(o.result["status"], "Fail") << o.output;
  const std::string advice =
      fmt::format("snell bless --backend gl --shaders {} --golden {} --filter '{}'",
                  (dir_ / "shaders").string(), (dir_ / "golden").string(), kCase);
  EXPECT_NE(o.output.find(advice), std::string::npos) << o.output;
}

TEST_F(GoldenCli, BlessRestoresAChangedGoldenAndSaysByHowMuch) {
  nudgeOnePixel(0.005f);
  const Outcome o = snell("bless");
  EXPECT_EQ(o.code, 0) << o.output;
  EXPECT_NE(o.output.find("blessed (changed: max error 0.005"), std::string::npos) << o.output;
  EXPECT_EQ(snell("run").result["status"], "Pass");
}

// Every golden file's bytes, by path.
std::map<std::string, std::string> goldenTree(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file()) {
      std::ifstream in(entry.path(), std::ios::binary);
      files[entry.path().string()].assign(std::istreambuf_iterator<char>(in), {});
    }
  return files;
}

// A bless cut short by Ctrl-C blesses nothing (a partial set of new
// goldens with exit 0 would be committed as whole): exit 130, every golden
// as it was, no temporary file left among them.
TEST_F(GoldenCli, AnInterruptedBlessBlessesNothing) {
  nudgeOnePixel(0.005f);  // a golden that a finished bless would write
  const auto before = goldenTree(dir_ / "golden");
  const fs::path json = dir_ / "bless.jsonl";
  const pid_t pid = testing::spawnSnell({"bless", "--backend", "gl,vk", "-j", "1", "--oracle-cache",
                                         "off", "--shaders", SNELL_SOURCE_ROOT "/shaders",
                                         "--golden", (dir_ / "golden").string(), "--out",
                                         (dir_ / "out").string(), "--json", json.string()});
  const fs::path partial = json.string() + ".partial";
  // Interrupted once its first result is written, with the rest to render.
  const auto oneWritten = [&] {
    std::error_code error;
    const auto size = fs::file_size(partial, error);
    return !error && size > 0;
  };
  const auto started = std::chrono::steady_clock::now();
  while (!oneWritten() && std::chrono::steady_clock::now() - started < std::chrono::seconds(120))
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_TRUE(oneWritten());
  ::kill(pid, SIGINT);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_EQ(goldenTree(dir_ / "golden"), before);
}

TEST_F(GoldenCli, BlessTouchesOnlyTheCasesItRan) {
  const fs::path other =
      goldenFiles(dir_ / "golden", "orange-book/14.3-chromatic/sphere", "gl").image;
  const auto before = fs::last_write_time(other);
  const auto vkBefore = fs::last_write_time(goldenFiles(dir_ / "golden", kCase, "vk").image);
  EXPECT_EQ(snell("bless").code, 0);
  EXPECT_EQ(fs::last_write_time(other), before);
  EXPECT_EQ(fs::last_write_time(goldenFiles(dir_ / "golden", kCase, "vk").image), vkBefore);
}

// The same pixels blessed again leave the golden's files as they were:
// encoded anew they would differ in their bytes (the EXR header's date, PNG
// compression), and every bless would be a binary change to review. The
// files are copied first, as a fresh clone has them: without the mark by
// which snell skips writing an image it wrote itself (core/written_mark.h).
class GoldenBlessAgain : public GoldenCli {
 protected:
  void SetUp() override {
    GoldenCli::SetUp();
    ASSERT_EQ(snell("bless").code, 0);  // this machine's own image and metadata
    files_ = goldenFiles(dir_ / "golden", kCase, "gl");
    for (const fs::path& path : {files_.image, files_.preview, files_.metadata}) {
      const fs::path copy = dir_ / "copy";
      fs::copy_file(path, copy);
      fs::remove(path);
      fs::rename(copy, path);
    }
  }

  static std::string bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
  struct Snapshot {
    std::string bytes;
    fs::file_time_type time;
  };
  static Snapshot snapshot(const fs::path& path) {
    return {bytes(path), fs::last_write_time(path)};
  }
  static void expectUntouched(const fs::path& path, const Snapshot& before) {
    EXPECT_EQ(bytes(path), before.bytes) << path;
    EXPECT_EQ(fs::last_write_time(path), before.time) << path;
  }

  GoldenFiles files_;
};

TEST_F(GoldenBlessAgain, TheSamePixelsWriteNothing) {
  const Snapshot image = snapshot(files_.image), preview = snapshot(files_.preview),
                 metadata = snapshot(files_.metadata);
  const Outcome o = snell("bless");
  EXPECT_EQ(o.code, 0) << o.output;
  EXPECT_NE(o.output.find("blessed (unchanged, files left as they were)"), std::string::npos)
      << o.output;
  expectUntouched(files_.image, image);
  expectUntouched(files_.preview, preview);
  expectUntouched(files_.metadata, metadata);
}

// A lost preview alone is written again, and said so.
TEST_F(GoldenBlessAgain, ALostPreviewIsWrittenAgainAndSaidSo) {
  fs::remove(files_.preview);
  const Snapshot image = snapshot(files_.image), metadata = snapshot(files_.metadata);
  const Outcome o = snell("bless");
  EXPECT_EQ(o.code, 0) << o.output;
  EXPECT_NE(o.output.find("blessed (unchanged pixels, the lost preview written again)"),
            std::string::npos)
      << o.output;
  EXPECT_TRUE(fs::is_regular_file(files_.preview));
  expectUntouched(files_.image, image);
  expectUntouched(files_.metadata, metadata);
}

// A changed tolerance rewrites the metadata alone; a lost preview is
// written again beside the kept image.
TEST_F(GoldenBlessAgain, OnlyWhatChangedOrIsMissingIsWritten) {
  const fs::path manifest = dir_ / "shaders" / "fresnel" / "manifest.toml";
  std::string text = bytes(manifest);
  text.replace(text.find("warn = 0.002"), 12, "warn = 0.0025");
  std::ofstream(manifest, std::ios::trunc) << text;
  fs::remove(files_.preview);
  const Snapshot image = snapshot(files_.image);
  const Outcome o = snell("bless");
  EXPECT_EQ(o.code, 0) << o.output;
  EXPECT_NE(o.output.find("blessed (unchanged pixels, the lost preview written again; metadata "
                          "rewritten (tolerance changed))"),
            std::string::npos)
      << o.output;
  expectUntouched(files_.image, image);
  EXPECT_TRUE(fs::is_regular_file(files_.preview));
  EXPECT_EQ(nlohmann::json::parse(bytes(files_.metadata))["tolerance"]["warn"], 0.0025);
}

// A preview that does not read as an image is written again, as a lost one
// is; a field of the metadata that changed is named (here the CPU features
// the goldens were rendered with, not the driver or the tolerance).
TEST_F(GoldenBlessAgain, ADamagedPreviewIsWrittenAgainAndAChangedFieldNamed) {
  fs::resize_file(files_.preview, 100);
  nlohmann::json metadata = nlohmann::json::parse(bytes(files_.metadata));
  const nlohmann::json features = metadata["cpu_features"];
  metadata["cpu_features"] = "sse4_1";
  std::ofstream(files_.metadata, std::ios::trunc) << metadata.dump(2) << "\n";
  const Snapshot image = snapshot(files_.image);
  const Outcome o = snell("bless");
  EXPECT_EQ(o.code, 0) << o.output;
  EXPECT_NE(o.output.find("blessed (unchanged pixels, the damaged preview written again; "
                          "metadata rewritten (cpu_features changed))"),
            std::string::npos)
      << o.output;
  expectUntouched(files_.image, image);
  EXPECT_GT(fs::file_size(files_.preview), 100u);
  EXPECT_EQ(readImage(files_.preview).width, readImage(files_.image).width);
  EXPECT_EQ(nlohmann::json::parse(bytes(files_.metadata))["cpu_features"], features);
}

// A golden whose files are there but do not read is replaced, and the
// output says so and why: it is not a new golden.
TEST_F(GoldenBlessAgain, AGoldenThatDoesNotReadIsSaidToBeReplaced) {
  std::ofstream(files_.metadata, std::ios::trunc) << "not json {";
  Outcome o = snell("bless");
  EXPECT_EQ(o.code, 0) << o.output;
  EXPECT_EQ(o.output.find("blessed (new)"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("blessed (replaced a golden that could not be read: golden " +
                          files_.metadata.string() + ": not valid JSON"),
            std::string::npos)
      << o.output;
  EXPECT_EQ(o.output.find("bless a new one with"), std::string::npos) << o.output;
  EXPECT_TRUE(nlohmann::json::parse(bytes(files_.metadata)).is_object());
  // Valid JSON that is not a golden's metadata is no better.
  std::ofstream(files_.metadata, std::ios::trunc) << "[1, 2]";
  o = snell("run");
  EXPECT_EQ(o.code, 1) << o.output;
  EXPECT_NE(o.output.find("not a golden's metadata"), std::string::npos) << o.output;
  // With every file gone it is new.
  for (const fs::path& file : {files_.image, files_.preview, files_.metadata}) fs::remove(file);
  o = snell("bless");
  EXPECT_NE(o.output.find("blessed (new)"), std::string::npos) << o.output;
}

TEST_F(GoldenCli, BlessRefusesAnImageThatIsOffTheReference) {
  std::ifstream in(dir_ / "shaders" / "fresnel" / "fresnel.vert");
  std::string source((std::istreambuf_iterator<char>(in)), {});
  source.replace(source.find("Eta = 0.66"), 10, "Eta = 0.67");
  std::ofstream(dir_ / "shaders" / "fresnel" / "fresnel.vert", std::ios::trunc) << source;
  const auto before = fs::last_write_time(goldenExr());
  const Outcome o = snell("bless");
  EXPECT_EQ(o.code, 1);
  EXPECT_NE(o.output.find("not blessed"), std::string::npos) << o.output;
  EXPECT_EQ(fs::last_write_time(goldenExr()), before);
}

// --out naming the --golden folder (with or without a trailing slash): run
// wrote its images over the goldens before comparing with them, so a wrong
// shader passed, and the goldens were lost. Refused before any case.
TEST_F(GoldenCli, OutIntoTheGoldenFolderIsRefusedBeforeAnyCase) {
  const auto before = goldenTree(dir_ / "golden");
  for (const std::string command : {"run", "bless"})
    for (const std::string slash : {"", "/"}) {
      const fs::path log = dir_ / "log.txt";
      const std::string line = fmt::format(
          "{} {} --backend gl -j 1 --filter '{}' --shaders {} --golden {} --out {}{} >{} 2>&1",
          SNELL_BINARY, command, kCase, (dir_ / "shaders").string(), (dir_ / "golden").string(),
          (dir_ / "golden").string(), slash, log.string());
      const int status = std::system(line.c_str());
      std::ifstream in(log);
      const std::string output((std::istreambuf_iterator<char>(in)), {});
      EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 2) << line << "\n" << output;
      EXPECT_NE(output.find("is also --golden"), std::string::npos) << output;
      EXPECT_EQ(goldenTree(dir_ / "golden"), before) << line;
    }
}

// Against a --golden folder with no golden for the driver (not the one
// blessed into) every image case passed on the CPU reference alone, and
// the summary said nothing: it now says how many and which.
TEST_F(GoldenCli, ImageCasesWithoutAGoldenAreSaidInTheSummary) {
  const Outcome blessed = snell("run");
  EXPECT_EQ(blessed.code, 0) << blessed.output;
  EXPECT_EQ(blessed.output.find("had no golden"), std::string::npos) << blessed.output;
  fs::create_directories(dir_ / "empty");
  const fs::path log = dir_ / "log.txt";
  const int status = std::system(
      fmt::format(
          "{} run --backend gl -j 1 --filter '{}' --shaders {} --golden {} --out {} >{} 2>&1",
          SNELL_BINARY, kCase, (dir_ / "shaders").string(), (dir_ / "empty").string(),
          (dir_ / "out").string(), log.string())
          .c_str());
  std::ifstream in(log);
  const std::string output((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 0) << output;
  EXPECT_NE(output.find("1 image case(s) had no golden for their driver, so only the CPU "
                        "reference gated them: " +
                        kCase + " on gl"),
            std::string::npos)
      << output;
}

// A run's --out inside its --golden folder: the renders of the run before
// (OUT/CASE/gl.png) read as goldens of the driver, and the next run
// reported every image case's golden as missing, where the folder has none.
TEST_F(GoldenCli, RendersOfAnEarlierRunInsideTheGoldenFolderAreNotGoldens) {
  const fs::path golden = dir_ / "golden-with-out";
  fs::create_directories(golden);
  const fs::path log = dir_ / "log-inside.txt";
  const auto run = [&] {
    const int status = std::system(
        fmt::format("{} run --backend gl -j 1 --filter '{}' --shaders {} --golden {} --out {} "
                    ">{} 2>&1",
                    SNELL_BINARY, kCase, (dir_ / "shaders").string(), golden.string(),
                    (golden / "out").string(), log.string())
            .c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  EXPECT_EQ(run(), 0);
  ASSERT_TRUE(fs::exists(golden / "out" / kCase / "gl.png"));
  EXPECT_EQ(run(), 0) << readText(log);
  EXPECT_NE(readText(log).find("1 image case(s) had no golden for their driver"), std::string::npos)
      << readText(log);
}

TEST_F(GoldenCli, AResultsFileOnAGoldensFilesIsRefusedAndTheGoldenKept) {
  const GoldenFiles files = goldenFiles(dir_ / "golden", kCase, "gl");
  const std::string image = readText(files.image), metadata = readText(files.metadata);
  const fs::path log = dir_ / "log-onto.txt";
  const auto snellWith = [&](const std::string& command, const std::string& outputs) {
    const int status = std::system(
        fmt::format("{} {} --backend gl -j 1 --filter '{}' --shaders {} --golden {} --out {} {} "
                    ">{} 2>&1",
                    SNELL_BINARY, command, kCase, (dir_ / "shaders").string(),
                    (dir_ / "golden").string(), (dir_ / "out").string(), outputs, log.string())
            .c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  // The golden's metadata as run's results, its preview as run's JUnit
  // file, its image as bless's results: each refused before any case runs.
  // And where a golden of another backend, with none yet, would go: bless
  // would write over the results.
  const std::vector<std::pair<std::string, std::string>> attempts = {
      {"run", "--json " + files.metadata.string()},
      {"run", "--junit " + files.preview.string()},
      {"bless", "--json " + files.image.string()},
      {"bless", "--json " + goldenFiles(dir_ / "golden", kCase, "gl-softpipe").metadata.string()}};
  for (const auto& [command, outputs] : attempts) {
    EXPECT_EQ(snellWith(command, outputs), 2) << command << " " << outputs << "\n" << readText(log);
    EXPECT_NE(readText(log).find("is a golden's file under --golden"), std::string::npos)
        << readText(log);
    EXPECT_FALSE(fs::exists(dir_ / "out" / kCase)) << "a case ran: " << outputs;
  }
  EXPECT_EQ(readText(files.image), image);
  EXPECT_EQ(readText(files.metadata), metadata);
  EXPECT_TRUE(fs::exists(files.preview));
  // A results file in the golden folder itself is not a golden, nor is its
  // FILE.timing.json, also on a second run that finds the first one's.
  const fs::path results = dir_ / "golden" / "results.jsonl";
  EXPECT_EQ(snellWith("run", "--json " + results.string()), 0) << readText(log);
  EXPECT_EQ(snellWith("run", "--json " + results.string()), 0) << readText(log);
  EXPECT_TRUE(fs::exists(dir_ / "golden" / "results.timing.json"));
}

}  // namespace
}  // namespace snell

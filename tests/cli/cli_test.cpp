// The `snell` command as a user runs it.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "edited_listing.h"
#include "json_lines.h"

namespace {

using snell::testing::jsonLines;

namespace fs = std::filesystem;

struct Outcome {
  int code = -1;
  std::string out;  // stdout and stderr together
};

// `env`: a shell prefix such as "VK_LAYER_PATH=/nonexistent".
Outcome snell(const std::string& args, const std::string& input = "", const std::string& env = "") {
  const fs::path in = fs::temp_directory_path() / fmt::format("snell-cli-in-{}", ::getpid());
  std::ofstream(in) << input;
  const std::string command =
      fmt::format("{} {} {} < {} 2>&1", env, SNELL_BINARY, args, in.string());
  FILE* pipe = popen(command.c_str(), "r");
  Outcome outcome;
  std::array<char, 4096> buffer;
  while (std::size_t n = fread(buffer.data(), 1, buffer.size(), pipe))
    outcome.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  outcome.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  fs::remove(in);
  return outcome;
}

TEST(Cli, UnknownFlagIsExit2) { EXPECT_EQ(snell("run --no-such-flag").code, 2); }

// A user reading --help learns where listings, goldens and images go
// without reading the source.
TEST(Cli, HelpShowsTheDefaultFolders) {
  for (const char* command : {"run", "bless"}) {
    const Outcome o = snell(fmt::format("{} --help", command));
    EXPECT_EQ(o.code, 0) << o.out;
    EXPECT_NE(o.out.find(SNELL_SOURCE_ROOT "/shaders"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find(SNELL_SOURCE_ROOT "/golden"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("(default: snell-out)"), std::string::npos) << o.out;
  }
}
TEST(Cli, NoSubcommandIsExit2) { EXPECT_EQ(snell("").code, 2); }
TEST(Cli, BadBackendIsExit2) { EXPECT_EQ(snell("run --backend d3d").code, 2); }
TEST(Cli, MissingShadersFolderIsExit2) { EXPECT_EQ(snell("run --shaders /nonexistent").code, 2); }

TEST(Cli, AFolderWithNoListingsIsExit2SayingSo) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-cli-empty-{}", ::getpid());
  fs::create_directories(dir / "not-a-listing");
  std::ofstream(dir / "not-a-listing" / "shader.vert") << "void main() {}\n";
  for (const char* command : {"list", "run", "bless", "sweep"}) {
    const Outcome o = snell(fmt::format("{} --shaders {}", command, dir.string()));
    EXPECT_EQ(o.code, 2) << command << ": " << o.out;
    EXPECT_NE(o.out.find(dir.string() + ": no listings here (no manifest.toml below it)"),
              std::string::npos)
        << command << ": " << o.out;
  }
  fs::remove_all(dir);
}

// Outputs that cannot be written, or would land on one another, are
// refused before any case runs: not after minutes of work, not as an
// internal error, and with nothing left behind.
// An --out folder on a read-only file system (or, for a user other than
// root, one without write permission) is named before any case runs: its
// first write came from a worker, as each image case's crash.
TEST(Cli, AnOutFolderThatCannotBeWrittenIsExit2BeforeTheRun) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-cli-ro-{}", ::getpid());
  fs::create_directories(dir);
  const bool root = ::geteuid() == 0;
  if (root && ::mount("tmpfs", dir.c_str(), "tmpfs", MS_RDONLY, "size=64k") != 0) {
    fs::remove(dir);
    GTEST_SKIP() << "as root only a read-only mount is unwritable, and mount failed here";
  }
  if (!root) fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec);
  for (const std::string& out : {dir.string(), (dir / "new" / "sub").string()}) {
    const Outcome o = snell("run --filter 'orange-book/14.1-fresnel/*' --backend gl --out " + out);
    EXPECT_EQ(o.code, 2) << o.out;
    EXPECT_NE(o.out.find(fmt::format("--out {}: folder {} is not writable", out, dir.string())),
              std::string::npos)
        << o.out;
    EXPECT_EQ(o.out.find("[1/"), std::string::npos) << "a case ran:\n" << o.out;
  }
  if (root) ::umount(dir.c_str());
  fs::permissions(dir, fs::perms::owner_all);
  fs::remove_all(dir);
}

// A disk that fills during the run: the results file that cannot be
// written is named (not its temporary) with the system's reason, and no
// temporary file is left behind, of the results or of an image.
TEST(Cli, AFullDiskLeavesNoTemporaryFiles) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-cli-full-{}", ::getpid());
  fs::create_directories(dir);
  if (::mount("tmpfs", dir.c_str(), "tmpfs", 0, "size=256k") != 0) {
    fs::remove(dir);
    GTEST_SKIP() << "a small file system needs a tmpfs mount, which failed here";
  }
  const auto temporaries = [&] {
    std::vector<std::string> found;
    for (const auto& e : fs::recursive_directory_iterator(dir))
      if (e.path().filename().string().find(".tmp") != std::string::npos)
        found.push_back(e.path().string());
    return found;
  };
  // Images of two cases do not fit in 256 KiB.
  const Outcome images = snell(fmt::format(
      "run --filter 'orange-book/14.1-fresnel/*' --backend gl --oracle-cache off --out {}/out",
      dir.string()));
  EXPECT_NE(images.out.find("cannot write"), std::string::npos) << images.out;
  EXPECT_EQ(temporaries(), std::vector<std::string>{}) << images.out;
  fs::remove_all(dir / "out");
  std::ofstream(dir / "fill") << std::string(250 * 1024, 'x');
  const Outcome results = snell(
      fmt::format("run --filter 'orange-book/14.1-fresnel/sweep' --backend gl --json {}/r.jsonl",
                  dir.string()));
  EXPECT_EQ(results.code, 2) << results.out;
  EXPECT_NE(results.out.find(
                fmt::format("{}/r.jsonl: write failed (No space left on device)", dir.string())),
            std::string::npos)
      << results.out;
  EXPECT_EQ(temporaries(), std::vector<std::string>{}) << results.out;
  ::umount(dir.c_str());
  fs::remove_all(dir);
}

// An output path that is a link, a device or a pipe was replaced by a plain
// file (the file is written beside it and renamed onto it): a link to the
// results lost its link, and as root --junit /dev/null replaced the device.
// An empty --junit wrote nothing, with exit 0; an empty --filter ran every
// case; --json onto the --expectations file overwrote it. Each is refused
// before any case runs.
TEST(Cli, OutputsThatAreNotPlainFilesOrAreInputsAreRefusedBeforeTheRun) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-cli-kinds-{}", ::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "target.xml") << "kept\n";
  fs::create_symlink(dir / "target.xml", dir / "link.xml");
  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
  std::ofstream(dir / "gl-fails.txt") << "# none\n";
  const std::string run = "run --filter 'orange-book/14.1-fresnel/sweep' --backend gl";
  const std::string d = dir.string();
  for (const auto& [args, expected] : std::vector<std::pair<std::string, std::string>>{
           {fmt::format("--junit {}/link.xml", d),
            fmt::format("--junit {0}/link.xml: is a link to {0}/target.xml; name the file itself",
                        d)},
           {fmt::format("--json {}/pipe", d),
            fmt::format("--json {}/pipe: is a named pipe, not a file", d)},
           {"--junit /dev/null", "--junit /dev/null: is a character device, not a file"},
           {"--junit ''", "--junit: an empty path"},
           {"--expectations ''", "--expectations: an empty path"},
           {"--filter ''", "--filter: an empty glob"},
           {"--device ''", "--device: an empty device"},
           {fmt::format("--expectations {0}/gl-fails.txt --json {0}/gl-fails.txt", d),
            "--expectations"}}) {
    const Outcome o = snell(run + " " + args);
    EXPECT_EQ(o.code, 2) << args << ": " << o.out;
    EXPECT_NE(o.out.find(expected), std::string::npos) << args << ": " << o.out;
    EXPECT_EQ(o.out.find("[1/1]"), std::string::npos) << args << ": the case ran\n" << o.out;
  }
  EXPECT_TRUE(fs::is_symlink(dir / "link.xml"));
  EXPECT_EQ(fs::status(dir / "pipe").type(), fs::file_type::fifo);
  EXPECT_EQ(fs::status("/dev/null").type(), fs::file_type::character);
  std::stringstream expectations;
  expectations << std::ifstream(dir / "gl-fails.txt").rdbuf();
  EXPECT_EQ(expectations.str(), "# none\n");
  fs::remove_all(dir);
}

// Standard output on a full disk: `compare --json`, `devices` and the
// others exited 0 with nothing said, and `list` said "internal error".
TEST(Cli, StandardOutputThatCannotBeWrittenIsExit2WithAMessage) {
  const fs::path err = fs::temp_directory_path() / fmt::format("snell-cli-full-{}", ::getpid());
  for (const std::string args : {"list", "--version", "list --filter '*14.1*'"}) {
    const int status =
        std::system(fmt::format("{} {} >/dev/full 2>{}", SNELL_BINARY, args, err.string()).c_str());
    std::stringstream message;
    message << std::ifstream(err).rdbuf();
    EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 2) << args << ": " << message.str();
    EXPECT_NE(message.str().find("snell: cannot write to standard output"), std::string::npos)
        << args << ": " << message.str();
    EXPECT_EQ(message.str().find("internal error"), std::string::npos) << message.str();
  }
  fs::remove(err);
}

TEST(Cli, OutputsThatCannotBeWrittenAreExit2BeforeTheRun) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-cli-outputs-{}", ::getpid());
  fs::create_directories(dir / "folder");
  std::ofstream(dir / "file") << "not a folder\n";
  const std::string run = "run --filter 'orange-book/14.1-fresnel/sweep' --backend gl";
  const std::string d = dir.string();
  for (const auto& [args, expected] : std::vector<std::pair<std::string, std::string>>{
           {fmt::format("--json {0}/r.jsonl --junit {0}/r.jsonl", d), "are one file"},
           {fmt::format("--json {0}/r.csv", d), "and --json (its results.csv)"},
           {fmt::format("--json {0}/new --out {0}/new", d),
            "a file and a folder cannot both be written there"},
           {fmt::format("--json {0}/{1}.jsonl", d, std::string(300, 'x')),
            fmt::format("--json {}/{}.jsonl: File name too long", d, std::string(300, 'x'))},
           {fmt::format("--out {0}/{1}/sub", d, std::string(300, 'x')),
            fmt::format("--out {}/{}/sub: File name too long", d, std::string(300, 'x'))},
           // Short enough itself, but not its temporary name (FILE.tmpPID).
           {fmt::format("--junit {0}/{1}.xml", d, std::string(250, 'x')),
            fmt::format("--junit {}/{}.xml: too long a name", d, std::string(250, 'x'))},
           {fmt::format("--json {0}/file/r.jsonl", d), "/file is a file, not a folder"},
           {fmt::format("--json {0}/folder", d), "/folder: is a folder"},
           {fmt::format("--junit {0}/no-such/r.xml", d), "/no-such does not exist"},
           {fmt::format("--out {0}/file", d), "/file is a file, not a folder"},
           // A folder that takes no new entries whatever its mode says.
           {"--out /proc/snell-no-such/sub",
            "--out /proc/snell-no-such/sub: cannot make folder "
            "/proc/snell-no-such"}}) {
    const Outcome o = snell(run + " " + args);
    EXPECT_EQ(o.code, 2) << args << ": " << o.out;
    EXPECT_NE(o.out.find(expected), std::string::npos) << args << ": " << o.out;
    EXPECT_EQ(o.out.find("internal error"), std::string::npos) << args << ": " << o.out;
    EXPECT_EQ(o.out.find("[1/1]"), std::string::npos) << args << ": the case ran\n" << o.out;
  }
  EXPECT_FALSE(fs::exists(dir / "r.jsonl"));
  EXPECT_FALSE(fs::exists(dir / "folder.partial"));
  EXPECT_FALSE(fs::exists(dir / "new.partial"));
  // The report's folder, given a results file it could report on.
  ASSERT_EQ(snell(run + fmt::format(" --json {}/r.jsonl", d)).code, 0);
  // A command that fails after making its output folder leaves none of
  // the folders it made.
  const Outcome noSweep =
      snell(fmt::format("report {0}/r.jsonl -o {0}/made/rep --sweep {0}/folder", d));
  EXPECT_EQ(noSweep.code, 2) << noSweep.out;
  EXPECT_FALSE(fs::exists(dir / "made")) << noSweep.out;
  const Outcome badScene = snell(fmt::format("bench --scene nosuch --out {}/made/bench", d));
  EXPECT_EQ(badScene.code, 2) << badScene.out;
  EXPECT_FALSE(fs::exists(dir / "made")) << badScene.out;
  // A report into a folder of the user's leaves what it holds, a `work/`
  // of theirs included, and no scratch folder of its own.
  fs::create_directories(dir / "rep" / "work");
  std::ofstream(dir / "rep" / "work" / "notes.txt") << "mine\n";
  const Outcome kept = snell(fmt::format("report {0}/r.jsonl -o {0}/rep", d));
  EXPECT_EQ(kept.code, 0) << kept.out;
  EXPECT_TRUE(fs::exists(dir / "rep" / "work" / "notes.txt")) << kept.out;
  EXPECT_TRUE(fs::exists(dir / "rep" / "index.html")) << kept.out;
  for (const auto& entry : fs::directory_iterator(dir / "rep"))
    EXPECT_TRUE(entry.path().filename() == "work" || entry.path().filename() == "index.html")
        << entry.path();
  const Outcome report = snell(fmt::format("report {0}/r.jsonl -o {0}/file", d));
  EXPECT_EQ(report.code, 2) << report.out;
  EXPECT_NE(report.out.find("-o " + d + "/file: " + d + "/file is a file, not a folder"),
            std::string::npos)
      << report.out;
  fs::remove_all(dir);
}

// Values CLI11 lets through that would run something meaningless: nan for
// a time or a factor (every range check is false for it), a backend named
// twice (every case twice, two records under one key), a sweep of nothing;
// and options that would be passed over without a word (a driver's device
// for the oracle, rules a driver is not judged by, a ladder beside the
// results file that replaces its own).
TEST(Cli, OptionsThatMeanNothingAreExit2) {
  for (const auto& [args, expected] : std::vector<std::pair<std::string, std::string>>{
           {"run --timeout nan", "not nan"},
           {"sweep --timeout nan", "not nan"},
           {"compare --drift nan a b", "not nan"},
           {"run --backend gl,gl", "`gl` is named twice"},
           {"run --backend gl,", "'gl,' has an empty name between its commas"},
           {"sweep --backend ,vk", "',vk' has an empty name between its commas"},
           {"advise --backend ''", "--backend: an empty backend"},
           {"sweep --listings 'no-such-listing*'", "no listing matches --listings"},
           {"sweep --no-builtins --listings ''", "nothing to sweep"},
           {"eval --backend oracle --device 0 -", "--device 0: oracle does not take a device"},
           {"eval --backend foo -", "unknown backend 'foo': use oracle or one of gl, "},
           {"serve --backend gl --idle-exit 1.5", "--idle-exit: give a whole number"},
           // A count that is not a whole number: not "Value abc not in range",
           // and not hexadecimal read as a count.
           {"run --reruns abc --filter 'no-such/*'", "--reruns: give a whole number"},
           {"run -j 0x10 --filter 'no-such/*'", "--jobs: give a whole number"},
           {"bench --repeats 2.5", "--repeats: give a whole number"},
           {"bench --warmup -1", "--warmup: give a whole number"},
           // The one scene the references model, named for an unknown scene
           // too (not a list of scenes it would refuse as well).
           {"bench --scene cube", "bench the `sphere` scene, not `cube`"},
           {"bench --scene torus", "bench the `sphere` scene, not `torus`"},
           // Empty (an unset variable): not the default folder in its place.
           {"run --oracle-cache '' --filter 'no-such/*'", "--oracle-cache: an empty path"},
           {"run --json '' --filter 'no-such/*'", "--json: an empty path"},
           {"eval --backend gl --rules vulkan -", "a gl driver is judged by its own API's rules"},
           // A driver option no backend of the command reads, which each
           // would pass over without a word (each case ends at once without
           // the check too: no server left up, no suite or sweep run).
           {"eval --backend gl --device 7 -",
            "--device 7: gl does not take a device (only gl:gpu, vk and vk:gpu do)"},
           {"eval --backend vk --gl-provider egl -",
            "--gl-provider egl: vk does not take an OpenGL context provider"},
           {"eval --backend gl:gpu --gl-provider osmesa -", "gl:gpu does not take"},
           {"serve --backend gl:softpipe --device 1 --idle-exit 1",
            "gl:softpipe does not take a device"},
           {"run --backend gl,gl:softpipe --device 0 --filter 'no-such/*'",
            "none of gl, gl:softpipe takes a device"},
           {"sweep --backend vk --gl-provider osmesa --listings 'no-such*'",
            "vk does not take an OpenGL context"},
           // One backend of the run reading it is enough; `all` may hold one.
           {"run --backend gl,vk --device 0 --filter 'no-such/*'", "no case matches --filter"},
           {"run --backend all --gl-provider egl --filter 'no-such/*'", "no case matches --filter"},
           {"advise --ladder dispersion --scene sphere --budget 1 --results " SNELL_SOURCE_ROOT
            "/docs/bench/fresnel/bench.json",
            "both say which results to read"},
           // Empty paths on the other commands (an internal error, or the
           // default in their place).
           {"merge /dev/null --json ''", "--json: an empty path"},
           {"merge /dev/null --json /tmp/m.jsonl --junit ''", "--junit: an empty path"},
           {"report /dev/null -o ''", "--out: an empty path"},
           {"report /dev/null -o /tmp/r --images ''", "--images: an empty path"},
           {"sweep --out ''", "--out: an empty path"},
           {"sweep --json ''", "--json: an empty path"},
           {"bench --out ''", "--out: an empty path"},
           {"advise --scene sphere --budget 1 --results ''", "--results: an empty path"},
           // bench: each backend once, sizes increasing (the error is taken
           // at the last, which the charts call the largest).
           {"init /dev/null", "/dev/null: a file, not a folder"},
           {"run --shard '' --filter 'no-such/*'", "--shard: empty (are the CI variables unset?)"},
           {"run --shard / --filter 'no-such/*'", "--shard: empty"},
           {"bench --backends vk,vk", "`vk` is named twice"},
           {"bench --resolutions 64,32", "--resolutions 64,32: give them in increasing order"},
           {"bench --resolutions 32,32", "--resolutions 32,32: give them in increasing order"},
           // A list is read as given: an empty item is a number left out,
           // not one to drop (CLI11's own delimiter drops it).
           {"bench --resolutions 16,,32", "--resolutions: item 2 of `16,,32` is empty"},
           {"bench --resolutions 16,32,", "--resolutions: item 3 of `16,32,` is empty"},
           {"bench --resolutions 16,abc", "--resolutions: `abc` is not a whole number"},
           {"bench --resolutions ''", "--resolutions: an empty list of sizes"},
           {"bench --resolutions 99999999999", "--resolutions: `99999999999` is too large"},
           {"bench --tessellations 12,,48", "--tessellations: item 2 of `12,,48` is empty"},
           // Lists given apart join, as before: the sizes are checked together.
           {"bench --resolutions 64 --resolutions 32",
            "--resolutions 64,32: give them in increasing order"},
           {"bench --resolutions 64 32", "--resolutions 64,32: give them in increasing order"}}) {
    const Outcome o = snell(args);
    EXPECT_EQ(o.code, 2) << args << ": " << o.out;
    EXPECT_NE(o.out.find(expected), std::string::npos) << args << ": " << o.out;
  }
}

// A budget the most accurate method misses by less than the fourth digit:
// its error is printed to as many digits as tell the two apart (it read
// "no method within 0.05825; the most accurate is ... 0.05825").
TEST(Cli, AdviseTellsAMissedBudgetFromTheErrorThatMissedIt) {
  const Outcome o =
      snell("advise --scene sphere --budget 0.05825 --backend vk --results " SNELL_SOURCE_ROOT
            "/docs/bench/fresnel/bench.json");
  EXPECT_EQ(o.code, 1) << o.out;
  EXPECT_NE(o.out.find("no method within de_mean 0.05825; the most accurate is "
                       "6-exact-fragment"),
            std::string::npos)
      << o.out;
  EXPECT_NE(o.out.find("de_mean 0.058252)"), std::string::npos) << o.out;
}

// The validation layer is Vulkan's: on a run without Vulkan it checks
// nothing, and says so.
TEST(Cli, ValidationWithoutVulkanIsNoted) {
  const Outcome o =
      snell("run --filter 'orange-book/14.1-fresnel/sweep' --backend gl --validation");
  EXPECT_EQ(o.code, 0) << o.out;
  EXPECT_NE(o.out.find("--validation checks Vulkan backends only, and this run has none (gl)"),
            std::string::npos)
      << o.out;
}

// --validation where the layer cannot be found: every case was a Crash,
// exit 1, each record saying why. The backend is brought up as its workers
// bring it up, so the run stops before any case, exit 2.
TEST(Cli, ValidationWithoutTheLayerIsExit2BeforeAnyCase) {
  const Outcome o = snell("run --filter 'orange-book/14.1-fresnel/sweep' --backend vk --validation",
                          "", "VK_LAYER_PATH=/nonexistent");
  EXPECT_EQ(o.code, 2) << o.out;
  EXPECT_NE(o.out.find("backend vk cannot be brought up"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("is not installed: install vulkan-validationlayers"), std::string::npos)
      << o.out;
  EXPECT_EQ(o.out.find("Crash"), std::string::npos) << o.out;
}

TEST(Cli, FilterMatchingNothingIsExit2WithHint) {
  const Outcome o = snell("run --filter 'no-such/*'");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.out.find("snell list"), std::string::npos) << o.out;
}

// As run does, list refuses a filter that matches no case, and a listing's
// id (which matches none of its cases) is told how to match them.
TEST(Cli, ListFilterMatchingNothingIsExit2) {
  for (const auto& [args, expected] : std::vector<std::pair<std::string, std::string>>{
           {"list --filter 'orange-book/14.1-fresnel'",
            "use --filter 'orange-book/14.1-fresnel/*'"},
           {"list --filter 'no-such/*'", "no case matches --filter 'no-such/*'"},
           {"run --filter 'orange-book/14.1-fresnel'", "use --filter 'orange-book/14.1-fresnel/*'"},
           {"bless --filter 'orange-book/14.1-fresnel' --golden /tmp",
            "no image case matches --filter 'orange-book/14.1-fresnel', which is listing "
            "orange-book/14.1-fresnel's id"},
           // Cases that match but have no image check are the reason, not
           // the filter (which `cs381/chromatic-aberration/*` would not mend).
           {"bless --filter 'cs381/*' --golden /tmp",
            "no image case matches --filter 'cs381/*': the 9 case(s) it matches "
            "(cs381/chromatic-aberration/sphere and 8 more) are not image cases"},
           {"bless --filter 'cs381/glass' --golden /tmp",
            "which is listing cs381/glass's id, and none of its cases is an image case"},
           // A glob over several listings' ids names each of them, and the
           // glob that matches their cases.
           {"list --filter 'blog/[fd]*[ln]'",
            "which matches the ids of listings blog/diffraction and blog/fresnel: a case's id "
            "adds its scene; use --filter 'blog/[fd]*[ln]/*' for their cases"},
           {"bless --filter 'blog/[fc]*[lc]' --golden /tmp",
            "which matches the ids of listings blog/chromatic and blog/fresnel, and none of "
            "their cases is an image case"},
           {"list --filter 'blog/*[cln]'",
            "which matches the ids of listings blog/chromatic, blog/diffraction and 1 more"},
           // `*l/*` would also match every learnopengl case (a `*` matches
           // '/'): not offered.
           {"list --filter '*l'",
            "which matches the ids of listings blog/fresnel, methods/fresnel/2-empirical and 2 "
            "more: a case's id adds its scene; use --filter 'ID/*' for each listing's cases"}}) {
    const Outcome o = snell(args);
    EXPECT_EQ(o.code, 2) << args << ": " << o.out;
    EXPECT_NE(o.out.find(expected), std::string::npos) << args << ": " << o.out;
  }
}

// The first word that is no command is named with the commands there are
// (not CLI11's "argument was not expected"); --drivers alone is refused.
TEST(Cli, AnUnknownCommandListsTheCommands) {
  const Outcome o = snell("frobnicate");
  EXPECT_EQ(o.code, 2) << o.out;
  EXPECT_NE(o.out.find("unknown command 'frobnicate'; the commands are run, list, eval"),
            std::string::npos)
      << o.out;
  EXPECT_EQ(o.out.find("worker"), std::string::npos) << "the hidden worker is not offered";
  const Outcome drivers = snell("--drivers");
  EXPECT_EQ(drivers.code, 2) << drivers.out;
  EXPECT_NE(drivers.out.find("--drivers goes with --version"), std::string::npos) << drivers.out;
}

TEST(Cli, ListShowsTheFresnelCases) {
  const Outcome o = snell("list");
  EXPECT_EQ(o.code, 0);
  EXPECT_NE(o.out.find("orange-book/14.1-fresnel/sphere"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("orange-book/14.1-fresnel/sweep"), std::string::npos) << o.out;
}

TEST(Cli, ListCheckRefusesACaseThatRunWouldRefuse) {
  // A capture the oracle does not compute passes the manifest reader; only
  // the checks `run` makes first (and `list --check`) refuse it.
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-cli-check-{}", ::getpid());
  fs::create_directories(dir);
  fs::copy(SNELL_SOURCE_ROOT "/shaders/orange-book/14.1-fresnel", dir / "fresnel",
           fs::copy_options::recursive);
  snell::edited::replaceInFile(dir / "fresnel" / "manifest.toml", "\"Reflect\"",
                               "\"NoSuchOutput\"");
  EXPECT_EQ(snell(fmt::format("list --shaders {}", dir.string())).code, 0);
  const Outcome checked = snell(fmt::format("list --check --shaders {}", dir.string()));
  EXPECT_EQ(checked.code, 2) << checked.out;
  EXPECT_NE(checked.out.find("NoSuchOutput"), std::string::npos) << checked.out;
  fs::remove_all(dir);
}

// A samplerCube bound to the scene's 2D texture passed `list --check` and
// then crashed every case in the driver. It is refused at its line.
TEST(Cli, ASamplerBoundToTheWrongKindOfTextureIsRefusedAtItsLine) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-cli-sampler-{}", ::getpid());
  for (const auto& [binding, message] : std::vector<std::pair<std::string, std::string>>{
           {"\"scene.decal\"",
            "manifest.toml:28: `skybox` is a samplerCube but is bound to scene.decal, the "
            "scene's 2D texture; bind \"scene.environment\""}}) {
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::copy(SNELL_SOURCE_ROOT "/shaders/learnopengl/refraction", dir / "refraction",
             fs::copy_options::recursive);
    snell::edited::replaceInFile(dir / "refraction" / "manifest.toml", "\"scene.environment\"",
                                 binding);
    const Outcome checked = snell(fmt::format("list --check --shaders {}", dir.string()));
    EXPECT_EQ(checked.code, 2) << checked.out;
    EXPECT_NE(checked.out.find(message), std::string::npos) << checked.out;
  }
  fs::remove_all(dir);
}

TEST(Cli, BrokenManifestIsExit2NamingTheFile) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-cli-bad-{}", ::getpid());
  fs::create_directories(dir / "x");
  std::ofstream(dir / "x" / "manifest.toml") << "id = \"x\"\ntitle = 5\n";
  const Outcome o = snell(fmt::format("run --shaders {}", dir.string()));
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.out.find("manifest.toml:2:"), std::string::npos) << o.out;
  fs::remove_all(dir);
}

TEST(Cli, EvalOracleAnswersEveryLineInOrder) {
  const Outcome o = snell("eval --backend oracle",
                          "{\"fn\":\"refract\",\"I\":[0,-1,0],\"N\":[0,1,0],\"eta\":0.66}\n"
                          "{\"fn\":\"reflect\",\"I\":[0.6,-0.8],\"N\":[0,1]}\n");
  EXPECT_EQ(o.code, 0) << o.out;
  const auto lines = jsonLines(o.out);
  ASSERT_EQ(lines.size(), 2u) << o.out;
  // Normal incidence: refract keeps the direction; reflect mirrors the normal component.
  EXPECT_EQ(lines[0]["value"][1].get<double>(), -1.0);
  EXPECT_NEAR(lines[1]["value"][0].get<double>(), 0.6, 1e-7);
  EXPECT_NEAR(lines[1]["value"][1].get<double>(), 0.8, 1e-7);
  EXPECT_LE(lines[1]["lo"][1].get<double>(), lines[1]["value"][1].get<double>());
  EXPECT_GE(lines[1]["hi"][1].get<double>(), lines[1]["value"][1].get<double>());
}

// Near the critical angle refract() may return the zero vector or the
// refracted ray: eval shows both ways, and a vector that takes its x from
// one and y, z from the other lies in the box of lo and hi but in neither way.
TEST(Cli, EvalOracleShowsBothWaysOfRefractNearTheCriticalAngle) {
  const float d = -0.7f;
  const float s = std::sqrt(1.0f - d * d);
  const Outcome o = snell(
      "eval --backend oracle",
      fmt::format("{{\"fn\":\"refract\",\"I\":[{:.9g},{:.9g},0],\"N\":[0,1,0],\"eta\":{:.9g}}}\n",
                  s, d, 1.0f / s));
  EXPECT_EQ(o.code, 0) << o.out;
  const auto lines = jsonLines(o.out);
  ASSERT_EQ(lines.size(), 1u) << o.out;
  const auto& ways = lines[0]["alternatives"];
  ASSERT_EQ(ways.size(), 2u) << o.out;
  const auto isZero = [](const nlohmann::json& way) {
    for (int k = 0; k < 3; ++k)
      if (way["lo"][k].get<double>() != 0.0 || way["hi"][k].get<double>() != 0.0) return false;
    return true;
  };
  ASSERT_NE(isZero(ways[0]), isZero(ways[1])) << o.out;
  const auto& ray = isZero(ways[0]) ? ways[1] : ways[0];
  const std::array<double, 3> mixed = {0.0, ray["value"][1].get<double>(),
                                       ray["value"][2].get<double>()};
  const auto inside = [&](const nlohmann::json& way) {
    for (int k = 0; k < 3; ++k)
      if (mixed[k] < way["lo"][k].get<double>() || mixed[k] > way["hi"][k].get<double>())
        return false;
    return true;
  };
  EXPECT_TRUE(inside(lines[0])) << "the box of the ways holds the mix";
  EXPECT_FALSE(inside(ways[0]));
  EXPECT_FALSE(inside(ways[1]));
}

TEST(Cli, EvalMalformedLineNamesItsNumberAndOthersAreAnswered) {
  const Outcome o = snell("eval",
                          "{\"fn\":\"reflect\",\"I\":[1,0],\"N\":[0,1]}\n"
                          "not json\n"
                          "{\"fn\":\"reflect\",\"I\":[1,0,0],\"N\":[0,1]}\n"
                          "{\"fn\":\"reflect\",\"I\":[1,0],\"N\":[0,1]}\n");
  EXPECT_EQ(o.code, 2);
  const auto lines = jsonLines(o.out);
  ASSERT_EQ(lines.size(), 4u) << o.out;
  EXPECT_TRUE(lines[0].contains("value"));
  EXPECT_NE(lines[1]["error"].get<std::string>().find("line 2"), std::string::npos);
  EXPECT_NE(lines[2]["error"].get<std::string>().find("line 3"), std::string::npos);
  EXPECT_TRUE(lines[3].contains("value"));
}

class EvalOnDriver : public ::testing::TestWithParam<std::string> {};

TEST_P(EvalOnDriver, DriverResultsAreWithinSpec) {
  std::string input;
  for (int k = 0; k < 200; ++k) {
    const double a = k * 0.0078;  // incidence from 0 to about 89.4 degrees
    input += fmt::format("{{\"fn\":\"refract\",\"I\":[{},{},0],\"N\":[0,1,0],\"eta\":{}}}\n",
                         std::sin(a), -std::cos(a), k % 2 ? 0.66 : 1.5);
    input += fmt::format("{{\"fn\":\"reflect\",\"I\":[{},{}],\"N\":[0,1]}}\n", std::sin(a),
                         -std::cos(a));
  }
  const Outcome o = snell("eval --backend " + GetParam(), input);
  EXPECT_EQ(o.code, 0) << o.out.substr(0, 2000);
  const auto lines = jsonLines(o.out);
  ASSERT_EQ(lines.size(), 400u);
  for (const auto& line : lines) {
    ASSERT_TRUE(line.contains("within_spec")) << line.dump();
    EXPECT_TRUE(line["within_spec"].get<bool>()) << line.dump();
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, EvalOnDriver, ::testing::Values("gl", "vk"));

// A compile log that is not UTF-8 (glslang quotes the bytes of a byte order
// mark) made the Vulkan worker's result unwritable as JSON: the case was a
// Crash with an internal error, and its log was lost. It is a CompileError
// with the log whole, the bytes that are not UTF-8 written as U+FFFD.
TEST(Cli, ACompileLogThatIsNotUtf8IsRecordedNotACrash) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("snell-cli-bom-{}", ::getpid());
  const fs::path listing = dir / "shaders" / "bom";
  fs::remove_all(dir);
  fs::create_directories(listing);
  std::ofstream(listing / "s.vert") << R"(#version 330 core
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform vec3 cameraPos;
out vec3 R;
void main()
{
    vec3 P = vec3(model * vec4(aPos, 1.0));
    vec3 N = normalize(mat3(model) * aNormal);
    R = refract(normalize(P - cameraPos), N, 0.66);
    gl_Position = projection * view * vec4(P, 1.0);
}
)";
  // The derived oracle reads the vertex stage only: the fragment stage's
  // byte order mark reaches the drivers' compilers alone.
  std::ofstream(listing / "s.frag", std::ios::binary) << "\xEF\xBB\xBF"
                                                      << R"(#version 330 core
out vec4 FragColor;
in vec3 R;
void main() { FragColor = vec4(R, 1.0); }
)";
  std::ofstream(listing / "manifest.toml") << R"(id = "bom"
title = "a byte order mark"
source = { file = "x", where = "y" }
stages = { vertex = "s.vert", fragment = "s.frag" }
[inputs]
aPos = "scene.position"
aNormal = "scene.normal"
[uniforms]
model = "scene.model"
view = "scene.view"
projection = "scene.projection"
cameraPos = "scene.eye_position"
[capture]
vertex = ["R"]
[[case]]
scene = "torus"
checks = ["vectors"]
)";
  const fs::path json = dir / "results.jsonl";
  const Outcome o =
      snell(fmt::format("run --backend vk -j 1 --filter '*/torus' --shaders {} --out {} --json {}",
                        (dir / "shaders").string(), (dir / "out").string(), json.string()));
  EXPECT_EQ(o.code, 1) << o.out;
  std::ifstream results(json);
  const auto records = jsonLines(std::string((std::istreambuf_iterator<char>(results)), {}));
  ASSERT_EQ(records.size(), 1u) << o.out;
  EXPECT_EQ(records[0]["status"], "CompileError") << records[0].dump();
  EXPECT_EQ(o.out.find("internal error"), std::string::npos) << o.out;
  fs::remove_all(dir);
}

}  // namespace

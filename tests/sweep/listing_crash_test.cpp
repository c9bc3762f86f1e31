// A driver child of the listings' sweep that crashes or hangs on one draw:
// that draw is recorded as such, a new child goes on with the next, and
// the sweep returns.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "sweep/listing_capture.h"

namespace snell::sweep {
namespace {

namespace fs = std::filesystem;

// A stand-in for `snell sweep --listing-worker JOB --listing-start N ...`:
// answers each draw from N on, dying of SIGSEGV on a draw whose manifest
// path says "crash" and stalling on one that says "hang".
fs::path fakeWorker() {
  const fs::path script = fs::temp_directory_path() / fmt::format("snell-lw-{}.sh", ::getpid());
  std::ofstream(script)
      << "#!/bin/sh\n"
         "k=0\n"
         "while IFS= read -r line; do\n"
         "  if [ $k -ge \"$5\" ]; then\n"
         "    case \"$line\" in *crash*) kill -SEGV $$;; *hang*) sleep 30;; esac\n"
         "    echo \"{\\\"draw\\\":$k,\\\"compiled\\\":true,\\\"varyings\\\":[]}\"\n"
         "  fi\n"
         "  k=$((k+1))\n"
         "done < \"$3\"\n";
  ::chmod(script.c_str(), 0755);
  return script;
}

fs::path job(const std::vector<std::string>& paths) {
  const fs::path file = fs::temp_directory_path() / fmt::format("snell-lw-job-{}.txt", ::getpid());
  std::ofstream out(file);
  for (const std::string& p : paths) out << drawLine({p, "unit", 0, true}) << '\n';
  return file;
}

TEST(ListingCrash, ACrashCostsOnlyItsDraw) {
  const fs::path script = fakeWorker();
  const fs::path file = job({"/a/manifest.toml", "/crash/manifest.toml", "/b/manifest.toml"});
  const std::vector<DrawCapture> got = captureDraws(script.string(), "gl", {}, file, 3, 30);
  fs::remove(script);
  fs::remove(file);
  ASSERT_EQ(got.size(), 3u);
  EXPECT_TRUE(got[0].answered);
  EXPECT_FALSE(got[1].answered);
  EXPECT_NE(got[1].problem.find("signal 11"), std::string::npos) << got[1].problem;
  EXPECT_TRUE(got[2].answered);
}

TEST(ListingCrash, AHangIsCutOffAndTheSweepGoesOn) {
  const fs::path script = fakeWorker();
  const fs::path file = job({"/hang/manifest.toml", "/b/manifest.toml"});
  const std::vector<DrawCapture> got = captureDraws(script.string(), "gl", {}, file, 2, 1);
  fs::remove(script);
  fs::remove(file);
  ASSERT_EQ(got.size(), 2u);
  EXPECT_FALSE(got[0].answered);
  EXPECT_NE(got[0].problem.find("hang"), std::string::npos) << got[0].problem;
  EXPECT_TRUE(got[1].answered);
}

}  // namespace
}  // namespace snell::sweep

#include "golden/golden_store.h"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include "compare/image_io.h"
#include "core/atomic_file.h"
#include "core/errors.h"

namespace snell {

namespace fs = std::filesystem;

GoldenFiles goldenFiles(const fs::path& root, const std::string& caseId,
                        const std::string& backend) {
  const fs::path dir = root / caseId;
  return {dir / (backend + ".exr"), dir / (backend + ".png"), dir / (backend + ".json")};
}

namespace {

// KEY.exr, KEY.png or KEY.json: one of the three files of a golden of `key`.
bool isGoldenFileName(const fs::path& file, const std::string& key) {
  const std::string extension = file.extension().string();
  return file.stem() == key && (extension == ".exr" || extension == ".png" || extension == ".json");
}

}  // namespace

bool hasAnyGolden(const fs::path& root, const std::string& backend, const fs::path& skip) {
  std::error_code error;
  for (fs::recursive_directory_iterator it(root, error), end; !error && it != end;
       it.increment(error)) {
    std::error_code notSame;
    if (!skip.empty() && it->is_directory(notSame) && fs::equivalent(it->path(), skip, notSame)) {
      it.disable_recursion_pending();
      continue;
    }
    // Any of a golden's three files counts: a golden with its image lost is
    // a damaged golden to report, not a driver that has none yet.
    if (isGoldenFileName(it->path(), backend)) return true;
  }
  return false;
}

bool isGoldenFile(const fs::path& root, const fs::path& path,
                  const std::vector<std::string>& goldenKeys) {
  std::error_code error;
  const fs::path file = fs::weakly_canonical(path, error);
  if (error) return false;
  const fs::path folder = fs::weakly_canonical(root, error);
  if (error) return false;
  // ROOT/CASE/KEY.ext: below the root by a case folder at least.
  const fs::path inside = file.lexically_relative(folder);
  if (inside.empty() || *inside.begin() == ".." || !inside.has_parent_path()) return false;
  return std::any_of(goldenKeys.begin(), goldenKeys.end(),
                     [&](const std::string& key) { return isGoldenFileName(file, key); });
}

Golden readGolden(const fs::path& root, const std::string& caseId, const std::string& backend,
                  int expectedWidth, int expectedHeight, const std::string& blessCommand,
                  const std::function<Image(const fs::path&)>& read) {
  const GoldenFiles files = goldenFiles(root, caseId, backend);
  // Without a command (bless itself reads the golden it replaces) no advice.
  const std::string hint =
      blessCommand.empty() ? ""
                           : fmt::format("; check it, or bless a new one with `{}`", blessCommand);
  Golden golden;
  try {
    golden.image = read(files.image);
  } catch (const UsageError& error) {
    throw UsageError(fmt::format("golden {}{}", error.what(), hint));
  }
  if (golden.image.width != expectedWidth || golden.image.height != expectedHeight)
    throw UsageError(fmt::format("golden {}: is {}x{}, the scene renders {}x{}{}",
                                 files.image.string(), golden.image.width, golden.image.height,
                                 expectedWidth, expectedHeight, hint));
  std::ifstream in(files.metadata);
  if (!in) throw UsageError(fmt::format("golden {}: missing{}", files.metadata.string(), hint));
  try {
    golden.metadata = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& error) {
    throw UsageError(fmt::format("golden {}: not valid JSON ({}){}", files.metadata.string(),
                                 readableError(error), hint));
  }
  if (!golden.metadata.is_object())
    throw UsageError(fmt::format("golden {}: not a golden's metadata (a JSON object){}",
                                 files.metadata.string(), hint));
  return golden;
}

void writeGolden(const fs::path& root, const std::string& caseId, const std::string& backend,
                 const Image& image, const nlohmann::json& metadata) {
  const GoldenFiles files = goldenFiles(root, caseId, backend);
  fs::create_directories(files.image.parent_path());
  writeImageAtomically(files.image, image);
  writeImageAtomically(files.preview, image);
  writeFileAtomically(
      files.metadata,
      metadata.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

std::string cpuFeatures() {
  // The flags that change llvmpipe's vector width and instruction choice.
  static const std::set<std::string> kRelevant = {"sse4_1", "sse4_2", "avx",     "avx2",
                                                  "fma",    "f16c",   "avx512f", "avx512bw"};
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("flags", 0) != 0) continue;
    std::istringstream words(line.substr(line.find(':') + 1));
    std::string out;
    for (std::string flag; words >> flag;)
      if (kRelevant.count(flag)) out += (out.empty() ? "" : " ") + flag;
    return out;
  }
  return "unknown";
}

}  // namespace snell

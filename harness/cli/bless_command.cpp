// `snell bless`: renders the image cases and writes their goldens, only when
// asked, only for the cases it ran, and only for images that are correct
// (within the tolerance of the CPU reference): a wrong image is never blessed.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <string.h>

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "backends/backend_registry.h"
#include "cli/commands.h"
#include "cli/output_paths.h"
#include "cli/results_output.h"
#include "cli/suite_session.h"
#include "compare/image_compare.h"
#include "compare/image_io.h"
#include "core/atomic_file.h"
#include "core/errors.h"
#include "golden/golden_store.h"
#include "runner/image_check.h"
#include "runner/interrupt_flag.h"
#include "runner/json_fields.h"

namespace snell::cli {
namespace {

namespace fs = std::filesystem;

nlohmann::json metadataOf(const CaseResult& r, const Case& c, const Image& image) {
  return {{"case", r.caseId},
          {"backend", r.backend},
          {"api", r.driver.api},
          {"api_version", r.driver.apiVersion},
          {"renderer", r.driver.renderer},
          {"driver_version", r.driver.driverVersion},
          {"device_type", r.driver.deviceType},
          {"cpu_features", cpuFeatures()},
          {"width", image.width},
          {"height", image.height},
          {"tolerance",
           {{"fail", c.spec.image.fail},
            {"warn", c.spec.image.warn},
            {"failpercent", c.spec.image.failPercent},
            {"hardfail", c.spec.image.hardFail}}}};
}

// What blessing changes, against the golden it replaces.
struct GoldenChange {
  std::string description;
  bool samePixels = false;  // the golden's image is this one, pixel for pixel
  // The metadata fields whose values differ from the golden's (with a field
  // added or dropped), when the pixels are the same.
  std::vector<std::string> changedFields;
};

std::vector<std::string> changedFieldsOf(const nlohmann::json& old, const nlohmann::json& now) {
  std::set<std::string> keys;
  for (const auto& [key, value] : old.items()) keys.insert(key);
  for (const auto& [key, value] : now.items()) keys.insert(key);
  std::vector<std::string> changed;
  for (const std::string& key : keys)
    if (!old.contains(key) || !now.contains(key) || old[key] != now[key]) changed.push_back(key);
  return changed;
}

GoldenChange changeOf(const fs::path& goldenDir, const Case& c, const std::string& backend,
                      const Image& image, const nlohmann::json& metadata) {
  const GoldenFiles files = goldenFiles(goldenDir, c.id, backend);
  std::error_code error;
  if (!fs::exists(files.image, error) && !fs::exists(files.metadata, error) &&
      !fs::exists(files.preview, error))
    return {"new", false, {}};
  try {
    const Golden old = readGolden(goldenDir, c.id, backend, image.width, image.height, "");
    const ImageComparison change = compareImages("golden", image, old.image, {}, c.spec.image);
    if (change.maxError == 0)
      return {"unchanged, files left as they were", true, changedFieldsOf(old.metadata, metadata)};
    return {fmt::format("changed: max error {:.6g} at ({}, {}), {} pixels over {}, {} over {}",
                        change.maxError, change.maxX, change.maxY, change.failed, c.spec.image.fail,
                        change.warned, c.spec.image.warn),
            false,
            {}};
  } catch (const UsageError& damaged) {
    // A golden that cannot be read is replaced, and said to be: its files
    // are there, so it is not new.
    return {fmt::format("replaced a golden that could not be read: {}", damaged.what()), false, {}};
  }
}

// Whether the golden's preview is a readable image of the golden's size: a
// damaged one is written again beside a golden whose pixels are kept.
bool previewIsWhole(const fs::path& preview, const Image& image) {
  if (!fs::is_regular_file(preview)) return false;
  try {
    const Image read = readImage(preview);
    return read.width == image.width && read.height == image.height;
  } catch (const UsageError&) {
    return false;
  }
}

int bless(const SuiteOptions& options) {
  if (!fs::is_directory(options.golden))
    throw UsageError(
        fmt::format("{}: {}; create it or pass --golden DIR", options.golden,
                    fs::exists(options.golden) ? "not a folder" : "no such golden folder"));
  std::vector<OutputPath> files;
  if (!options.json.empty()) files = resultsFileOutputs("--json", options.json);
  checkOutputs(files, {{"--out", options.out}}, {{"--golden", options.golden}});
  checkNotGoldenFiles(files, {"--golden", options.golden});
  const SuiteRun suite = runSuite(options, true, false);
  // A bless cut short blesses nothing: a partial set of new goldens beside
  // old ones, with exit 0, would be committed as if it were whole.
  if (suite.interruptedBy) {
    fmt::print(
        "\nsnell: interrupted by {} before every image case was rendered: nothing "
        "blessed, the goldens are as they were\n",
        signalName(suite.interruptedBy));
    return 130;
  }
  // A signal while goldens are written stops after the case being written,
  // whose files are written together, and says what was and was not.
  const InterruptFlag interrupt;
  std::size_t handled = 0;
  std::map<std::string, const Case*> cases;
  for (const Case& c : suite.cases) cases[c.id] = &c;
  int refused = 0;
  std::set<std::pair<std::string, std::string>> written;  // (case, golden key)
  for (const CaseResult& r : suite.results) {
    if (interrupt.signal()) {
      fmt::print(
          "\nsnell: interrupted by {} while goldens were written: {} of {} results "
          "handled above, the others' goldens are as they were\n",
          signalName(interrupt.signal()), handled, suite.results.size());
      return 130;
    }
    ++handled;
    const Case& c = *cases.at(r.caseId);
    const std::string key = backendRegistry().find(r.backend).goldenKey;
    if (written.count({r.caseId, key})) {
      fmt::print(
          "{} {}: not blessed, its golden `{}` was written by another backend on the same "
          "driver in this run\n",
          r.backend, r.caseId, key);
      continue;
    }
    if (r.status != Status::Pass) {
      ++refused;
      fmt::print("{} {}: not blessed, {}:\n{}", r.backend, r.caseId, statusName(r.status),
                 asLines(r.message));
      continue;
    }
    const Image image = readImage(renderedImagePath(options.out, r.caseId, r.backend));
    const nlohmann::json metadata = metadataOf(r, c, image);
    const GoldenChange change = changeOf(options.golden, c, key, image, metadata);
    // The same pixels are not written again: an image file encoded anew
    // differs in its bytes (a date in the EXR header, PNG compression), and
    // each bless would be a binary change to review in version control.
    const GoldenFiles files = goldenFiles(options.golden, r.caseId, key);
    std::string description = change.description;
    if (!change.samePixels) {
      writeGolden(options.golden, r.caseId, key, image, metadata);
    } else {
      // The image kept; what is missing or stale beside it is written.
      std::vector<std::string> rewritten;
      if (!fs::is_regular_file(files.preview)) {
        writeImageAtomically(files.preview, image);
        rewritten.push_back("the lost preview written again");
      } else if (!previewIsWhole(files.preview, image)) {
        writeImageAtomically(files.preview, image);
        rewritten.push_back("the damaged preview written again");
      }
      if (!change.changedFields.empty()) {
        writeFileAtomically(files.metadata, jsonText(metadata, 2) + "\n");
        rewritten.push_back(
            fmt::format("metadata rewritten ({} changed)", fmt::join(change.changedFields, ", ")));
      }
      if (!rewritten.empty())
        description = fmt::format("unchanged pixels, {}", fmt::join(rewritten, "; "));
    }
    written.insert({r.caseId, key});
    fmt::print("{} {}: blessed ({})\n", r.backend, r.caseId, description);
  }
  return refused ? 1 : 0;
}

}  // namespace

Command addBlessCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "bless", "Render the image cases and write their goldens (only correct images are blessed)");
  auto options = std::make_shared<SuiteOptions>();
  addSuiteOptions(*sub, *options);
  return [options] { return bless(*options); };
}

}  // namespace snell::cli

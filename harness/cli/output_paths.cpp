#include "cli/output_paths.h"

#include <fmt/format.h>
#include <unistd.h>

#include "core/errors.h"

namespace snell::cli {
namespace {

namespace fs = std::filesystem;

// The same file for two paths, whether or not it exists yet.
fs::path identity(const fs::path& path) {
  std::error_code error;
  const fs::path canonical = fs::weakly_canonical(fs::absolute(path), error);
  return error ? fs::absolute(path).lexically_normal() : canonical;
}

void checkFile(const OutputPath& file) {
  if (fs::is_directory(file.path))
    throw UsageError(
        fmt::format("{} {}: is a folder; name a file to write", file.option, file.path.string()));
  const fs::path folder = fs::absolute(file.path).parent_path();
  if (!fs::is_directory(folder))
    throw UsageError(
        fmt::format("{} {}: folder {} does not exist; create it or name a file in "
                    "an existing folder",
                    file.option, file.path.string(), folder.string()));
  if (access(folder.c_str(), W_OK | X_OK) != 0)
    throw UsageError(
        fmt::format("{} {}: folder {} is not writable; name a file in a writable "
                    "folder",
                    file.option, file.path.string(), folder.string()));
}

void checkFolder(const OutputPath& folder) {
  // A folder that does not exist yet is made by the command, with its parents.
  fs::path existing = fs::absolute(folder.path);
  while (!existing.empty() && !fs::exists(existing) && existing != existing.root_path())
    existing = existing.parent_path();
  if (!fs::is_directory(existing))
    throw UsageError(fmt::format("{} {}: {} is a file, not a folder; name a folder", folder.option,
                                 folder.path.string(), existing.string()));
}

}  // namespace

std::vector<OutputPath> resultsFileOutputs(const std::string& option, const fs::path& file) {
  fs::path partial = file;
  partial += ".partial";
  fs::path timing = file;
  timing.replace_extension(".timing.json");
  fs::path csv = file;
  csv.replace_extension(".csv");
  return {{option, file},
          {option + " (its .partial file)", partial},
          {option + " (its results.csv)", csv},
          {option + " (its .timing.json)", timing}};
}

void checkOutputs(const std::vector<OutputPath>& files, const std::vector<OutputPath>& folders,
                  const std::vector<OutputPath>& inputs) {
  for (const OutputPath& file : files) checkFile(file);
  for (const OutputPath& folder : folders) checkFolder(folder);
  for (std::size_t i = 0; i < files.size(); ++i) {
    const fs::path id = identity(files[i].path);
    for (std::size_t j = i + 1; j < files.size(); ++j)
      if (identity(files[j].path) == id)
        throw UsageError(
            fmt::format("{} and {} both name {}: one would overwrite the other; "
                        "name two files",
                        files[i].option, files[j].option, files[i].path.string()));
    for (const OutputPath& input : inputs)
      if (identity(input.path) == id)
        throw UsageError(
            fmt::format("{} {} is also {}: writing it would destroy that input; "
                        "name another file",
                        files[i].option, files[i].path.string(), input.option));
  }
}

}  // namespace snell::cli

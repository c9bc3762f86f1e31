#pragma once
// The files and folders a command will write, checked before it does any
// work: a run of minutes must not end in "cannot rename: Is a directory",
// and one output must not land on another or on an input.
#include <filesystem>
#include <string>
#include <vector>

namespace snell::cli {

// A path a command writes, and the option that names it (for the message).
struct OutputPath {
  std::string option;
  std::filesystem::path path;
};

// The files `run --json FILE` writes: FILE, and beside it FILE.partial,
// results.csv (FILE's extension replaced) and FILE.timing.json (`merge`
// writes FILE and results.csv; the other two are checked for it as well,
// which refuses nothing it could write).
std::vector<OutputPath> resultsFileOutputs(const std::string& option,
                                           const std::filesystem::path& file);

// Throws UsageError (exit 2) naming the option when:
// - a file is a folder, or its folder does not exist or is not writable;
// - a folder exists as something other than a folder;
// - two outputs, a file and a folder, or an output and an input, are the
//   same path (an input may be a folder: run's --golden).
void checkOutputs(const std::vector<OutputPath>& files, const std::vector<OutputPath>& folders = {},
                  const std::vector<OutputPath>& inputs = {});

// Throws UsageError when one file is given as two inputs (merge's results
// files: an empty one would count as two shards, and a non-empty one would
// be said to overlap itself).
void checkInputsOnce(const std::vector<OutputPath>& inputs);

// Throws UsageError when an output file is, or would be, one of a golden's
// files under `golden` (run's or bless's --golden): a results file named
// there would replace a blessed image or its metadata, or be replaced by
// one that bless writes.
void checkNotGoldenFiles(const std::vector<OutputPath>& files, const OutputPath& golden);

// Whether `path` is `place` or lies inside it, whether or not either
// exists yet (links followed where they exist).
bool isAtOrWithin(const std::filesystem::path& path, const std::filesystem::path& place);

// The outermost folder of `path` that does not exist yet, or empty when all
// of it does: what a command that makes `path` and then fails removes, so
// that it leaves nothing behind that it made.
std::filesystem::path firstMissingFolder(const std::filesystem::path& path);

}  // namespace snell::cli

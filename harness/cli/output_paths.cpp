#include "cli/output_paths.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "backends/backend_registry.h"
#include "core/atomic_file.h"
#include "core/errors.h"
#include "golden/golden_store.h"

namespace snell::cli {
namespace {

namespace fs = std::filesystem;

// The same file for two paths, whether or not it exists yet.
fs::path identity(const fs::path& path) {
  std::error_code error;
  const fs::path canonical = fs::weakly_canonical(fs::absolute(path), error);
  return error ? fs::absolute(path).lexically_normal() : canonical;
}

// The file's type, following links; a path the system cannot look up (too
// long, a loop of links, a folder that cannot be searched) is the user's
// to fix, named with its option, not an internal error.
fs::file_type typeOf(const OutputPath& output, const fs::path& path) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (error && error != std::errc::no_such_file_or_directory && error != std::errc::not_a_directory)
    throw UsageError(fmt::format("{} {}: {} ({}); name another path", output.option,
                                 output.path.string(), error.message(), path.string()));
  return status.type();
}

const char* notAFileKind(fs::file_type type) {
  switch (type) {
    case fs::file_type::character:
      return "a character device";
    case fs::file_type::block:
      return "a block device";
    case fs::file_type::fifo:
      return "a named pipe";
    case fs::file_type::socket:
      return "a socket";
    default:
      return "not a plain file";
  }
}

void checkFile(const OutputPath& file) {
  if (typeOf(file, file.path) == fs::file_type::directory)
    throw UsageError(
        fmt::format("{} {}: is a folder; name a file to write", file.option, file.path.string()));
  // A file is written beside its path and renamed onto it (a reader never
  // sees half of one): that would replace a link itself, not what it
  // leads to, and a device or a pipe (/dev/null, as root) with a plain file.
  std::error_code kindError;
  const fs::file_status own = fs::symlink_status(file.path, kindError);
  if (!kindError && fs::is_symlink(own)) {
    const fs::path target = fs::read_symlink(file.path, kindError);
    throw UsageError(fmt::format(
        "{} {}: is a link{}; name the file itself (snell writes a new file and renames it into "
        "place, which would replace the link)",
        file.option, file.path.string(), kindError ? "" : fmt::format(" to {}", target.string())));
  }
  if (!kindError && fs::exists(own) && !fs::is_regular_file(own))
    throw UsageError(fmt::format(
        "{} {}: is {}, not a file; name a file (snell writes a new file and renames it into "
        "place), or leave the option out",
        file.option, file.path.string(), notAFileKind(own.type())));
  const fs::path folder = fs::absolute(file.path).parent_path();
  const fs::file_type folderType = typeOf(file, folder);
  if (folderType == fs::file_type::not_found)
    throw UsageError(
        fmt::format("{} {}: folder {} does not exist; create it or name a file in "
                    "an existing folder",
                    file.option, file.path.string(), folder.string()));
  if (folderType != fs::file_type::directory)
    throw UsageError(fmt::format("{} {}: {} is a file, not a folder; name a file in a folder",
                                 file.option, file.path.string(), folder.string()));
  if (access(folder.c_str(), W_OK | X_OK) != 0)
    throw UsageError(
        fmt::format("{} {}: folder {} is not writable; name a file in a writable "
                    "folder",
                    file.option, file.path.string(), folder.string()));
  // To root, access() says yes where no file can be made (/proc, a
  // read-only mount): one is made there and removed, as the file itself
  // will be written: beside it, under the temporary name
  // writeFileAtomically gives it, then renamed. A name a few characters
  // short of the file system's limit fits, and its temporary one does not.
  const fs::path probe = folder / temporaryPathFor(file.path).filename();
  const int fd = open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  const int error = fd < 0 ? errno : 0;
  if (fd < 0 && error == ENAMETOOLONG)
    throw UsageError(fmt::format(
        "{} {}: too long a name: snell writes the file first as {} beside it, which is too "
        "long for the file system; name a shorter file",
        file.option, file.path.string(), probe.filename().string()));
  if (fd < 0 && error != EEXIST)
    throw UsageError(
        fmt::format("{} {}: no file can be made in folder {} ({}); name a file in a "
                    "writable folder",
                    file.option, file.path.string(), folder.string(), std::strerror(error)));
  if (fd >= 0) {
    close(fd);
    unlink(probe.c_str());
  }
}

// A folder path split where it stops existing: its nearest part that
// exists (a link counts, even one that leads nowhere) and the outermost
// part that does not (empty when all of it exists). A part the system
// cannot look up (too long, a loop of links) stops the walk with its error.
struct FolderParts {
  fs::path existing;
  fs::path firstMissing;
  std::error_code error;
};

FolderParts folderParts(const fs::path& path) {
  FolderParts parts;
  for (fs::path p = fs::absolute(path).lexically_normal();; p = p.parent_path()) {
    std::error_code error;
    const bool present = fs::exists(fs::symlink_status(p, error));
    if (error && error != std::errc::no_such_file_or_directory &&
        error != std::errc::not_a_directory) {
      parts.existing = p;
      parts.error = error;
      break;
    }
    if (present || p == p.root_path() || !p.has_parent_path()) {
      parts.existing = p;
      break;
    }
    parts.firstMissing = p;
  }
  return parts;
}

void checkFolder(const OutputPath& folder) {
  // A folder that does not exist yet is made by the command, with its
  // parents: the nearest part of the path that exists must be a folder.
  const FolderParts parts = folderParts(folder.path);
  const fs::path& existing = parts.existing;
  // Named here, not found by the command after its work.
  if (parts.error)
    throw UsageError(fmt::format("{} {}: {} ({}); name another path", folder.option,
                                 folder.path.string(), parts.error.message(), existing.string()));
  if (typeOf(folder, existing) != fs::file_type::directory)
    throw UsageError(fmt::format(
        "{} {}: {} is {}, not a folder; name a folder", folder.option, folder.path.string(),
        existing.string(), fs::is_symlink(existing) ? "a link to nothing or to a file" : "a file"));
  // A read-only folder (or file system) is said before any case runs: its
  // first write would come from a worker, as that case's crash.
  if (access(existing.c_str(), W_OK | X_OK) != 0)
    throw UsageError(fmt::format("{} {}: folder {} is not writable ({}); name a writable folder",
                                 folder.option, folder.path.string(), existing.string(),
                                 std::strerror(errno)));
  // Some folders take no new entries whatever their mode says (/proc, /sys):
  // the first missing part is made and removed again, so the command that
  // makes it after its work cannot fail then.
  if (!parts.firstMissing.empty()) {
    if (::mkdir(parts.firstMissing.c_str(), 0777) == 0) {
      ::rmdir(parts.firstMissing.c_str());
    } else if (errno != EEXIST) {  // EEXIST: another process made it meanwhile; theirs to keep
      throw UsageError(fmt::format("{} {}: cannot make folder {} ({}); name another folder",
                                   folder.option, folder.path.string(), parts.firstMissing.string(),
                                   std::strerror(errno)));
    }
  }
}

// The same for a folder named with or without a trailing slash.
fs::path folderIdentity(const fs::path& path) {
  const fs::path id = identity(path);
  return id.has_filename() ? id : id.parent_path();
}

std::string named(const OutputPath& output, const fs::path& id) {
  return output.path == id ? output.path.string()
                           : fmt::format("{} (that is {})", output.path.string(), id.string());
}

}  // namespace

fs::path firstMissingFolder(const fs::path& path) { return folderParts(path).firstMissing; }

std::vector<OutputPath> resultsFileOutputs(const std::string& option, const fs::path& file) {
  fs::path partial = file;
  partial += kPartialSuffix;
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
  // An output folder that is an input one (run --out the --golden folder)
  // would have its images written over what they are compared with.
  for (const OutputPath& folder : folders) {
    const fs::path id = folderIdentity(folder.path);
    for (const OutputPath& input : inputs)
      if (folderIdentity(input.path) == id)
        throw UsageError(fmt::format(
            "{} {} is also {}: the command would write its images over the ones it reads "
            "there; name another folder",
            folder.option, named(folder, id), input.option));
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    const fs::path id = identity(files[i].path);
    for (std::size_t j = i + 1; j < files.size(); ++j)
      if (identity(files[j].path) == id)
        throw UsageError(fmt::format(
            "{} {} and {} {} are one file: one would overwrite the other; name two files",
            files[i].option, named(files[i], id), files[j].option, named(files[j], id)));
    for (const OutputPath& folder : folders)
      if (identity(folder.path) == id)
        throw UsageError(
            fmt::format("{} {} and {} {} are one path: a file and a folder cannot "
                        "both be written there; name two paths",
                        files[i].option, named(files[i], id), folder.option, named(folder, id)));
    for (const OutputPath& input : inputs)
      if (identity(input.path) == id)
        throw UsageError(
            fmt::format("{} {} is also {}: writing it would destroy that input; "
                        "name another file",
                        files[i].option, named(files[i], id), input.option));
  }
}

void checkInputsOnce(const std::vector<OutputPath>& inputs) {
  for (std::size_t i = 0; i < inputs.size(); ++i)
    for (std::size_t j = i + 1; j < inputs.size(); ++j)
      if (identity(inputs[i].path) == identity(inputs[j].path))
        throw UsageError(fmt::format("{} and {} are one file, given twice; give each file once",
                                     inputs[i].path.string(), inputs[j].path.string()));
}

void checkNotGoldenFiles(const std::vector<OutputPath>& files, const OutputPath& golden) {
  std::vector<std::string> keys;
  for (const BackendEntry& entry : backendRegistry().entries()) keys.push_back(entry.goldenKey);
  for (const OutputPath& file : files)
    if (isGoldenFile(golden.path, file.path, keys))
      throw UsageError(fmt::format(
          "{} {} is a golden's file under {} {} (a case folder, and a backend's golden key): "
          "writing it would replace the golden, or bless would write over it; name a file "
          "outside the golden folder's case folders",
          file.option, file.path.string(), golden.option, golden.path.string()));
}

bool isAtOrWithin(const fs::path& path, const fs::path& place) {
  const fs::path relative = identity(path).lexically_relative(identity(place));
  return !relative.empty() && *relative.begin() != "..";
}

}  // namespace snell::cli

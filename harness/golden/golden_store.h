#pragma once
// Blessed images by case id and backend: golden/<case id>/<backend>.exr
// (compared), .png (for people) and .json (the driver that produced it and
// the tolerance in force). Goldens change only through `snell bless`.
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "compare/image_io.h"
#include "core/image.h"

namespace snell {

struct GoldenFiles {
  std::filesystem::path image, preview, metadata;
};

GoldenFiles goldenFiles(const std::filesystem::path& root, const std::string& caseId,
                        const std::string& backend);

struct Golden {
  Image image;
  nlohmann::json metadata;
};

// Whether any case has a golden under `backend` (a backend's golden key): a
// driver with none yet starts from "no golden yet", not from failures.
// `skip` (a run's --out, which may lie inside the golden folder) is not
// searched: the renders there are named as goldens are.
bool hasAnyGolden(const std::filesystem::path& root, const std::string& backend,
                  const std::filesystem::path& skip = {});

// Whether `path` is one of a golden's files under `root`: ROOT/CASE/KEY.exr,
// .png or .json where KEY.exr and KEY.json are there (a golden that has
// been blessed, whatever its case and backend: a results file's
// FILE.timing.json has no FILE.timing.exr beside it). Another command's output written
// there would replace it, though goldens change only through `snell bless`.
bool isGoldenFile(const std::filesystem::path& root, const std::filesystem::path& path);

// Throws UsageError naming the file, what is wrong (missing, unreadable,
// truncated, wrong size, metadata that is not a JSON object) and what to
// do: check it, or run `blessCommand` (the caller's, since only it knows the
// flags the user ran with; empty: no advice). The
// image file is read by `read` (readImage, or one that keeps its pixels).
Golden readGolden(const std::filesystem::path& root, const std::string& caseId,
                  const std::string& backend, int expectedWidth, int expectedHeight,
                  const std::string& blessCommand,
                  const std::function<Image(const std::filesystem::path&)>& read = readImage);

// Writes the three files, each atomically (temporary file, then rename).
void writeGolden(const std::filesystem::path& root, const std::string& caseId,
                 const std::string& backend, const Image& image, const nlohmann::json& metadata);

// The CPU features llvmpipe and lavapipe choose their code paths by.
std::string cpuFeatures();

}  // namespace snell

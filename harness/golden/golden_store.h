#pragma once
// Blessed images by case id and backend: golden/<case id>/<backend>.exr
// (compared), .png (for people) and .json (the driver that produced it and
// the tolerance in force). Goldens change only through `snell bless`.
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

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

// Whether `path` is, or would be, one of a golden's files under `root`:
// ROOT/CASE/KEY.exr, .png or .json, KEY one of `goldenKeys` (whether or
// not the golden is there yet: bless writes it after the run). Another
// command's output written there would replace a golden, or be replaced by
// one, though goldens change only through `snell bless`. A results file's
// FILE.timing.json, or any file in the root itself, is not one.
bool isGoldenFile(const std::filesystem::path& root, const std::filesystem::path& path,
                  const std::vector<std::string>& goldenKeys);

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

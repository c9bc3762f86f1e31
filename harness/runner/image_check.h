#pragma once
// The pixel half of a case: render on the backend, then hold the image
// against the CPU reference (correct?) and the golden (changed?). The third
// comparison, against the other API, needs both backends' images and is
// made by the supervisor (cross_api_check.h).
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "compare/image_compare.h"
#include "core/case.h"
#include "oracle/reference/reference_image.h"
#include "runner/oracle_store/oracle_store.h"
#include "runner/reference_cache.h"

namespace snell {

struct ImageCheckOptions {
  std::filesystem::path outDir;     // where images, heat maps and masks are written
  std::filesystem::path goldenDir;  // empty: no golden comparison (bless runs)
  std::string goldenKey =
      "";  // NOLINT(readability-redundant-string-init): the backend's golden key; empty: its name
  // The user's own `--shaders`/`--golden` flags, repeated in the bless
  // command a missing or broken golden's message advises.
  std::string blessFlags = "";  // NOLINT(readability-redundant-string-init)
  // Where decoded goldens and comparisons are kept across runs; empty: nowhere.
  std::optional<OracleStore> store = std::nullopt;
};

// `snell bless` for one case on one backend, with the user's flags.
std::string blessCommand(const std::string& backend, const std::string& blessFlags,
                         const std::string& caseId);

struct ImageCheck {
  bool compiled = true;
  std::string compileLog;
  std::vector<ImageComparison> comparisons;  // reference, then golden
  std::string goldenProblem;                 // a missing or unreadable golden
  std::string goldenNote;                    // no golden yet for this driver: not a failure
  // A golden the image is off: which file, and the command that blesses
  // the image if the change is intended.
  std::string goldenAdvice;
};

// The samplerCube uniforms a manifest binds to the scene's environment.
std::map<std::string, const CubeMap*> environmentBindings(const Manifest& m, const Scene& scene);

// The sampler2D uniforms a manifest binds to the scene's decal.
std::map<std::string, const Image*> decalBindings(const Manifest& m, const Scene& scene);

// Where a backend's rendered image of a case is written.
std::filesystem::path renderedImagePath(const std::filesystem::path& outDir,
                                        const std::string& caseId, const std::string& backend);

// Where the heat map of a backend's image of a case against `against`
// ("reference" or "golden") is written.
std::filesystem::path heatMapPath(const std::filesystem::path& outDir, const std::string& caseId,
                                  const std::string& backend, const std::string& against);

// The reference's mask travels between processes as an EXR (mask value in red).
std::filesystem::path maskImagePath(const std::filesystem::path& outDir, const std::string& caseId);
// The CPU reference image of a case, beside its rendered images.
std::filesystem::path referenceImagePath(const std::filesystem::path& outDir,
                                         const std::string& caseId);
Image maskAsImage(const ReferenceImage& reference);
std::vector<PixelMask> maskFromImage(const Image& image);

// The render of a case's scene: its program as published, the bound values,
// the scene's triangles, environment, decal and image size.
RenderJob sceneRenderJob(const Manifest& m, const Scene& scene, const ResolvedBindings& bindings);

// The reference and its mask, in float for the report's heat maps and as
// PNG for people: reference.exr, reference.png, mask.exr, mask.png.
void writeReferenceImages(const std::filesystem::path& outDir, const std::string& caseId,
                          const ReferenceImage& reference);

// `referenceWritten`: the reference cache wrote the reference's files for
// this run already (one worker does, for all backends), so this check does not.
ImageCheck checkImage(Backend& backend, const Case& c, const Scene& scene,
                      const ResolvedBindings& bindings, const ReferenceImage& reference,
                      const ImageCheckOptions& options, bool referenceWritten);

}  // namespace snell

#include "runner/image_check.h"

#include <fmt/format.h>

#include "compare/image_io.h"
#include "core/errors.h"
#include "core/phase_clock.h"
#include "golden/golden_store.h"
#include "runner/oracle_store/image_results.h"

namespace snell {

namespace fs = std::filesystem;

std::map<std::string, const CubeMap*> environmentBindings(const Manifest& m, const Scene& scene) {
  std::map<std::string, const CubeMap*> out;
  for (const Binding& b : m.uniforms)
    if (const auto* semantic = std::get_if<std::string>(&b.source);
        semantic && *semantic == "environment" && scene.environment)
      out[b.name] = scene.environment.get();
  return out;
}

std::map<std::string, const Image*> decalBindings(const Manifest& m, const Scene& scene) {
  std::map<std::string, const Image*> out;
  for (const Binding& b : m.uniforms)
    if (const auto* semantic = std::get_if<std::string>(&b.source);
        semantic && *semantic == "decal" && scene.decal)
      out[b.name] = scene.decal.get();
  return out;
}

fs::path renderedImagePath(const fs::path& outDir, const std::string& caseId,
                           const std::string& backend) {
  return outDir / caseId / (backend + ".exr");
}

fs::path heatMapPath(const fs::path& outDir, const std::string& caseId, const std::string& backend,
                     const std::string& against) {
  return outDir / caseId / (backend + "-vs-" + against + ".png");
}

fs::path maskImagePath(const fs::path& outDir, const std::string& caseId) {
  return outDir / caseId / "mask.exr";
}

fs::path referenceImagePath(const fs::path& outDir, const std::string& caseId) {
  return outDir / caseId / "reference.exr";
}

Image maskAsImage(const ReferenceImage& reference) {
  Image image(reference.color.width, reference.color.height);
  for (std::size_t p = 0; p < reference.mask.size(); ++p)
    image.pixels[p * 4] = static_cast<float>(reference.mask[p]);
  return image;
}

std::vector<PixelMask> maskFromImage(const Image& image) {
  std::vector<PixelMask> mask(static_cast<std::size_t>(image.width) * image.height);
  for (std::size_t p = 0; p < mask.size(); ++p)
    mask[p] = static_cast<PixelMask>(static_cast<int>(image.pixels[p * 4]));
  return mask;
}

RenderJob sceneRenderJob(const Manifest& m, const Scene& scene, const ResolvedBindings& bindings) {
  RenderJob job;
  job.program = loadProgram(m);
  job.uniforms = bindings.uniforms;
  job.attributes = bindings.attributes;
  job.indices = scene.indices;
  job.cubeMaps = environmentBindings(m, scene);
  job.textures2D = decalBindings(m, scene);
  job.width = scene.width;
  job.height = scene.height;
  return job;
}

namespace {

ImageComparison compareTimed(const OracleStore* store, const std::string& against,
                             const Image& image, const Image& other,
                             const std::vector<PixelMask>& mask, const ImageTolerance& rules) {
  const PhaseScope phase(Phase::Compare);
  return compareImagesKept(store, against, image, other, mask, rules);
}

void writeHeatMapTimed(const fs::path& path, const Image& image, const Image& other,
                       const std::vector<PixelMask>& mask, double fail) {
  const PhaseScope phase(Phase::Images);
  writeDifferenceHeatMap(path, image, other, mask, fail);
}

}  // namespace

std::string blessCommand(const std::string& backend, const std::string& blessFlags,
                         const std::string& caseId) {
  return fmt::format("snell bless --backend {}{}{}{}", backend, blessFlags.empty() ? "" : " ",
                     blessFlags, caseId.empty() ? "" : fmt::format(" --filter '{}'", caseId));
}

void writeReferenceImages(const fs::path& outDir, const std::string& caseId,
                          const ReferenceImage& reference) {
  const PhaseScope phase(Phase::Images);
  const fs::path dir = outDir / caseId;
  fs::create_directories(dir);
  writeImageAtomically(referenceImagePath(outDir, caseId), reference.color);
  writeImageAtomically(dir / "reference.png", reference.color);
  writeImageAtomically(maskImagePath(outDir, caseId), maskAsImage(reference));
  writeDifferenceHeatMap(dir / "mask.png", reference.color, reference.color, reference.mask, 1.0);
}

ImageCheck checkImage(Backend& backend, const Case& c, const Scene& scene,
                      const ResolvedBindings& bindings, const ReferenceImage& reference,
                      const ImageCheckOptions& options, bool referenceWritten) {
  const RenderOutcome outcome = backend.render(sceneRenderJob(*c.manifest, scene, bindings));
  ImageCheck check;
  if (!outcome.compile.ok) {
    check.compiled = false;
    check.compileLog = outcome.compile.log;
    return check;
  }
  const std::string name = backend.name();
  const fs::path dir = options.outDir / c.id;
  {
    const PhaseScope phase(Phase::Images);
    fs::create_directories(dir);
    writeImageAtomically(renderedImagePath(options.outDir, c.id, name), outcome.image);
    writeImageAtomically(dir / (name + ".png"), outcome.image);
    if (!referenceWritten) writeReferenceImages(options.outDir, c.id, reference);
  }
  const OracleStore* store = options.store ? &*options.store : nullptr;
  check.comparisons.push_back(compareTimed(store, "reference", outcome.image, reference.color,
                                           reference.mask, c.spec.image));
  writeHeatMapTimed(heatMapPath(options.outDir, c.id, name, "reference"), outcome.image,
                    reference.color, reference.mask, c.spec.image.fail);

  const std::string goldenKey = options.goldenKey.empty() ? name : options.goldenKey;
  if (!options.goldenDir.empty() && !hasAnyGolden(options.goldenDir, goldenKey, options.outDir)) {
    check.goldenNote = fmt::format(
        "no golden yet for this driver (key `{}`): the CPU reference gates it; `{}` writes its "
        "goldens",
        goldenKey, blessCommand(name, options.blessFlags, ""));
  } else if (!options.goldenDir.empty()) {
    try {
      const Golden golden = [&] {
        const PhaseScope phase(Phase::Images);
        return readGolden(options.goldenDir, c.id, goldenKey, scene.width, scene.height,
                          blessCommand(name, options.blessFlags, c.id),
                          [&](const fs::path& path) { return readImageKept(store, path); });
      }();
      check.comparisons.push_back(
          compareTimed(store, "golden", outcome.image, golden.image, reference.mask, c.spec.image));
      if (check.comparisons.back().verdict != ImageVerdict::Pass)
        check.goldenAdvice =
            fmt::format("golden {}: if the change is intended, bless the new image with `{}`",
                        goldenFiles(options.goldenDir, c.id, goldenKey).image.string(),
                        blessCommand(name, options.blessFlags, c.id));
      writeHeatMapTimed(heatMapPath(options.outDir, c.id, name, "golden"), outcome.image,
                        golden.image, reference.mask, c.spec.image.fail);
    } catch (const UsageError& error) {
      check.goldenProblem = error.what();
    }
  }
  return check;
}

}  // namespace snell

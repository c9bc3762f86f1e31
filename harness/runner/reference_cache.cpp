#include "runner/reference_cache.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include "compare/image_io.h"
#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/phase_clock.h"
#include "core/whole_file.h"
#include "runner/image_check.h"
#include "runner/listing_oracles.h"
#include "runner/oracle_store/oracle_store_key.h"

namespace snell {
namespace {

namespace fs = std::filesystem;

// An exclusive lock on a file, held for the object's life.
class FileLock {
 public:
  explicit FileLock(const fs::path& path)
      : fd_(::open(path.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644)) {
    if (fd_ < 0) throw SetupError("cannot open the lock file " + path.string());
    while (::flock(fd_, LOCK_EX) != 0)
      if (errno != EINTR) throw SetupError("cannot lock " + path.string());
  }
  ~FileLock() { ::close(fd_); }  // closing releases the lock
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_;
};

}  // namespace

const ReferenceImage& ReferenceCache::get(const Case& c, const Scene& scene,
                                          const ResolvedBindings& bindings) {
  if (auto it = images_.find(c.id); it != images_.end()) return it->second;
  ReferenceImage image =
      runId_.empty() ? render(c, scene, bindings) : renderOrShare(c, scene, bindings);
  return images_.emplace(c.id, std::move(image)).first->second;
}

ReferenceImage ReferenceCache::render(const Case& c, const Scene& scene,
                                      const ResolvedBindings& bindings) {
  // Gathering the reference's inputs (copies of the scene's attributes and
  // textures) is the oracle's work too.
  const PhaseScope phase(Phase::Oracle);
  const Manifest& m = *c.manifest;
  const DrawingOracles oracles = drawingOracles(m);
  ReferenceInput input{oracles.label,
                       bindings.uniforms,
                       m.constants,
                       bindings.attributes,
                       bindings.vertexCount,
                       scene.indices,
                       environmentBindings(m, scene),
                       scene.width,
                       scene.height,
                       {0, 0, 0, 0},
                       true,
                       decalBindings(m, scene),
                       oracles.vertex.get(),
                       oracles.fragment.get()};
  if (!store_ || oracles.identity.empty()) {
    ++rendered_;
    return renderReferenceImage(input);
  }
  const Digest key = referenceImageKey(oracles.identity, input);
  if (std::optional<ReferenceImage> kept = store_->loadReference(key)) {
    ++fromStore_;
    return std::move(*kept);
  }
  ++rendered_;
  ReferenceImage image = renderReferenceImage(input);
  store_->saveReference(key, image);
  return image;
}

ReferenceImage ReferenceCache::renderOrShare(const Case& c, const Scene& scene,
                                             const ResolvedBindings& bindings) {
  // Its folder, lock and owner file are image files' work.
  const PhaseScope files(Phase::Images);
  const fs::path dir = outDir_ / c.id;
  fs::create_directories(dir);
  const fs::path color = referenceImagePath(outDir_, c.id), mask = maskImagePath(outDir_, c.id),
                 owner = dir / "reference.run";
  // Waiting here is waiting for the run's other worker to render the
  // reference: the reference's time (the oracle's), not this case's own.
  const FileLock lock = [&] {
    const PhaseScope waiting(Phase::Oracle);
    return FileLock(dir / "reference.lock");
  }();
  const bool sharedThisRun = readWholeFile(owner).value_or("") == runId_;
  // The run's other worker rendered it: with a store, its result is there
  // (render() reads it without decoding an image file).
  if (sharedThisRun && store_) return render(c, scene, bindings);
  if (sharedThisRun) {
    const PhaseScope phase(Phase::Images);
    try {
      ReferenceImage shared{readImage(color), maskFromImage(readImage(mask))};
      if (shared.color.width == scene.width && shared.color.height == scene.height) return shared;
    } catch (const UsageError&) {
      // Damaged since it was written: render it again below.
    }
  }
  ReferenceImage image = render(c, scene, bindings);
  // Every file of the reference, once for the run's workers: they read
  // the float ones back, and the report shows the rest.
  writeReferenceImages(outDir_, c.id, image);
  writeFileAtomically(owner, runId_);
  return image;
}

}  // namespace snell

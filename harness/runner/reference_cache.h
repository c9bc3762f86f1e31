#pragma once
// The CPU reference image of each image case, computed once per run. In a
// worker it is kept in memory for the cases that worker runs; across the
// run's workers (one per backend) it is shared through the run's output
// folder, where the reference and its mask are written for the report
// anyway: under a lock, the first worker renders and writes them with the
// run's id, and every other worker of that run reads them back (float EXR,
// so bit for bit) instead of rendering again.
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "core/case.h"
#include "core/scene.h"
#include "oracle/reference/reference_image.h"
#include "runner/oracle_store/oracle_store.h"

namespace snell {

class ReferenceCache {
 public:
  ReferenceCache() = default;  // in memory only
  // Shared with the other workers of the run `runId` through `outDir`, and
  // with later runs through `store` when there is one.
  ReferenceCache(std::filesystem::path outDir, std::string runId,
                 std::optional<OracleStore> store = std::nullopt)
      : outDir_(std::move(outDir)), runId_(std::move(runId)), store_(std::move(store)) {}

  const ReferenceImage& get(const Case& c, const Scene& scene, const ResolvedBindings& bindings);

  // True when the reference's files (runner/image_check.h's
  // writeReferenceImages) are written here, once for the whole run.
  bool writesImages() const { return !runId_.empty(); }

  // How many references this cache rendered itself (the rest it read), and
  // how many of those reads were from the store.
  std::size_t rendered() const { return rendered_; }
  std::size_t fromStore() const { return fromStore_; }

 private:
  ReferenceImage render(const Case& c, const Scene& scene, const ResolvedBindings& bindings);
  ReferenceImage renderOrShare(const Case& c, const Scene& scene, const ResolvedBindings& bindings);

  std::filesystem::path outDir_;
  std::string runId_;
  std::optional<OracleStore> store_;
  std::map<std::string, ReferenceImage> images_;
  std::size_t rendered_ = 0;
  std::size_t fromStore_ = 0;
};

}  // namespace snell

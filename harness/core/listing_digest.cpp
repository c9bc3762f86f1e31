#include "core/listing_digest.h"

#include "core/content_hash.h"
#include "core/whole_file.h"

namespace snell {

std::string listingDigest(const Manifest& manifest) {
  ContentHash hash;
  hash.add(readWholeFile(manifest.path).value_or(""));
  const std::filesystem::path folder = manifest.path.parent_path();
  // A stage the listing does not have is an empty field: the fields keep
  // their places.
  for (const std::string& stage : {manifest.vertexFile, manifest.fragmentFile})
    hash.add(stage.empty() ? std::string() : readWholeFile(folder / stage).value_or(""));
  return hash.finish().hex();
}

}  // namespace snell

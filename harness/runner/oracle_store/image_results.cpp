#include "runner/oracle_store/image_results.h"

#include <optional>
#include <string>

#include "compare/image_io.h"
#include "compare/image_library.h"
#include "core/whole_file.h"
#include "runner/oracle_store/stored_result_format.h"

namespace snell {
namespace {

void addImage(ContentHash& hash, const Image& image) {
  hash.add(image.width);
  hash.add(image.height);
  hash.add(static_cast<std::uint64_t>(image.pixels.size()));
  hash.addBytes(image.pixels.data(), image.pixels.size() * sizeof(float));
}

}  // namespace

Image readImageKept(const OracleStore* store, const std::filesystem::path& path) {
  if (!store) return readImage(path);
  const std::optional<std::string> bytes = readWholeFile(path);
  if (!bytes) return readImage(path);  // missing or unreadable: its own message
  ContentHash hash;
  hash.add(std::string_view("decoded image"));
  hash.add(std::string_view(imageWriterIdentity()));  // the decoder's build
  hash.add(std::string_view(*bytes));
  return store->keptOrComputed(hash.finish(), decodeStoredImage, encodeStoredImage,
                               [&] { return readImage(path); });
}

ImageComparison compareImagesKept(const OracleStore* store, const std::string& against,
                                  const Image& observed, const Image& expected,
                                  const std::vector<PixelMask>& mask,
                                  const ImageTolerance& thresholds) {
  if (!store) return compareImages(against, observed, expected, mask, thresholds);
  ContentHash hash;
  hash.add(std::string_view("image comparison"));
  hash.add(std::string_view(imageWriterIdentity()));  // the comparison's build
  hash.add(std::string_view(against));
  addImage(hash, observed);
  addImage(hash, expected);
  hash.add(static_cast<std::uint64_t>(mask.size()));
  hash.addBytes(mask.data(), mask.size() * sizeof(PixelMask));
  for (double t : {thresholds.fail, thresholds.warn, thresholds.failPercent, thresholds.hardFail})
    hash.add(t);
  return store->keptOrComputed(hash.finish(), decodeStoredComparison, encodeStoredComparison, [&] {
    return compareImages(against, observed, expected, mask, thresholds);
  });
}

}  // namespace snell

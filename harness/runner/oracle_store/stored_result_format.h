#pragma once
// The bytes of one stored oracle result (runner/oracle_store/oracle_store.h):
// a header that names the key, the kind of result and the digest of the
// payload, then every field of the result (the OracleVaryings of a vector
// check, or a CPU reference image and its mask), so that a result read
// back is bit for bit the one that was computed. A file that was cut short, damaged, written
// by another format version or under another key reads as nothing.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compare/image_compare.h"
#include "core/content_hash.h"
#include "core/expected_values.h"
#include "oracle/reference/reference_image.h"

namespace snell {

inline constexpr std::uint32_t kStoredResultFormat = 1;

std::string encodeStoredResult(const Digest& key, const std::vector<OracleVarying>& result);
std::optional<std::vector<OracleVarying>> decodeStoredResult(const Digest& key,
                                                             std::string_view bytes);

std::string encodeStoredReference(const Digest& key, const ReferenceImage& reference);
std::optional<ReferenceImage> decodeStoredReference(const Digest& key, std::string_view bytes);

// An image file's decoded pixels, and the comparison of two images.
std::string encodeStoredImage(const Digest& key, const Image& image);
std::optional<Image> decodeStoredImage(const Digest& key, std::string_view bytes);
std::string encodeStoredComparison(const Digest& key, const ImageComparison& comparison);
std::optional<ImageComparison> decodeStoredComparison(const Digest& key, std::string_view bytes);

}  // namespace snell

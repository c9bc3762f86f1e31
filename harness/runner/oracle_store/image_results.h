#pragma once
// Image work kept across runs in the oracle store, so that a run on the
// same driver as an earlier one need not open the image module at all: the
// pixels decoded from an image file (by the digest of the file's bytes) and
// the comparison of two images under a case's thresholds (by the digest of
// both images, the mask and the thresholds). Files written again from the
// same pixels are skipped where they are written (core/written_mark.h).
// With no store (null), each is the plain operation.
#include <filesystem>
#include <string>
#include <vector>

#include "compare/image_compare.h"
#include "core/image.h"
#include "core/manifest.h"
#include "core/pixel_mask.h"
#include "runner/oracle_store/oracle_store.h"

namespace snell {

// readImage (compare/image_io.h), errors included.
Image readImageKept(const OracleStore* store, const std::filesystem::path& path);

// compareImages (compare/image_compare.h).
ImageComparison compareImagesKept(const OracleStore* store, const std::string& against,
                                  const Image& observed, const Image& expected,
                                  const std::vector<PixelMask>& mask,
                                  const ImageTolerance& thresholds);

}  // namespace snell

#pragma once
// The C interface of snell_image_library, the module that holds everything
// in snell that touches OpenImageIO. libOpenImageIO pulls in some 260 shared
// libraries (codecs, GDAL, DICOM...); linked into `snell`, the dynamic
// loader resolved them in every process, even `snell --help`. Opened with
// dlopen on the first image read, write or comparison (compare/image_library.h),
// only the processes that handle images pay for it.
//
// Plain C across the boundary: one entry point returns a table of function
// pointers; no C++ types or exceptions cross it. Each function returns a
// SnellImageStatus and, when that is not SNELL_IMAGE_OK, a message in the
// caller's SnellImageError. Bump SNELL_IMAGE_LIBRARY_ABI on any change here.
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define SNELL_IMAGE_LIBRARY_ABI 1
#define SNELL_IMAGE_LIBRARY_ENTRY_POINT "snell_image_library"

typedef enum SnellImageStatus {
  SNELL_IMAGE_OK = 0,
  SNELL_IMAGE_BAD_FILE = 1,      // unreadable, truncated, not RGBA: the user's file
  SNELL_IMAGE_CANNOT_WRITE = 2,  // the file could not be written
  SNELL_IMAGE_FAILED = 3         // anything else (out of memory, OpenImageIO threw)
} SnellImageStatus;

typedef enum SnellImageEncoding {
  SNELL_IMAGE_FLOAT = 0,  // 32-bit float, zip-compressed where the format has it (EXR)
  SNELL_IMAGE_SRGB8 = 1   // linear to sRGB, then 8 bits (PNG, for people)
} SnellImageEncoding;

typedef struct SnellImageError {
  char message[2048];  // what went wrong, without the file name; NUL-terminated
} SnellImageError;

// Called once by readRgba with the image's size; returns where the
// width * height * 4 floats go, or NULL when they cannot be allocated.
// Must not throw.
typedef float* (*SnellImageAllocate)(void* context, int width, int height);

// ImageBufAlgo::compare's results, as they come.
typedef struct SnellImageDifference {
  double meanError, rmsError, psnr, maxError;
  int maxX, maxY;
  uint64_t warned, failed;  // pixels
} SnellImageDifference;

typedef struct SnellImageLibraryFunctions {
  int abi;                     // SNELL_IMAGE_LIBRARY_ABI
  const char* libraryVersion;  // OpenImageIO's, for diagnostics

  // An RGBA image as linear floats, row 0 at the top. BAD_FILE when the
  // file cannot be opened, has not 4 channels, or is truncated.
  SnellImageStatus (*readRgba)(const char* path, void* context, SnellImageAllocate allocate,
                               SnellImageError* error);

  // `channels` floats per pixel; the format comes from the file name's
  // extension. Writes `path` itself: callers wanting atomicity pass a
  // temporary name and rename it.
  SnellImageStatus (*write)(const char* path, const float* pixels, int width, int height,
                            int channels, SnellImageEncoding encoding, SnellImageError* error);

  // Two RGBA images of one size; channels off by more than `fail` (`warn`)
  // count as failed (warned) pixels.
  SnellImageStatus (*compareRgba)(const float* a, const float* b, int width, int height, float fail,
                                  float warn, SnellImageDifference* result, SnellImageError* error);

  // One value per pixel in [0, 1] through the "inferno" colour map; a
  // negative value (a masked pixel) is drawn flat grey. Written as
  // OpenImageIO writes float pixels to the file's format (no sRGB step).
  SnellImageStatus (*writeHeatMap)(const char* path, const float* values, int width, int height,
                                   SnellImageError* error);
} SnellImageLibraryFunctions;

typedef const SnellImageLibraryFunctions* (*SnellImageLibraryEntryPoint)(void);

#ifdef __cplusplus
}
#endif

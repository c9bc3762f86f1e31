#pragma once
// The OpenImageIO module (compare/oiio/image_library_abi.h), opened on first
// use. Where it is looked for, in order:
//   1. $SNELL_IMAGE_LIBRARY, when set: that file and nothing else;
//   2. the module this snell was built with (its absolute path, compiled in;
//      the build puts it beside the snell executable);
//   3. libsnell_image_library.so beside the running executable, for a copy
//      of the two elsewhere.
#include <string>
#include <vector>

#include "compare/oiio/image_library_abi.h"

namespace snell {

// Opens the module once per process (thread-safe) and returns its table.
// Throws SetupError naming each file tried, the loader's reason and what to
// do; a later call tries again.
const SnellImageLibraryFunctions& imageLibrary();

// The files imageLibrary() tries, in order.
std::vector<std::string> imageLibraryCandidates();

// Throws SetupError, naming the files looked for and what to do, when none
// of imageLibraryCandidates() exists: said before a run that draws starts,
// instead of as a failure of every image case. Opens nothing (a run whose
// image work is kept may never need the module).
void requireImageLibraryFile();

// What decides the bytes of an image file written here, known without
// opening the module: the module file that would be opened (its path, size
// and time) and the build of the code that prepares the pixels. Part of the
// digest a written file is marked with (core/written_mark.h).
const std::string& imageWriterIdentity();

// Opens the first of `candidates` that loads and checks that it is the
// module, of this interface version; no caching. Throws SetupError.
const SnellImageLibraryFunctions& openImageLibrary(const std::vector<std::string>& candidates);

}  // namespace snell

#pragma once
// Which driver build a result came from. The shards that `merge` joins and
// the run that `--resume` goes on with must each hold one build per
// backend: results of two builds joined under one would be credited to
// whichever the report and compare read first.
#include <string>

#include "backends/backend.h"

namespace snell {

// The same renderer, API version and driver version. A record that names
// no driver at all (a worker that died before it said) matches any.
bool sameDriverBuild(const DriverInfo& a, const DriverInfo& b);
bool namesDriver(const DriverInfo& driver);

// "Mesa 22.3.6, llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core
// Profile) Mesa 22.3.6": for a message naming two builds apart.
std::string driverBuildName(const DriverInfo& driver);

}  // namespace snell

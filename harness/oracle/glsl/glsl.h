#pragma once
// Everything a listing oracle needs to read like its GLSL source.
#include "oracle/glsl/branch.h"
#include "oracle/glsl/geometric.h"
#include "oracle/glsl/scalar.h"
#include "oracle/glsl/vector.h"

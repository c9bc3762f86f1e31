#pragma once
// Registers the tool's number types with the oracle's GLSL templates, so a
// listing mirrored as Shader<T> runs over them unchanged.
#include "oracle/glsl/glsl.h"
#include "widths/chain_functions.h"
#include "widths/conforming_sampler.h"
#include "widths/deqp_interval.h"

namespace snell::glsl {
template <>
struct IsNumber<widths::Deqp> : std::true_type {};
template <>
struct IsNumber<widths::Sampled> : std::true_type {};
}  // namespace snell::glsl

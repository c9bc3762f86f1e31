#pragma once
// The inputs the widths are measured on: for reflect and refract, random
// unit vectors and the edges where intervals are hardest (grazing
// incidence, the critical angle, eta near 1, and the reproductions of issue
// 9); for a listing, its manifest's constants and its first case's scene
// (uniforms, and attributes the scene provides), with inputs the scene does
// not provide (fragment-stage probe values) drawn at random.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "widths/snell_intervals.h"

namespace snell::widths {

struct BuiltinInput {
  std::vector<float> I, N;
  float eta = 1.0f;
};

struct BuiltinInputSet {
  std::string fn;    // "reflect" / "refract"
  std::string name;  // "random", "grazing", ...
  std::vector<BuiltinInput> inputs;
};

std::vector<BuiltinInputSet> builtinInputSets(std::size_t perSet, std::uint64_t seed);

struct ListingInputSet {
  std::string oracle;
  std::string manifest;  // the manifest's id
  ListingBindings bindings;
};

// One set per manifest under `shaders` that runs (not an expected compile
// error), at most `vertices` vertices each.
std::vector<ListingInputSet> listingInputSets(const std::filesystem::path& shaders,
                                              std::size_t vertices, std::uint64_t seed);

}  // namespace snell::widths

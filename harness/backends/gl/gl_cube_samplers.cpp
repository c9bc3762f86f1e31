#include "backends/gl/gl_cube_samplers.h"

#include "core/errors.h"

namespace snell {

namespace {
void checkFaces(const std::string& name, const CubeMap& map) {
  if (map.size <= 0)
    throw UsageError("cube map for sampler '" + name + "' has size " + std::to_string(map.size));
  const std::size_t floats = static_cast<std::size_t>(map.size) * map.size * 4;
  for (std::size_t face = 0; face < map.faces.size(); ++face) {
    if (map.faces[face].size() != floats)
      throw UsageError("cube map for sampler '" + name + "': face " + std::to_string(face) +
                       " holds " + std::to_string(map.faces[face].size()) + " floats; a " +
                       std::to_string(map.size) + "x" + std::to_string(map.size) +
                       " RGBA face needs " + std::to_string(floats));
  }
}
}  // namespace

GlCubeSamplerPlan planCubeSamplers(const std::vector<GlUniformTable::Sampler>& samplers,
                                   const std::map<std::string, const CubeMap*>& cubeMaps) {
  GlCubeSamplerPlan plan;
  const std::string* seamlessFrom = nullptr;
  for (const GlUniformTable::Sampler& sampler : samplers) {
    const auto given = cubeMaps.find(sampler.name);
    if (given == cubeMaps.end() || given->second == nullptr)
      throw UsageError("the shader samples '" + sampler.name +
                       "' but the job gives it no cube map");
    if (sampler.type != GL_SAMPLER_CUBE || sampler.arraySize != 1)
      throw UsageError("sampler '" + sampler.name + "' is declared " +
                       GlUniformTable::glslName(sampler.type) +
                       (sampler.arraySize != 1 ? "[" + std::to_string(sampler.arraySize) + "]" : "") +
                       " in the shader; only a single samplerCube can take a cube map");
    const CubeMap& map = *given->second;
    checkFaces(sampler.name, map);
    if (seamlessFrom && map.seamless != plan.seamless)
      throw UsageError("cube maps for '" + *seamlessFrom + "' and '" + sampler.name +
                       "' disagree on seamless filtering, which OpenGL sets per draw");
    seamlessFrom = &sampler.name;
    plan.seamless = map.seamless;
    plan.bindings.push_back({sampler.location, &map});
  }
  return plan;
}

}  // namespace snell

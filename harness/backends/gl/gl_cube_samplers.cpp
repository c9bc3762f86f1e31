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

void checkImage(const std::string& name, const Image& image) {
  const std::string size = std::to_string(image.width) + "x" + std::to_string(image.height);
  if (image.width <= 0 || image.height <= 0)
    throw UsageError("2D texture for sampler '" + name + "' is " + size);
  const std::size_t floats = static_cast<std::size_t>(image.width) * image.height * 4;
  if (image.pixels.size() != floats)
    throw UsageError("2D texture for sampler '" + name + "' holds " +
                     std::to_string(image.pixels.size()) + " floats; a " + size +
                     " RGBA image needs " + std::to_string(floats));
}

std::string declaration(const GlUniformTable::Sampler& sampler) {
  return GlUniformTable::glslName(sampler.type) +
         (sampler.arraySize != 1 ? "[" + std::to_string(sampler.arraySize) + "]" : "");
}
}  // namespace

GlSamplerPlan planSamplers(const std::vector<GlUniformTable::Sampler>& samplers,
                           const std::map<std::string, const CubeMap*>& cubeMaps,
                           const std::map<std::string, const Image*>& textures2D) {
  GlSamplerPlan plan;
  const std::string* seamlessFrom = nullptr;
  for (const GlUniformTable::Sampler& sampler : samplers) {
    if (sampler.type == GL_SAMPLER_2D && sampler.arraySize == 1) {
      const auto given = textures2D.find(sampler.name);
      if (given == textures2D.end() || given->second == nullptr)
        throw UsageError("the shader samples '" + sampler.name +
                         "' (sampler2D) but the job gives it no 2D texture");
      checkImage(sampler.name, *given->second);
      plan.textures2D.push_back({sampler.location, given->second});
      continue;
    }
    const auto given = cubeMaps.find(sampler.name);
    if (given == cubeMaps.end() || given->second == nullptr)
      throw UsageError("the shader samples '" + sampler.name +
                       "' but the job gives it no cube map");
    if (sampler.type != GL_SAMPLER_CUBE || sampler.arraySize != 1)
      throw UsageError("sampler '" + sampler.name + "' is declared " + declaration(sampler) +
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

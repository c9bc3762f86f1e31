#include "core/case.h"

#include <fmt/format.h>
#include <fnmatch.h>

#include <algorithm>
#include <optional>

#include "core/errors.h"
#include "core/glsl_declarations.h"

namespace snell {

std::vector<Case> expandCases(const std::vector<Manifest>& manifests, const std::string& glob) {
  std::vector<Case> cases;
  for (const Manifest& manifest : manifests)
    for (const CaseSpec& spec : manifest.cases) {
      Case c{manifest.id + "/" + spec.scene, &manifest, spec};
      if (glob.empty() || fnmatch(glob.c_str(), c.id.c_str(), 0) == 0)
        cases.push_back(std::move(c));
    }
  return cases;
}

namespace {

// A semantic the scene lacks, or one of the other kind: an input takes a
// per-vertex semantic, a uniform one value for the draw (or a texture).
[[noreturn]] void unknownSemantic(const Manifest& manifest, const Binding& binding,
                                  const Scene& scene, const std::string& semantic, bool input) {
  std::vector<std::string> perVertex, perDraw;
  for (const auto& [name, value] : scene.attributes) perVertex.push_back("scene." + name);
  for (const auto& [name, value] : scene.values) perDraw.push_back("scene." + name);
  for (const std::string& name : scene.samplers) perDraw.push_back("scene." + name);
  const bool otherKind = input ? scene.values.count(semantic) > 0 ||
                                     std::find(scene.samplers.begin(), scene.samplers.end(),
                                               semantic) != scene.samplers.end()
                               : scene.attributes.count(semantic) > 0;
  const std::string where = fmt::format("{}:{}: ", manifest.path.string(), binding.line);
  const std::vector<std::string>& takes = input ? perVertex : perDraw;
  if (otherKind)
    throw UsageError(fmt::format(
        "{}{} `{}` is bound to scene.{}, which is {}; bind {}: {}", where,
        input ? "input" : "uniform", binding.name, semantic,
        input ? "one value for the whole draw (a uniform's)" : "per vertex (an input's)",
        input ? "a per-vertex semantic" : "a value for the draw", fmt::join(takes, ", ")));
  throw UsageError(
      fmt::format("{}`{}` is bound to scene.{}, which scene `{}` does not "
                  "provide; it provides {}",
                  where, binding.name, semantic, scene.name, fmt::join(takes, ", ")));
}

// GL's initial value of a uniform the manifest binds to "default": zero, of
// the type the listing declares (a sampler is left to the backend's unit 0).
void bindApiDefaultUniform(const Manifest& manifest, const Binding& binding, UniformMap& uniforms) {
  const ProgramSource program = loadProgram(manifest);
  for (const std::string* source : {&program.vertex, &program.fragment})
    for (const GlslDeclaration& d : readGlobalDeclarations(*source)) {
      if (d.qualifier != "uniform" || d.name != binding.name) continue;
      for (ValueType type : {ValueType::Float, ValueType::Vec2, ValueType::Vec3, ValueType::Vec4,
                             ValueType::Mat3, ValueType::Mat4})
        if (d.type == glslTypeName(type))
          uniforms[binding.name] = Value{type, std::vector<float>(componentCount(type), 0.0f)};
      return;
    }
}

// GL's initial value of a generic vertex input, (0, 0, 0, 1), cut to the
// components the listing declares, at every vertex.
AttributeStream apiDefaultInput(const Manifest& manifest, const std::string& name,
                                std::size_t vertexCount) {
  int components = 4;
  for (const GlslDeclaration& d : readGlobalDeclarations(loadProgram(manifest).vertex))
    if ((d.qualifier == "in" || d.qualifier == "attribute") && d.name == name)
      components = d.type == "float" ? 1 : d.type.size() == 4 ? d.type[3] - '0' : 4;
  components = std::clamp(components, 1, 4);
  const float initial[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  AttributeStream stream{name, components, {}};
  stream.data.reserve(vertexCount * static_cast<std::size_t>(components));
  for (std::size_t v = 0; v < vertexCount; ++v)
    stream.data.insert(stream.data.end(), initial, initial + components);
  return stream;
}

// The components a vertex input is declared with (float 1, vecN N), or 0
// when the listing does not declare it as a float input (a built-in such as
// gl_Vertex, or a name the manifest check reports).
int declaredInputComponents(const std::vector<GlslDeclaration>& vertex, const std::string& name) {
  for (const GlslDeclaration& d : vertex) {
    if ((d.qualifier != "in" && d.qualifier != "attribute") || d.name != name) continue;
    if (d.type == "float") return 1;
    if (d.type.size() == 4 && d.type.rfind("vec", 0) == 0 && d.type[3] >= '2' && d.type[3] <= '4')
      return d.type[3] - '0';
    return 0;
  }
  return 0;
}

// The scene's stream as the listing declares it: a `vec3 aPos` bound to the
// vec4 scene.position gets x, y, z of each vertex, so backends, hand-written
// and derived oracles all read the same values with the declared shape. A
// stream narrower than the declaration is left for the manifest check.
AttributeStream shapedAs(const AttributeStream& scene, int components) {
  if (components <= 0 || components >= scene.components) return scene;
  AttributeStream out{scene.name, components, {}};
  const std::size_t vertices = scene.vertexCount();
  out.data.reserve(vertices * static_cast<std::size_t>(components));
  for (std::size_t v = 0; v < vertices; ++v) {
    const auto first = scene.data.begin() + static_cast<std::ptrdiff_t>(v * scene.components);
    out.data.insert(out.data.end(), first, first + components);
  }
  return out;
}

}  // namespace

ResolvedBindings resolveBindings(const Manifest& manifest, const Scene& scene) {
  ResolvedBindings out;
  out.vertexCount = scene.vertexCount;
  for (const Binding& binding : manifest.uniforms) {
    if (binding.apiDefault) {
      bindApiDefaultUniform(manifest, binding, out.uniforms);
      continue;
    }
    if (const Value* literal = std::get_if<Value>(&binding.source)) {
      out.uniforms[binding.name] = *literal;
      continue;
    }
    const std::string& semantic = std::get<std::string>(binding.source);
    if (auto it = scene.values.find(semantic); it != scene.values.end())
      out.uniforms[binding.name] = it->second;
    else if (std::find(scene.samplers.begin(), scene.samplers.end(), semantic) ==
             scene.samplers.end())
      unknownSemantic(manifest, binding, scene, semantic, false);
    // Samplers are bound by the pixel path; the vertex stage does not read them.
  }
  std::optional<std::vector<GlslDeclaration>> vertexDeclarations;  // read once, when needed
  for (const Binding& binding : manifest.inputs) {
    if (binding.apiDefault) {
      out.attributes[binding.name] = apiDefaultInput(manifest, binding.name, scene.vertexCount);
      continue;
    }
    if (std::holds_alternative<Value>(binding.source))
      throw UsageError(
          fmt::format("{}:{}: input `{}` must name a per-vertex scene semantic "
                      "(scene.position, scene.normal), not a literal",
                      manifest.path.string(), binding.line, binding.name));
    const std::string& semantic = std::get<std::string>(binding.source);
    auto it = scene.attributes.find(semantic);
    if (it == scene.attributes.end()) unknownSemantic(manifest, binding, scene, semantic, true);
    if (!vertexDeclarations)
      vertexDeclarations = readGlobalDeclarations(loadProgram(manifest).vertex);
    AttributeStream stream =
        shapedAs(it->second, declaredInputComponents(*vertexDeclarations, binding.name));
    stream.name = binding.name;
    out.attributes[binding.name] = std::move(stream);
  }
  return out;
}

}  // namespace snell

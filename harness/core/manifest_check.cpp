#include "core/manifest_check.h"

#include <fmt/format.h>

#include <optional>

#include "core/errors.h"
#include "core/glsl_declarations.h"

namespace snell {
namespace {

std::optional<GlslDeclaration> find(const std::vector<GlslDeclaration>& declarations,
                                    std::initializer_list<const char*> qualifiers,
                                    const std::string& name) {
  for (const GlslDeclaration& d : declarations)
    for (const char* q : qualifiers)
      if (d.qualifier == q && d.name == name) return d;
  return std::nullopt;
}

}  // namespace

void checkManifestAgainstProgram(const Manifest& m, const ProgramSource& program,
                                 const ResolvedBindings& bindings) {
  const std::string manifest = m.path.string();
  const std::vector<GlslDeclaration> vertex = readGlobalDeclarations(program.vertex);
  std::vector<GlslDeclaration> all = vertex;
  for (const GlslDeclaration& d : readGlobalDeclarations(program.fragment)) all.push_back(d);

  for (const Binding& b : m.uniforms) {
    const auto declared = find(all, {"uniform"}, b.name);
    if (!declared)
      throw UsageError(fmt::format("{}:{}: uniform `{}` is not declared in {}{}{}; check the "
                                   "spelling against the listing",
                                   manifest, b.line, b.name, m.vertexFile,
                                   m.fragmentFile.empty() ? "" : " or ", m.fragmentFile));
    auto bound = bindings.uniforms.find(b.name);
    if (bound == bindings.uniforms.end()) {
      if (declared->type.rfind("sampler", 0) != 0)
        throw UsageError(fmt::format("{}:{}: `{}` is a {} but is bound to a texture", manifest,
                                     b.line, b.name, declared->type));
      continue;
    }
    if (declared->type != glslTypeName(bound->second.type))
      throw UsageError(fmt::format("{}:{}: `{}` is declared {} but bound to a {}", manifest,
                                   b.line, b.name, declared->type,
                                   glslTypeName(bound->second.type)));
  }
  for (const Binding& b : m.inputs) {
    const auto declared = find(vertex, {"in", "attribute"}, b.name);
    if (!declared)
      throw UsageError(fmt::format("{}:{}: input `{}` is not declared in {}; check the spelling "
                                   "against the listing",
                                   manifest, b.line, b.name, m.vertexFile));
    const int components = bindings.attributes.at(b.name).components;
    const bool fits = (declared->type == "float" && components == 1) ||
                      (declared->type.size() == 4 && declared->type.rfind("vec", 0) == 0 &&
                       declared->type[3] - '0' <= components);
    if (!fits)
      throw UsageError(fmt::format("{}:{}: input `{}` is declared {} but its semantic gives {} "
                                   "components",
                                   manifest, b.line, b.name, declared->type, components));
  }
  for (const std::string& name : m.captureVertex)
    if (!find(vertex, {"out", "varying"}, name))
      throw UsageError(fmt::format("{}:{}: capture.vertex names `{}`, which {} does not declare "
                                   "as an output",
                                   manifest, m.captureLine, name, m.vertexFile));
}

}  // namespace snell

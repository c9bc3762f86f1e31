#include "core/manifest_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <regex>

#include "core/errors.h"
#include "core/glsl_declarations.h"
#include "core/legacy_builtins.h"

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

bool legacyName(const std::string& name) { return name.rfind("gl_", 0) == 0; }

// A binding to a fixed-function built-in (gl_ModelViewMatrix, gl_Vertex):
// declared by GL itself, so it is checked against the table of what snell
// sets, by kind and type, instead of against the listing's declarations.
void checkLegacyBinding(const Manifest& m, const Binding& b, bool uniform,
                        const ResolvedBindings& bindings) {
  const std::string manifest = m.path.string();
  const auto builtin = findLegacyBuiltin(b.name);
  const bool attribute = builtin && builtin->kind == LegacyBuiltinKind::Attribute;
  if (!builtin || attribute == uniform)
    throw UsageError(fmt::format(
        "{}:{}: {} `{}` is not a built-in snell can set; it sets {}; "
        "check the spelling",
        manifest, b.line, uniform ? "uniform" : "input", b.name, legacyBindableNames()));
  if (builtin->kind == LegacyBuiltinKind::DerivedMatrix)
    throw UsageError(fmt::format(
        "{}:{}: `{}` is derived by OpenGL from gl_ModelViewMatrix{}; "
        "bind {} instead",
        manifest, b.line, b.name, b.name == "gl_NormalMatrix" ? "" : " and gl_ProjectionMatrix",
        b.name == "gl_NormalMatrix" ? "gl_ModelViewMatrix"
                                    : "gl_ModelViewMatrix and gl_ProjectionMatrix"));
  if (m.profile != Profile::Compatibility)
    throw UsageError(
        fmt::format("{}:{}: `{}` is fixed-function state, which only a legacy "
                    "listing reads; set profile = \"compatibility\"",
                    manifest, b.line, b.name));
  if (uniform) {
    const auto bound = bindings.uniforms.find(b.name);
    if (bound == bindings.uniforms.end())
      throw UsageError(fmt::format("{}:{}: `{}` is a {} but is bound to a texture", manifest,
                                   b.line, b.name, glslTypeName(builtin->type)));
    if (bound->second.type != builtin->type)
      throw UsageError(fmt::format("{}:{}: `{}` is a {} but is bound to a {}", manifest, b.line,
                                   b.name, glslTypeName(builtin->type),
                                   glslTypeName(bound->second.type)));
    return;
  }
  // glNormalPointer takes exactly three components, glVertexPointer two to four.
  const int components = bindings.attributes.at(b.name).components;
  const bool fits = b.name == "gl_Normal"   ? components == 3
                    : b.name == "gl_Vertex" ? components >= 2
                                            : components >= 1;
  if (!fits)
    throw UsageError(
        fmt::format("{}:{}: input `{}` is a {} but its semantic gives {} "
                    "components",
                    manifest, b.line, b.name, glslTypeName(builtin->type), components));
}

bool identifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Occurrences of `name` as a whole identifier in `code` (comments blanked).
int identifierUses(const std::string& code, const std::string& name) {
  int uses = 0;
  for (std::size_t at = code.find(name); at != std::string::npos; at = code.find(name, at + 1)) {
    const bool startsWord = at == 0 || !identifierChar(code[at - 1]);
    const std::size_t end = at + name.size();
    const bool endsWord = end >= code.size() || !identifierChar(code[end]);
    uses += startsWord && endsWord;
  }
  return uses;
}

bool bound(const std::vector<Binding>& bindings, const std::string& name) {
  return std::any_of(bindings.begin(), bindings.end(),
                     [&](const Binding& b) { return b.name == name; });
}

// A uniform or vertex input the listing declares and reads but the manifest
// leaves unbound would be read as the API's initial value (0) and the case
// might pass on nothing: the author binds it, or writes "default" to say the
// initial value is meant.
void checkEveryReadDeclarationIsBound(const Manifest& m, const ProgramSource& program) {
  struct Stage {
    const std::string& source;
    const std::string& file;
    bool vertex;
  };
  for (const Stage& stage : {Stage{program.vertex, program.vertexPath, true},
                             Stage{program.fragment, program.fragmentPath, false}}) {
    if (stage.source.empty()) continue;
    const std::string code = withoutComments(stage.source);
    for (const GlslDeclaration& d : readGlobalDeclarations(stage.source)) {
      const bool uniform = d.qualifier == "uniform";
      const bool input = stage.vertex && (d.qualifier == "in" || d.qualifier == "attribute");
      if (!uniform && !input) continue;
      if (bound(uniform ? m.uniforms : m.inputs, d.name)) continue;
      if (identifierUses(code, d.name) < 2) continue;  // declared, never read
      throw UsageError(fmt::format(
          "{}:{}: {} `{}` is declared and read, but {} does not bind it: add it to [{}] as "
          "\"scene.<semantic>\", a literal, or \"default\" for the API's initial value",
          stage.file, d.line, uniform ? "uniform" : "input", d.name, m.path.string(),
          uniform ? "uniforms" : "inputs"));
    }
  }
}

}  // namespace

namespace {

// The name of the uniform block (`uniform Camera { ... };`, with or without
// a layout) that declares `member`, or "" when none does.
std::string uniformBlockHolding(const std::string& source, const std::string& member) {
  // A TOML key can be any text: only an identifier can be a member.
  static const std::regex kIdentifier(R"([A-Za-z_]\w*)");
  if (!std::regex_match(member, kIdentifier)) return "";
  static const std::regex kBlock(R"(\buniform\s+([A-Za-z_]\w*)\s*\{([^}]*)\})");
  const std::regex kMember("\\b" + member + "\\s*(\\[[^\\]]*\\]\\s*)?;");
  for (auto it = std::sregex_iterator(source.begin(), source.end(), kBlock);
       it != std::sregex_iterator(); ++it)
    if (std::regex_search((*it)[2].first, (*it)[2].second, kMember)) return (*it)[1].str();
  return "";
}

}  // namespace

void checkManifestAgainstProgram(const Manifest& m, const ProgramSource& program,
                                 const ResolvedBindings& bindings) {
  const std::string manifest = m.path.string();
  const std::vector<GlslDeclaration> vertex = readGlobalDeclarations(program.vertex);
  std::vector<GlslDeclaration> all = vertex;
  for (const GlslDeclaration& d : readGlobalDeclarations(program.fragment)) all.push_back(d);

  for (const Binding& b : m.uniforms) {
    if (legacyName(b.name) && b.apiDefault)
      throw UsageError(
          fmt::format("{}:{}: `{}` is fixed-function state: \"default\" is for the "
                      "listing's own uniforms and inputs; bind a scene semantic",
                      manifest, b.line, b.name));
    if (legacyName(b.name)) {
      checkLegacyBinding(m, b, true, bindings);
      continue;
    }
    const auto declared = find(all, {"uniform"}, b.name);
    if (!declared) {
      // `cam.eta`, `Camera.eta` or `eta` of `uniform Camera { float eta; }`.
      const std::string member = b.name.substr(b.name.find('.') + 1);
      for (const std::string* source : {&program.vertex, &program.fragment})
        if (const std::string block = uniformBlockHolding(*source, member); !block.empty())
          throw UsageError(fmt::format(
              "{}:{}: `{}` is a member of the uniform block `{}`: [uniforms] binds uniforms "
              "declared outside a block only, and snell sets no block's members; declare it "
              "outside the block",
              manifest, b.line, member, block));
      throw UsageError(
          fmt::format("{}:{}: uniform `{}` is not declared in {}{}{}; check the "
                      "spelling against the listing",
                      manifest, b.line, b.name, m.vertexFile, m.fragmentFile.empty() ? "" : " or ",
                      m.fragmentFile));
    }
    auto bound = bindings.uniforms.find(b.name);
    if (bound == bindings.uniforms.end()) {
      if (declared->type.rfind("sampler", 0) != 0 && b.apiDefault)
        throw UsageError(fmt::format(
            "{}:{}: `{}` is a {}, which snell cannot set, \"default\" included: it sets float, "
            "vec2-4, mat3 and mat4 uniforms; declare it as a float in the listing you gate",
            manifest, b.line, b.name, declared->type));
      if (declared->type.rfind("sampler", 0) != 0)
        throw UsageError(fmt::format("{}:{}: `{}` is a {} but is bound to a texture", manifest,
                                     b.line, b.name, declared->type));
      // The scene's textures by the kind each sampler takes: a cube map
      // bound to a sampler2D was a Crash of every case, found by the
      // driver. ("default", no texture, is for a scene that runs no
      // fragment: the sweep's.)
      const char* takes = declared->type == "samplerCube" ? "environment"
                          : declared->type == "sampler2D" ? "decal"
                                                          : nullptr;
      if (const auto* semantic = std::get_if<std::string>(&b.source);
          takes && !b.apiDefault && semantic && *semantic != takes)
        throw UsageError(fmt::format(
            "{}:{}: `{}` is a {} but is bound to scene.{}, the scene's {}; bind \"scene.{}\"",
            manifest, b.line, b.name, declared->type, *semantic,
            *semantic == "environment" ? "cube map" : "2D texture", takes));
      continue;
    }
    if (declared->type != glslTypeName(bound->second.type))
      throw UsageError(fmt::format("{}:{}: `{}` is declared {} but bound to a {}", manifest, b.line,
                                   b.name, declared->type, glslTypeName(bound->second.type)));
  }
  for (const Binding& b : m.inputs) {
    if (legacyName(b.name) && b.apiDefault)
      throw UsageError(
          fmt::format("{}:{}: `{}` is fixed-function state: \"default\" is for the "
                      "listing's own uniforms and inputs; bind a scene semantic",
                      manifest, b.line, b.name));
    if (legacyName(b.name)) {
      checkLegacyBinding(m, b, false, bindings);
      continue;
    }
    const auto declared = find(vertex, {"in", "attribute"}, b.name);
    if (!declared)
      throw UsageError(
          fmt::format("{}:{}: input `{}` is not declared in {}; check the spelling "
                      "against the listing",
                      manifest, b.line, b.name, m.vertexFile));
    if (b.apiDefault) continue;
    const int components = bindings.attributes.at(b.name).components;
    const bool fits = (declared->type == "float" && components == 1) ||
                      (declared->type.size() == 4 && declared->type.rfind("vec", 0) == 0 &&
                       declared->type[3] - '0' <= components);
    if (!fits)
      throw UsageError(
          fmt::format("{}:{}: input `{}` is declared {} but its semantic gives {} "
                      "components",
                      manifest, b.line, b.name, declared->type, components));
  }
  checkEveryReadDeclarationIsBound(m, program);
  for (const std::string& name : m.captureVertex)
    if (!find(vertex, {"out", "varying"}, name))
      throw UsageError(
          fmt::format("{}:{}: capture.vertex names `{}`, which {} does not declare "
                      "as an output",
                      manifest, m.captureLine, name, m.vertexFile));
}

}  // namespace snell

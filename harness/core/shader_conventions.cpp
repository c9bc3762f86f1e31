#include "core/shader_conventions.h"

#include <algorithm>
#include <initializer_list>

namespace snell {
namespace {

struct Convention {
  const char* semantic;
  std::initializer_list<const char*> types;
  std::initializer_list<const char*> names;
  const char* why;
};

// Names a position is declared with, vec2 to vec4: the declared type
// decides how many of scene.position's components the input gets.
const Convention kInputs[] = {
    {"position",
     {"vec2", "vec3", "vec4"},
     {"aPos", "aPosition", "a_position", "position", "inPosition", "in_Position", "vertexPosition",
      "vertexPos", "MCvertex", "MCVertex", "vertex"},
     "the object-space position"},
    {"normal",
     {"vec3"},
     {"aNormal", "a_normal", "normal", "inNormal", "in_Normal", "vertexNormal", "MCnormal",
      "MCNormal"},
     "the object-space unit normal"},
    {"tangent",
     {"vec3"},
     {"aTangent", "a_tangent", "tangent", "inTangent", "Tangent", "vertexTangent"},
     "a unit tangent, perpendicular to the normal"},
    {"texcoord",
     {"vec2"},
     {"aTexCoords", "aTexCoord", "a_texcoord", "a_texCoord", "uv", "texCoord", "texcoord",
      "inTexCoord", "in_TexCoord", "TexCoord"},
     "the surface's (u, v) in [0, 1]"},
};

const Convention kUniforms[] = {
    {"model",
     {"mat4"},
     {"model", "modelMatrix", "u_model", "uModel", "uModelMatrix", "modelToWorld"},
     "model to world"},
    {"view",
     {"mat4"},
     {"view", "viewMatrix", "u_view", "uView", "uViewMatrix"},
     "world to eye: the camera alone"},
    {"projection",
     {"mat4"},
     {"projection", "projectionMatrix", "u_projection", "uProjection", "uProjectionMatrix",
      "ProjectionMatrix"},
     "eye to clip"},
    {"modelview",
     {"mat4"},
     {"modelView", "modelview", "modelViewMatrix", "MVMatrix", "u_modelView", "uModelView",
      "uModelViewMatrix", "ModelViewMatrix"},
     "view * model"},
    {"view_projection",
     {"mat4"},
     {"viewProjection", "viewProjectionMatrix", "viewProj", "VPMatrix", "u_viewProjection",
      "uViewProjection"},
     "projection * view"},
    {"modelview_projection",
     {"mat4"},
     {"mvp", "MVP", "MVPMatrix", "modelViewProj", "modelViewProjection",
      "modelViewProjectionMatrix", "ModelViewProjectionMatrix", "u_mvp", "uMVP",
      "uModelViewProjectionMatrix"},
     "projection * view * model"},
    {"eye_position",
     {"vec3"},
     {"cameraPos", "cameraPosition", "camPos", "viewPos", "eyePositionW", "worldCameraPosition",
      "u_cameraPosition", "uCameraPosition", "uCameraPos"},
     "the camera in world space"},
    {"texture_matrix",
     {"mat4"},
     {"TextureMatrix", "textureMatrix"},
     "turns and moves the environment apart from the object"},
    {"resolution", {"vec3"}, {"iResolution"}, "the viewport: width, height, 1 (Shadertoy)"},
};

bool among(const std::string& text, std::initializer_list<const char*> list) {
  return std::any_of(list.begin(), list.end(), [&](const char* item) { return text == item; });
}

std::optional<ConventionalBinding> lookUp(const GlslDeclaration& d, const Convention* begin,
                                          const Convention* end) {
  for (const Convention* c = begin; c != end; ++c)
    if (among(d.name, c->names) && among(d.type, c->types))
      return ConventionalBinding{c->semantic, c->why};
  return std::nullopt;
}

bool declaresSemantic(const std::vector<GlslDeclaration>& uniforms, const char* semantic) {
  return std::any_of(uniforms.begin(), uniforms.end(), [&](const GlslDeclaration& u) {
    const auto bound = lookUp(u, std::begin(kUniforms), std::end(kUniforms));
    return bound && bound->semantic == semantic;
  });
}

}  // namespace

std::optional<ConventionalBinding> conventionalInput(const GlslDeclaration& input) {
  return lookUp(input, std::begin(kInputs), std::end(kInputs));
}

std::optional<ConventionalBinding> conventionalUniform(
    const GlslDeclaration& uniform, const std::vector<GlslDeclaration>& uniforms) {
  // The scene has one cube map and one 2D texture: a sampler of either type
  // can only mean that one.
  if (uniform.type == "samplerCube")
    return ConventionalBinding{"environment", "the scene's cube map (its only one)"};
  if (uniform.type == "sampler2D")
    return ConventionalBinding{"decal", "the scene's 2D texture (its only one)"};
  if (uniform.type == "mat3" &&
      among(uniform.name, {"normalMatrix", "NormalMatrix", "u_normalMatrix", "uNormalMatrix"})) {
    if (declaresSemantic(uniforms, "modelview") ||
        declaresSemantic(uniforms, "modelview_projection"))
      return ConventionalBinding{"normal_matrix",
                                 "eye-space normals, beside a modelview matrix (three.js, the "
                                 "Orange Book)"};
    if (declaresSemantic(uniforms, "model"))
      return ConventionalBinding{"model_normal_matrix",
                                 "world-space normals, beside a model matrix (LearnOpenGL)"};
    return std::nullopt;
  }
  return lookUp(uniform, std::begin(kUniforms), std::end(kUniforms));
}

}  // namespace snell

#pragma once
// The fixed-function state that a legacy listing (GLSL 1.10/1.20 on an
// OpenGL compatibility context) reads through built-in names, as manifests,
// jobs and oracles name it: "gl_ModelViewMatrix", "gl_TextureMatrix[1]",
// "gl_Vertex". One table, so the manifest check, the OpenGL backend (which
// sets this state through the fixed-function API), the Vulkan adapter
// (which turns it into ordinary uniforms and inputs) and the oracles agree
// on names, types and on how derived state is computed.
#include <optional>
#include <string>
#include <vector>

#include "core/values.h"

namespace snell {

// Texture units whose matrix (gl_TextureMatrix[k]) and coordinates
// (gl_MultiTexCoordk) snell sets: the GL minimum for gl_MaxTextureCoords
// is 2; Mesa offers 8.
inline constexpr int kLegacyTextureUnits = 8;

enum class LegacyBuiltinKind {
  Matrix,         // set by the application: glLoadMatrixf in GL, a uniform on Vulkan
  DerivedMatrix,  // computed by GL from the matrices above; never set directly
  Attribute,      // a per-vertex input: glVertexPointer and friends in GL
};

struct LegacyBuiltin {
  std::string name;  // "gl_TextureMatrix[1]"
  LegacyBuiltinKind kind = LegacyBuiltinKind::Matrix;
  ValueType type = ValueType::Mat4;
  int unit = -1;  // texture unit of gl_TextureMatrix[k] and gl_MultiTexCoordk, else -1
};

// The built-in a manifest or a job names, or nullopt when `name` is none
// that snell knows (a misspelling, or one it does not set).
std::optional<LegacyBuiltin> findLegacyBuiltin(const std::string& name);

// For messages: every name a manifest may bind, uniforms then inputs,
// texture units written as a range ("gl_TextureMatrix[0..7]").
std::string legacyBindableNames();

// GL's derived state, computed from the given matrices the way GL defines
// it: gl_ModelViewProjectionMatrix = gl_ProjectionMatrix *
// gl_ModelViewMatrix, gl_NormalMatrix = transpose(inverse(mat3(
// gl_ModelViewMatrix))). Each is evaluated in double from the fp32 inputs
// and rounded once to fp32, the correctly rounded value of the definition,
// except that a modelview whose upper 3x3 is orthonormal to fp32 rounding
// (|column_a . column_b - delta_ab| <= 1e-6, a rigid camera) is its own
// inverse transpose and is taken as is, as GL implementations do. On Mesa
// (llvmpipe) both match the driver's own bits for every scene
// (tests/gl/gl_legacy_state_test.cpp). Returns `uniforms` with those
// entries added (replacing any given under the same names, since GL never
// takes them from the application); each is added only when what it
// derives from is there.
UniformMap withDerivedLegacyState(const UniformMap& uniforms);

}  // namespace snell

#pragma once
// The Vulkan legacy adapter: one explicit text transform that lets a legacy
// listing (GLSL 1.10/1.20, written for an OpenGL compatibility context) be
// compiled for Vulkan, where glslang takes `#version 140` with relaxed
// Vulkan rules but has no fixed-function state. OpenGL runs the same
// listing unchanged; only the Vulkan compile path calls this.
//
// What it maps, token by token (identifier boundaries respected; comments
// and the characters of every other token are left as they are):
//  - the version: a `#version` line becomes `#version 140` in place; a
//    source without one (GLSL 1.10) gets `#version 140` before its first
//    line;
//  - `attribute` -> `in` (vertex); `varying` -> `out` (vertex), `in`
//    (fragment);
//  - texture1D/2D/3D/Cube -> texture, texture1D/2D/3DProj -> textureProj,
//    texture1D/2D/3D/CubeLod -> textureLod, texture1D/2D/3DProjLod ->
//    textureProjLod;
//  - gl_FragColor -> `layout(location = 0) out vec4 snell_FragColor`
//    (fragment; the layout only where the text places other outputs with
//    layout(location) too, since glslang's automatic locations do not step
//    around explicit ones: alone, it lands at 0 either way), gl_FragData[N]
//    (N a literal) -> `layout(location = N) out vec4 snell_FragDataN`;
//  - gl_Vertex, gl_Normal, gl_MultiTexCoordN -> `in` vec4 snell_Vertex,
//    vec3 snell_Normal, vec4 snell_MultiTexCoordN (vertex);
//  - gl_ModelViewMatrix, gl_ProjectionMatrix, gl_ModelViewProjectionMatrix,
//    gl_NormalMatrix -> uniforms snell_ModelViewMatrix, ... (mat3 for the
//    normal matrix), gl_TextureMatrix[N] (N a literal) -> uniform mat4
//    snell_TextureMatrixN (both stages);
//  - ftransform() -> (snell_ModelViewProjectionMatrix * snell_Vertex), its
//    definition.
//  - gl_FragCoord -> snell_FragCoord(), which mirrors y back to OpenGL's
//    lower-left origin (Vulkan allows only an upper-left one) from the
//    framebuffer height the backend gives in `snell_FramebufferHeight`
//    (fragment).
// Only what the source uses is declared. Everything else passes through,
// including probe outputs a harness inserted before (`layout(location = k)
// out vec4 snell_probe_k;` and their writes): when the result uses
// layout(location), GL_ARB_explicit_attrib_location is enabled, which GLSL
// 1.40 needs for it.
//
// Every published line keeps its line number: the version, extension and
// declarations form a prologue of their own lines, ended by `#line N`,
// which in GLSL below 3.30 numbers the *following* line N + 1; replaced
// tokens never add or remove a line break. Diagnostics point at the
// published lines.
//
// What it cannot do, and so leaves for the compiler to report:
//  - GLSL 1.10's stricter rules are not enforced: 1.10 has no implicit
//    int -> float conversion, 1.40 does, so a listing that fails on OpenGL
//    for that reason alone (`660 * u`) compiles on Vulkan;
//  - built-ins it does not map (gl_Color, gl_TexCoord[], gl_FrontColor,
//    gl_LightSource[], the Inverse/Transpose matrices, gl_TextureMatrix or
//    gl_FragData with a non-literal index, shadow2D, ...) stay as written
//    and fail to compile;
//  - a legacy identifier that is a keyword or a built-in in 1.40 (a
//    variable named `texture`, `flat`, `layout`, `sample`) breaks.
// Values are bound under the gl_ names (see `renamings`); GL's derived
// state (gl_NormalMatrix, gl_ModelViewProjectionMatrix) is computed from
// the bound matrices by core/legacy_builtins.h, as OpenGL derives it.
#include <string>
#include <vector>

namespace snell {

enum class LegacyStage { Vertex, Fragment };

// The uniform through which a Vulkan render gives an adapted fragment
// shader its framebuffer's height in pixels (for gl_FragCoord).
inline constexpr const char* kFramebufferHeightUniform = "snell_FramebufferHeight";

// One built-in turned into an ordinary variable.
struct LegacyRenaming {
  enum class Kind { Uniform, Input, Output };
  Kind kind = Kind::Uniform;
  std::string builtin;  // as manifests and jobs name it: "gl_TextureMatrix[1]", "gl_Vertex"
  std::string renamed;  // the variable in the adapted text: "snell_TextureMatrix1"
};

struct LegacyAdapted {
  std::string text;
  std::vector<LegacyRenaming> renamings;  // each once, in the order they are declared
};

// Pure text in, text out; never throws for what the source contains.
LegacyAdapted adaptLegacyForVulkan(const std::string& source, LegacyStage stage);

}  // namespace snell

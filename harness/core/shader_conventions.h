#pragma once
// The names common conventions give the values a scene provides: LearnOpenGL's
// tutorials (aPos, model, view, projection, cameraPos, skybox), three.js's
// built-ins (position, modelMatrix, modelViewMatrix, normalMatrix,
// cameraPosition), the Orange Book's (MCvertex, MVMatrix, NormalMatrix) and
// the Cg Tutorial's. `snell init` binds a declaration to a semantic only when
// its name and type say which one; everything else is left to the author.
#include <optional>
#include <string>
#include <vector>

#include "core/glsl_declarations.h"

namespace snell {

struct ConventionalBinding {
  std::string semantic;  // without "scene."
  std::string why;       // one line for the manifest's comment
};

// The semantic a vertex input (`in`/`attribute` of the vertex stage) binds
// to, by name and type, or nothing.
std::optional<ConventionalBinding> conventionalInput(const GlslDeclaration& input);

// The semantic a uniform binds to, by name and type, or nothing. `uniforms`
// are all the listing's uniforms: a mat3 `normalMatrix` is the eye-space one
// beside a modelview matrix (three.js, the Orange Book), the world-space one
// beside a model matrix alone (LearnOpenGL), and left to the author with
// neither.
std::optional<ConventionalBinding> conventionalUniform(
    const GlslDeclaration& uniform, const std::vector<GlslDeclaration>& uniforms);

}  // namespace snell

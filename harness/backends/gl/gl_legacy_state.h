#pragma once
// The fixed-function state a legacy listing reads on the compatibility
// context, set through the fixed-function API from the values a job gives
// under the built-ins' names (core/legacy_builtins.h): gl_ModelViewMatrix,
// gl_ProjectionMatrix and "gl_TextureMatrix[k]" with glMatrixMode and
// glLoadMatrixf (glActiveTexture picks the unit), gl_Vertex, gl_Normal and
// gl_MultiTexCoordk with glVertexPointer, glNormalPointer and
// glTexCoordPointer. GL derives gl_NormalMatrix and
// gl_ModelViewProjectionMatrix itself; values given under those names are
// not used. A core context has none of this state and none of it is
// touched there.
#include <cstddef>
#include <string>
#include <vector>

#include "backends/gl/gl_api.h"
#include "core/values.h"

namespace snell {

// The fixed-function state a linked program reads, from GL's lists of
// active uniforms and attributes, where built-ins appear under their gl_
// names (with location -1).
struct GlLegacyReads {
  bool matrices = false;                // any transform matrix, or state derived from one
  std::vector<std::string> attributes;  // "gl_Vertex", "gl_Normal", "gl_MultiTexCoord0", ...
  bool reads(const std::string& attribute) const;
};
GlLegacyReads queryLegacyReads(GLuint program);

// Whether the current context is a compatibility context.
bool compatibilityContext();

// Throws UsageError for a matrix given under a gl_ name that is not a mat4
// of 16 floats, or for a texture unit the context does not have. Changes
// no state.
void checkLegacyMatrices(const UniformMap& uniforms);

// Loads the modelview, projection and every texture unit's matrix from the
// values given, and the identity where none is given, so that no job sees
// an earlier job's matrices. Leaves GL_MODELVIEW the matrix mode and unit 0
// the active texture.
void loadLegacyMatrices(const UniformMap& uniforms);

// Throws UsageError when a fixed-function array cannot take `stream`
// (glNormalPointer takes 3 components, glVertexPointer 2 to 4).
void checkLegacyAttribute(const AttributeStream& stream);

// Disables every fixed-function array of the bound vertex array
// (compatibility context only).
void disableLegacyArrays();

// Points the fixed-function array of built-in `name` at the start of the
// bound GL_ARRAY_BUFFER, `components` floats per vertex, and enables it.
void enableLegacyArray(const std::string& name, int components);

// For each built-in attribute the program reads and the job leaves out,
// sets GL's initial current value (gl_Normal (0, 0, 1), gl_MultiTexCoordk
// (0, 0, 0, 1)), so it does not keep whatever the last draw left.
void resetLegacyCurrentValues(const GlLegacyReads& reads, const AttributeMap& given);

}  // namespace snell

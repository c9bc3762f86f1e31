#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "backends/gl/gl_api.h"
#include "backends/gl/gl_program_cache.h"
#include "core/values.h"

namespace snell {

// The vertex array and buffers that feed a draw, kept for the life of a
// context so that captures and renders allocate no GL objects per call.
// Must be destroyed while its context is current.
class GlVertexInputs {
 public:
  GlVertexInputs();  // the context must be current
  GlVertexInputs(const GlVertexInputs&) = delete;
  GlVertexInputs& operator=(const GlVertexInputs&) = delete;
  ~GlVertexInputs();

  GLuint vertexArray() const { return vertexArray_; }

  // Throws UsageError for an attribute the program reads that does not hold
  // `vertexCount` vertices of 1 to 4 floats. Attributes the program lacks
  // are ignored. Needs no bound vertex array, so it can run before any state
  // is changed.
  static void check(GlLinkedProgram& program, const AttributeMap& attributes,
                    std::size_t vertexCount);

  // Uploads the first `vertexCount` vertices of each attribute the program
  // reads. The vertex array must be bound; attributes the program has but
  // the job leaves out read GL's generic value (0,0,0,1).
  void bindAttributes(GlLinkedProgram& program, const AttributeMap& attributes,
                      std::size_t vertexCount);

  // Uploads a triangle list into the vertex array's element buffer. The
  // vertex array must be bound.
  void bindIndices(const std::vector<std::uint32_t>& indices);

 private:
  void disableAttributes();

  GLuint vertexArray_ = 0;
  GLuint elementBuffer_ = 0;
  std::vector<GLuint> attributeBuffers_;  // grows to the most attributes a job used
  std::vector<GLuint> enabledLocations_;
};

}  // namespace snell

#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "backends/gl/gl_api.h"
#include "core/values.h"

namespace snell {

// Where each captured output sits in one interleaved transform feedback
// record, as the linked program reports it.
struct GlVaryingLayout {
  struct Field {
    std::string name;
    int components = 0;  // floats per vertex
    int offset = 0;      // floats from the start of the record
  };
  std::vector<Field> fields;
  int stride = 0;  // floats per vertex

  // Throws UsageError for an output that is not float-based: the capture
  // returns floats, and reinterpreting int bits as float would mislead.
  static GlVaryingLayout query(GLuint program);

  // Splits interleaved records into one CapturedVarying per field.
  std::vector<CapturedVarying> split(const std::vector<float>& records,
                                     std::size_t vertexCount) const;
};

}  // namespace snell

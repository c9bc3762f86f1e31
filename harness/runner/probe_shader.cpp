#include "runner/probe_shader.h"

#include <fmt/format.h>

namespace snell {

ProgramSource builtinProbeProgram(const std::string& fn, int width) {
  const char* type = width == 1 ? "float" : width == 2 ? "vec2" : width == 3 ? "vec3" : "vec4";
  const bool refract = fn == "refract";
  ProgramSource program;
  program.vertexPath = fmt::format("<{} probe, {}>", fn, type);
  program.vertex = fmt::format(
      "#version 140\n"
      "in {0} I;\n"
      "in {0} N;\n"
      "{1}"
      "out {0} R;\n"
      "void main()\n"
      "{{\n"
      "    R = {2};\n"
      "    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);\n"
      "}}\n",
      type, refract ? "in float eta;\n" : "", refract ? "refract(I, N, eta)" : "reflect(I, N)");
  return program;
}

}  // namespace snell

// The least a process that checks one refract on llvmpipe can take: load
// libOSMesa (and with it libLLVM), bring up a core 3.3 context, compile and
// link a vertex shader calling refract(), draw one point with transform
// feedback and read the vector back. Nothing of snell's is linked.
//
// bench/piglit/side_by_side times it beside piglit and `snell eval`: piglit's
// time divided by this one is the most that any process loading llvmpipe
// could gain over piglit, whatever it does after the driver is up.
//
// Prints the vector read back; exit 0 when it is refract()'s, 1 when the
// driver gave something else or failed. `snell_llvmpipe_floor ETA` checks it
// against refract() with another eta than the shader's 0.66 (its test shows
// the check refusing a wrong vector that way); 2 for an ETA that is not a
// number.
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace {

// I = (0.6, -0.8, 0), N = (0, 1, 0), eta = 0.66: k = 1 - 0.66^2 * 0.36 > 0,
// so the refracted ray is eta * I - (eta * dot(N, I) + sqrt(k)) * N.
constexpr const char* kVertex = R"(#version 330 core
layout(location = 0) in vec3 I;
layout(location = 1) in vec3 N;
out vec3 refracted;
void main() {
  refracted = refract(I, N, 0.66);
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
)";
constexpr const char* kFragment = R"(#version 330 core
out vec4 colour;
void main() { colour = vec4(1.0); }
)";

// The shader, or 0 after printing the compiler's log.
GLuint compiled(GLenum stage, const char* text) {
  const GLuint shader = glCreateShader(stage);
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok == GL_TRUE) return shader;
  std::array<char, 4096> log{};
  glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
  std::fprintf(stderr, "llvmpipe_floor: a shader did not compile:\n%s\n", log.data());
  return 0;
}

bool nearlyRefract(const std::array<float, 3>& r, double eta) {
  const double d = -0.8;
  const double k = 1.0 - eta * eta * (1.0 - d * d);
  const double t = eta * d + std::sqrt(k);
  const std::array<double, 3> expected{eta * 0.6, eta * -0.8 - t, 0.0};
  for (int c = 0; c < 3; ++c)
    if (!(std::fabs(r[c] - expected[c]) < 1e-5)) return false;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  double eta = 0.66;
  if (argc > 1) {
    char* end = nullptr;
    eta = std::strtod(argv[1], &end);
    if (argc > 2 || end == argv[1] || *end != '\0') {
      std::fprintf(stderr, "usage: snell_llvmpipe_floor [ETA], ETA a number (default 0.66)\n");
      return 2;
    }
  }
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  const OSMesaContext context = OSMesaCreateContextAttribs(attributes, nullptr);
  static std::array<unsigned char, 16 * 16 * 4> pixels{};
  if (!context || !OSMesaMakeCurrent(context, pixels.data(), GL_UNSIGNED_BYTE, 16, 16)) {
    std::fprintf(stderr, "llvmpipe_floor: no OSMesa core 3.3 context\n");
    return 1;
  }
  const GLuint vertex = compiled(GL_VERTEX_SHADER, kVertex);
  const GLuint fragment = compiled(GL_FRAGMENT_SHADER, kFragment);
  const GLuint program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  const char* captured[] = {"refracted"};
  glTransformFeedbackVaryings(program, 1, captured, GL_INTERLEAVED_ATTRIBS);
  glLinkProgram(program);
  GLint linked = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  if (!vertex || !fragment || linked != GL_TRUE) {
    std::array<char, 4096> log{};
    glGetProgramInfoLog(program, static_cast<GLsizei>(log.size()), nullptr, log.data());
    std::fprintf(stderr, "llvmpipe_floor: the refract program did not build:\n%s\n", log.data());
    return 1;
  }
  glUseProgram(program);

  GLuint vertexArray = 0, inputs = 0, feedback = 0;
  glGenVertexArrays(1, &vertexArray);
  glBindVertexArray(vertexArray);
  const std::array<float, 6> IN{0.6f, -0.8f, 0.0f, 0.0f, 1.0f, 0.0f};
  glGenBuffers(1, &inputs);
  glBindBuffer(GL_ARRAY_BUFFER, inputs);
  glBufferData(GL_ARRAY_BUFFER, sizeof IN, IN.data(), GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float),
                        reinterpret_cast<const void*>(3 * sizeof(float)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  std::array<float, 3> refracted{};
  glGenBuffers(1, &feedback);
  glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, feedback);
  glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, sizeof refracted, nullptr, GL_STREAM_READ);
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, feedback);

  glEnable(GL_RASTERIZER_DISCARD);
  glBeginTransformFeedback(GL_POINTS);
  glDrawArrays(GL_POINTS, 0, 1);
  glEndTransformFeedback();
  glFinish();
  glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, sizeof refracted, refracted.data());
  const GLenum error = glGetError();
  OSMesaDestroyContext(context);

  std::printf("%.9g %.9g %.9g\n", refracted[0], refracted[1], refracted[2]);
  if (error != GL_NO_ERROR || !nearlyRefract(refracted, eta)) {
    std::fprintf(stderr, "llvmpipe_floor: GL error 0x%x, or not refract()'s vector\n", error);
    return 1;
  }
  return 0;
}

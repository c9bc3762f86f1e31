#include "backends/gl/gl_program_build.h"

#include <utility>

#include "backends/gl/gl_diagnostics.h"
#include "backends/gl/gl_error_check.h"

namespace snell {

GlProgram::GlProgram(GlProgram&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

GlProgram& GlProgram::operator=(GlProgram&& other) noexcept {
  if (this != &other) {
    if (id_) glDeleteProgram(id_);
    id_ = std::exchange(other.id_, 0);
  }
  return *this;
}

GlProgram::~GlProgram() {
  if (id_) glDeleteProgram(id_);
}

namespace {

// Shader objects are only needed until the link; the program keeps the code.
class GlShader {
 public:
  explicit GlShader(GLenum stage) : id_(glCreateShader(stage)) {}
  GlShader(const GlShader&) = delete;
  GlShader& operator=(const GlShader&) = delete;
  ~GlShader() { glDeleteShader(id_); }
  GLuint id() const { return id_; }

 private:
  GLuint id_;
};

// Shader and program logs are fetched the same way through different calls.
template <typename GetLength, typename GetLog>
std::string infoLog(GLuint object, GetLength getLength, GetLog getLog) {
  GLint capacity = 0;
  getLength(object, GL_INFO_LOG_LENGTH, &capacity);
  if (capacity <= 1) return "";
  std::string log(static_cast<std::size_t>(capacity), '\0');
  GLsizei written = 0;
  getLog(object, capacity, &written, log.data());
  log.resize(static_cast<std::size_t>(written));
  return log;
}

std::string shaderLog(GLuint shader) { return infoLog(shader, glGetShaderiv, glGetShaderInfoLog); }
std::string programLog(GLuint program) {
  return infoLog(program, glGetProgramiv, glGetProgramInfoLog);
}

std::string labelled(const std::string& label, const std::string& path) {
  return path.empty() ? label : label + " (" + path + ")";
}

// Appends a diagnostic block to `log`, headed so a reader knows which file
// of which stage it is about.
void appendLog(std::string& log, const std::string& heading, const std::string& text) {
  if (text.empty()) return;
  if (!log.empty() && log.back() != '\n') log += '\n';
  log += heading + ":\n" + text;
}

bool compileStage(GlShader& shader, const std::string& text, const std::string& stage,
                  const std::string& heading, CompileOutcome& outcome) {
  std::string& log = outcome.log;
  const char* source = text.c_str();
  const GLint length = static_cast<GLint>(text.size());
  glShaderSource(shader.id(), 1, &source, &length);
  glCompileShader(shader.id());
  GLint status = GL_FALSE;
  glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &status);
  std::string stageLog = shaderLog(shader.id());
  if (status != GL_TRUE && stageLog.empty())
    stageLog = "compilation failed (the driver gave no log)";
  appendLog(log, heading, stageLog);
  for (CompileDiagnostic& d : gl::parseInfoLog(stage, stageLog))
    outcome.diagnostics.push_back(std::move(d));
  return status == GL_TRUE;
}

}  // namespace

BuiltProgram buildGlProgram(const ProgramSource& source,
                            const std::vector<std::string>& feedbackVaryings) {
  BuiltProgram built;
  std::string& log = built.outcome.log;

  GlShader vertex(GL_VERTEX_SHADER);
  bool compiled = compileStage(vertex, source.vertex, "vertex",
                               labelled("vertex shader", source.vertexPath), built.outcome);

  const bool hasFragment = !source.fragment.empty();
  GlShader fragment(GL_FRAGMENT_SHADER);
  // Both stages are compiled even when the first fails, so one run reports
  // every error.
  if (hasFragment)
    compiled &= compileStage(fragment, source.fragment, "fragment",
                             labelled("fragment shader", source.fragmentPath), built.outcome);
  throwOnGlError("glCompileShader");
  if (!compiled) return built;

  GlProgram program(glCreateProgram());
  glAttachShader(program.id(), vertex.id());
  if (hasFragment) glAttachShader(program.id(), fragment.id());
  if (!feedbackVaryings.empty()) {
    std::vector<const char*> names;
    for (const auto& name : feedbackVaryings) names.push_back(name.c_str());
    glTransformFeedbackVaryings(program.id(), static_cast<GLsizei>(names.size()), names.data(),
                                GL_INTERLEAVED_ATTRIBS);
  }
  glLinkProgram(program.id());
  GLint linked = GL_FALSE;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &linked);
  std::string linkLog = programLog(program.id());
  if (linked != GL_TRUE && linkLog.empty()) linkLog = "link failed (the driver gave no log)";
  std::string heading = "program link";
  if (!source.vertexPath.empty() || !source.fragmentPath.empty())
    heading += " (" + source.vertexPath +
               (source.fragmentPath.empty() ? "" : " + " + source.fragmentPath) + ")";
  appendLog(log, heading, linkLog);
  throwOnGlError("glLinkProgram");

  if (linked != GL_TRUE) return built;
  if (hasFragment) {
    if (!bindOutputLocations(program.id())) {
      appendLog(log, heading,
                "relinking with the fragment outputs bound to their locations failed:\n" +
                    programLog(program.id()));
      return built;
    }
    built.fragmentOutputs = queryFragmentOutputs(program.id());
    throwOnGlError("querying the fragment shader outputs");
  }
  glDetachShader(program.id(), vertex.id());
  if (hasFragment) glDetachShader(program.id(), fragment.id());
  built.program = std::move(program);
  built.outcome.ok = true;
  return built;
}

}  // namespace snell

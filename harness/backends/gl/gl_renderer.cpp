#include "backends/gl/gl_renderer.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <string>

#include "backends/gl/gl_cube_samplers.h"
#include "backends/gl/gl_error_check.h"
#include "core/errors.h"
#include "core/phase_clock.h"

namespace snell {

namespace {

void checkJob(const GlLinkedProgram& program, const RenderJob& job) {
  if (job.width <= 0 || job.height <= 0)
    throw UsageError("render size " + std::to_string(job.width) + "x" + std::to_string(job.height) +
                     " is empty");
  if (job.indices.size() % 3 != 0)
    throw UsageError("render job has " + std::to_string(job.indices.size()) +
                     " indices; a triangle list needs a multiple of 3");
  if (job.program.fragment.empty())
    throw UsageError("a render needs a fragment shader; the program has only a vertex shader");
  // Legacy gl_FragColor is not listed among the outputs, and writes every
  // draw buffer.
  const auto& outputs = program.fragmentOutputs;
  if (outputs.empty()) return;
  const bool atZero =
      std::any_of(outputs.begin(), outputs.end(),
                  [](const GlFragmentOutput& output) { return output.location == 0; });
  if (atZero) return;
  std::string declared;
  for (const GlFragmentOutput& output : outputs)
    declared += (declared.empty() ? "" : ", ") + output.name + " at location " +
                std::to_string(output.location);
  throw UsageError("the fragment shader writes no output at location 0, which renders read (" +
                   declared + ")");
}

std::size_t vertexCountOf(const std::vector<std::uint32_t>& indices) {
  if (indices.empty()) return 0;
  return static_cast<std::size_t>(*std::max_element(indices.begin(), indices.end())) + 1;
}

// Binds what a render draws with and puts back, whichever way the render
// leaves, the state captures and compile checks assume: no program, vertex
// array, framebuffer or textures (cube or 2D) bound, depth test and culling off.
class RenderStateGuard {
 public:
  RenderStateGuard(GLuint program, GLuint vertexArray, GLuint framebuffer, int textureUnits)
      : textureUnits_(textureUnits) {
    glUseProgram(program);
    glBindVertexArray(vertexArray);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  }
  RenderStateGuard(const RenderStateGuard&) = delete;
  RenderStateGuard& operator=(const RenderStateGuard&) = delete;
  ~RenderStateGuard() {
    for (int unit = textureUnits_ - 1; unit >= 0; --unit) {
      glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
      glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
      glBindTexture(GL_TEXTURE_2D, 0);
    }
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindVertexArray(0);
    glUseProgram(0);
  }

 private:
  int textureUnits_;
};

// Everything that decides which fragments land and how, set on every render
// so that no earlier call (or a compatibility context's defaults) leaks in.
void setRasterState(const RenderJob& job) {
  glDisable(GL_RASTERIZER_DISCARD);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_DITHER);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glViewport(0, 0, job.width, job.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glFrontFace(GL_CCW);
  glCullFace(GL_BACK);
  if (job.cullBackFaces)
    glEnable(GL_CULL_FACE);
  else
    glDisable(GL_CULL_FACE);
  glClearColor(job.clearColor[0], job.clearColor[1], job.clearColor[2], job.clearColor[3]);
  glClearDepth(1.0);
  throwOnGlError("setting the render state (viewport, depth test, culling, clear values)");
}

void bindCubeMaps(const GlSamplerPlan& plan, GlCubeTextures& textures) {
  textures.beginJob();
  for (std::size_t unit = 0; unit < plan.bindings.size(); ++unit) {
    textures.bind(*plan.bindings[unit].map, static_cast<int>(unit));
    glUniform1i(plan.bindings[unit].location, static_cast<GLint>(unit));
  }
  if (plan.seamless)
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  else
    glDisable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  throwOnGlError("binding cube map samplers (glUniform1i, GL_TEXTURE_CUBE_MAP_SEAMLESS)");
}

// 2D textures take the units after the cube maps.
void bindTextures2D(const GlSamplerPlan& plan, GlTextures2D& textures) {
  textures.beginJob();
  const std::size_t first = plan.bindings.size();
  for (std::size_t k = 0; k < plan.textures2D.size(); ++k) {
    const auto unit = static_cast<int>(first + k);
    textures.bind(*plan.textures2D[k].image, unit);
    glUniform1i(plan.textures2D[k].location, static_cast<GLint>(unit));
  }
  throwOnGlError("binding 2D texture samplers (glBindTexture, glUniform1i)");
}

// The listing's target is cleared to the job's colour, each probe's to 0:
// alpha 0 marks a pixel its write never reached.
void clearTargets(const RenderJob& job, int colourTargets) {
  glClearBufferfv(GL_COLOR, 0, job.clearColor.data());
  const std::array<float, 4> unwritten{0, 0, 0, 0};
  for (int k = 1; k < colourTargets; ++k) glClearBufferfv(GL_COLOR, k, unwritten.data());
  const float depth = 1.0f;
  glClearBufferfv(GL_DEPTH, 0, &depth);
  throwOnGlError("glClearBufferfv");
}

// GL's row 0 is the bottom of the image; Image's is the top.
Image readBack(int width, int height, int attachment) {
  const std::size_t rowFloats = static_cast<std::size_t>(width) * 4;
  std::vector<float> bottomUp(rowFloats * static_cast<std::size_t>(height));
  glReadBuffer(static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + attachment));
  glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, bottomUp.data());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  throwOnGlError("glReadPixels(GL_RGBA, GL_FLOAT)");
  Image image(width, height);
  for (int row = 0; row < height; ++row)
    std::memcpy(image.at(0, row), &bottomUp[static_cast<std::size_t>(height - 1 - row) * rowFloats],
                rowFloats * sizeof(float));
  return image;
}

}  // namespace

std::vector<Image> GlRenderer::run(GlLinkedProgram& program, const RenderJob& job) {
  checkJob(program, job);
  const std::size_t vertexCount = vertexCountOf(job.indices);
  GlVertexInputs::check(program, job.attributes, vertexCount);
  const GlSamplerPlan samplers =
      planSamplers(program.uniforms.samplers(), job.cubeMaps, job.textures2D);
  const int colourTargets = 1 + static_cast<int>(job.probes.size());

  // The render target's allocation (on a size's first use) is the draw's,
  // as the Vulkan backend's is.
  const PhaseScope phase(Phase::Draw);
  GlFramebuffer& target = framebuffers_.get(job.width, job.height, colourTargets);
  RenderStateGuard guard(program.program.id(), inputs_.vertexArray(), target.id(),
                         samplers.units());
  program.uniforms.apply(job.uniforms);
  throwOnGlError("glUniform*");
  bindCubeMaps(samplers, cubeTextures_);
  bindTextures2D(samplers, textures2D_);
  inputs_.bindAttributes(program, job.attributes, vertexCount);
  inputs_.bindIndices(job.indices);
  setRasterState(job);

  clearTargets(job, colourTargets);
  if (!job.indices.empty()) {
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(job.indices.size()), GL_UNSIGNED_INT,
                   nullptr);
    throwOnGlError("glDrawElements(GL_TRIANGLES, GL_UNSIGNED_INT)");
  }
  glFinish();  // the draw's time is the draw's, not the read-back's
  const PhaseScope reading(Phase::ReadBack);
  std::vector<Image> images;
  for (int k = 0; k < colourTargets; ++k) images.push_back(readBack(job.width, job.height, k));
  return images;
}

}  // namespace snell

#include "backends/vk/glsl_to_spirv.h"

#include "backends/vk/glslang_diagnostics.h"

#include <glslang/Include/Types.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <memory>
#include <sstream>

#include "backends/vk/spirv_validate.h"
#include "core/errors.h"
#include "backends/vk/legacy_adapter.h"

namespace snell::vk {

namespace {

constexpr auto kMessages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);

// glslang keeps process-wide tables; they live until the process exits.
void ensureGlslangInitialised() {
  struct Process {
    Process() { glslang::InitializeProcess(); }
    ~Process() { glslang::FinalizeProcess(); }
  };
  static Process process;
}

std::string displayName(const std::string& path, const char* fallback) {
  return path.empty() ? fallback : path;
}

// glslang names the file in located messages (we hand it the path as the
// string name) but not in summaries such as "2 compilation errors"; give
// every line a file so that a log line on its own still says where it is from.
void appendLog(std::string& log, const std::string& text, const std::string& file) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (line.find(file) == std::string::npos) line = file + ": " + line;
    log += line + "\n";
  }
}

std::unique_ptr<glslang::TShader> parseStage(EShLanguage stage, const std::string& source,
                                             const std::string& file, VulkanProgram& result) {
  std::string& log = result.log;
  auto shader = std::make_unique<glslang::TShader>(stage);
  const char* text = source.c_str();
  const int length = static_cast<int>(source.size());
  const char* name = file.c_str();
  shader->setStringsWithLengthsAndNames(&text, &length, &name, 1);
  shader->setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
  // Relaxed rules let a GL-style listing compile for Vulkan unchanged: loose
  // uniforms go to gl_DefaultUniformBlock, locations and bindings get mapped.
  shader->setEnvInputVulkanRulesRelaxed();
  shader->setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
  shader->setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
  shader->setAutoMapLocations(true);
  shader->setAutoMapBindings(true);
  const bool ok = shader->parse(GetDefaultResources(), 100, false, kMessages);
  appendLog(log, shader->getInfoLog(), file);
  for (CompileDiagnostic& d :
       parseGlslangLog(stage == EShLangVertex ? "vertex" : "fragment", shader->getInfoLog()))
    result.diagnostics.push_back(std::move(d));
  return ok ? std::move(shader) : nullptr;
}

std::optional<ValueType> valueTypeOf(int glDefineType) {
  switch (glDefineType) {
    case 0x1406:
      return ValueType::Float;  // GL_FLOAT
    case 0x8B50:
      return ValueType::Vec2;  // GL_FLOAT_VEC2
    case 0x8B51:
      return ValueType::Vec3;  // GL_FLOAT_VEC3
    case 0x8B52:
      return ValueType::Vec4;  // GL_FLOAT_VEC4
    case 0x8B5B:
      return ValueType::Mat3;  // GL_FLOAT_MAT3
    case 0x8B5C:
      return ValueType::Mat4;  // GL_FLOAT_MAT4
    default:
      return std::nullopt;
  }
}

std::string declaredType(const glslang::TType* type) {
  if (!type) return "an unknown type";
  return type->getCompleteString(true, false, false).c_str();
}

std::optional<UniformBlockLayout> reflectDefaultBlock(const glslang::TProgram& program) {
  int blockIndex = -1;
  for (int i = 0; i < program.getNumUniformBlocks(); ++i) {
    if (program.getUniformBlock(i).name == kDefaultUniformBlock) blockIndex = i;
  }
  if (blockIndex < 0) return std::nullopt;
  const glslang::TObjectReflection& block = program.getUniformBlock(blockIndex);
  UniformBlockLayout layout;
  layout.size = static_cast<std::size_t>(block.size);
  const glslang::TQualifier& qualifier = block.getType()->getQualifier();
  if (qualifier.layoutPacking == glslang::ElpStd430) {
    layout.packing = BlockPacking::Std430;
  } else if (qualifier.layoutPacking != glslang::ElpStd140) {
    throw SetupError(std::string(kDefaultUniformBlock) +
                     " has a packing other than std140/std430; this glslang is not supported");
  }
  if (qualifier.layoutMatrix == glslang::ElmRowMajor) {
    throw SetupError(std::string(kDefaultUniformBlock) +
                     " is row-major; this glslang is not supported");
  }
  for (int i = 0; i < program.getNumUniformVariables(); ++i) {
    const glslang::TObjectReflection& uniform = program.getUniform(i);
    if (uniform.index != blockIndex) continue;
    BlockMember member;
    member.name = uniform.name;
    member.offset = static_cast<std::size_t>(uniform.offset);
    const bool array = uniform.size > 1 || (uniform.getType() && uniform.getType()->isArray());
    if (!array) member.type = valueTypeOf(uniform.glDefineType);
    member.declaredType = declaredType(uniform.getType());
    layout.members.push_back(std::move(member));
  }
  return layout;
}

std::vector<VertexInput> reflectVertexInputs(const glslang::TProgram& program) {
  std::vector<VertexInput> inputs;
  for (int i = 0; i < program.getNumPipeInputs(); ++i) {
    const glslang::TObjectReflection& input = program.getPipeInput(i);
    const glslang::TType* type = input.getType();
    VertexInput entry;
    entry.name = input.name;
    entry.declaredType = declaredType(type);
    // mapIO() has written the assigned locations into the reflected types.
    if (type && type->getQualifier().hasLocation())
      entry.location = type->getQualifier().layoutLocation;
    if (type && type->getBasicType() == glslang::EbtFloat && !type->isArray() &&
        !type->isMatrix() && !type->isStruct()) {
      entry.components = type->isScalar() ? 1 : type->getVectorSize();
    }
    inputs.push_back(std::move(entry));
  }
  return inputs;
}

// Values come under the names the listing uses (gl_ModelViewMatrix,
// gl_Vertex); the adapted program reads them as snell_ variables. Naming
// the reflected members and inputs back lets the rest of the backend bind
// them as any other. GL's derived state is not bound by anyone: it is
// computed from the given matrices when the block is packed.
void bindUnderBuiltinNames(const std::vector<LegacyRenaming>& renamings, VulkanProgram& program) {
  auto builtinOf = [&](std::string& name) {
    for (const LegacyRenaming& renaming : renamings)
      if (renaming.renamed == name) name = renaming.builtin;
  };
  if (program.uniformBlock) {
    for (BlockMember& member : program.uniformBlock->members) builtinOf(member.name);
    program.uniformBlock->derivesLegacyState = true;
  }
  for (VertexInput& input : program.vertexInputs) builtinOf(input.name);
}

std::vector<std::uint32_t> generateSpirv(glslang::TProgram& program, EShLanguage stage,
                                         const std::string& file, std::string& log) {
  std::vector<std::uint32_t> spirv;
  spv::SpvBuildLogger logger;
  glslang::SpvOptions options;
  options.disableOptimizer = true;  // keep the listing's arithmetic as written
  glslang::GlslangToSpv(*program.getIntermediate(stage), spirv, &logger, &options);
  appendLog(log, logger.getAllMessages(), file);
  return spirv;
}

}  // namespace

VulkanProgram compileForVulkan(const ProgramSource& source) {
  ensureGlslangInitialised();
  VulkanProgram result;
  const std::string vertexFile = displayName(source.vertexPath, "<vertex shader>");
  const std::string fragmentFile = displayName(source.fragmentPath, "<fragment shader>");
  const bool hasFragment = !source.fragment.empty();
  // A legacy listing goes through the one documented adapter
  // (core/legacy_adapter.h): its text stays as published everywhere else.
  const bool legacy = source.profile == Profile::Compatibility;
  LegacyAdapted vertexText{source.vertex, {}};
  LegacyAdapted fragmentText{source.fragment, {}};
  if (legacy) {
    vertexText = adaptLegacyForVulkan(source.vertex, LegacyStage::Vertex);
    if (hasFragment) fragmentText = adaptLegacyForVulkan(source.fragment, LegacyStage::Fragment);
  }

  auto vertex = parseStage(EShLangVertex, vertexText.text, vertexFile, result);
  std::unique_ptr<glslang::TShader> fragment;
  if (hasFragment)
    fragment = parseStage(EShLangFragment, fragmentText.text, fragmentFile, result);
  if (!vertex || (hasFragment && !fragment)) return result;

  // Declared after the shaders so that it is destroyed first: it points at them.
  glslang::TProgram program;
  program.addShader(vertex.get());
  if (fragment) program.addShader(fragment.get());
  const std::string linkFile = hasFragment ? vertexFile + ", " + fragmentFile : vertexFile;
  const bool linked = program.link(kMessages) && program.mapIO();
  appendLog(result.log, program.getInfoLog(), linkFile);
  if (!linked) return result;
  if (!program.buildReflection(EShReflectionDefault)) {
    appendLog(result.log, "glslang could not build reflection data", linkFile);
    return result;
  }

  result.uniformBlock = reflectDefaultBlock(program);
  result.vertexInputs = reflectVertexInputs(program);
  if (legacy) {
    std::vector<LegacyRenaming> renamings = vertexText.renamings;
    renamings.insert(renamings.end(), fragmentText.renamings.begin(), fragmentText.renamings.end());
    bindUnderBuiltinNames(renamings, result);
  }
  result.vertexSpirv = generateSpirv(program, EShLangVertex, vertexFile, result.log);
  if (fragment)
    result.fragmentSpirv = generateSpirv(program, EShLangFragment, fragmentFile, result.log);

  std::string invalid = validateSpirvForVulkan(result.vertexSpirv);
  appendLog(result.log, invalid, vertexFile);
  if (fragment) {
    const std::string fragmentInvalid = validateSpirvForVulkan(result.fragmentSpirv);
    appendLog(result.log, fragmentInvalid, fragmentFile);
    invalid += fragmentInvalid;
  }
  result.ok = invalid.empty();
  return result;
}

}  // namespace snell::vk

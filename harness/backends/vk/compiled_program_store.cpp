#include "backends/vk/compiled_program_store.h"

#include "core/build_id.h"
#include "core/sealed_record.h"

namespace snell::vk {
namespace {

RecordTag programTag() { return recordTag("snellspv", /*format=*/1, /*kind=*/1); }

void put(ByteWriter& w, const CompileDiagnostic& d) {
  w.put(d.stage);
  w.put(static_cast<std::int32_t>(d.line));
  w.put(static_cast<std::uint8_t>(d.error));
  w.put(d.message);
}

CompileDiagnostic getDiagnostic(ByteReader& r) {
  CompileDiagnostic d;
  d.stage = r.getString();
  d.line = r.get<std::int32_t>();
  d.error = r.get<std::uint8_t>() != 0;
  d.message = r.getString();
  return d;
}

// A member's type: 0 for none (a type snell cannot bind), else the
// ValueType plus one.
constexpr std::uint8_t kLastValueType = static_cast<std::uint8_t>(ValueType::Mat4);

void put(ByteWriter& w, const UniformBlockLayout& block) {
  w.put(static_cast<std::uint8_t>(block.packing));
  w.put(static_cast<std::uint64_t>(block.size));
  w.put(static_cast<std::uint8_t>(block.derivesLegacyState));
  w.put(static_cast<std::uint64_t>(block.members.size()));
  for (const BlockMember& m : block.members) {
    w.put(m.name);
    w.put(static_cast<std::uint64_t>(m.offset));
    w.put(static_cast<std::uint8_t>(m.type ? static_cast<std::uint8_t>(*m.type) + 1 : 0));
    w.put(m.declaredType);
  }
}

UniformBlockLayout getBlock(ByteReader& r) {
  UniformBlockLayout block;
  const auto packing = r.get<std::uint8_t>();
  if (packing > static_cast<std::uint8_t>(BlockPacking::Std430)) r.fail();
  block.packing = static_cast<BlockPacking>(packing);
  block.size = r.get<std::uint64_t>();
  block.derivesLegacyState = r.get<std::uint8_t>() != 0;
  const auto count = r.get<std::uint64_t>();
  for (std::uint64_t k = 0; r.ok() && k < count; ++k) {
    BlockMember m;
    m.name = r.getString();
    m.offset = r.get<std::uint64_t>();
    const auto type = r.get<std::uint8_t>();
    if (type > kLastValueType + 1) r.fail();
    if (type > 0) m.type = static_cast<ValueType>(type - 1);
    m.declaredType = r.getString();
    block.members.push_back(std::move(m));
  }
  return block;
}

}  // namespace

Digest compiledProgramKey(const ProgramSource& source) {
  static const std::string build =
      buildIdContaining(reinterpret_cast<const void*>(&compileForVulkan));
  ContentHash hash;
  hash.add(std::string_view("vk compiled program"));
  hash.add(std::string_view(build));
  hash.add(source.profile);
  hash.add(std::string_view(source.vertex));
  hash.add(std::string_view(source.fragment));
  // The paths are in the log and the diagnostics.
  hash.add(std::string_view(source.vertexPath));
  hash.add(std::string_view(source.fragmentPath));
  return hash.finish();
}

std::string encodeCompiledProgram(const Digest& key, const VulkanProgram& program) {
  ByteWriter w;
  w.put(static_cast<std::uint8_t>(program.ok));
  w.put(program.log);
  w.put(static_cast<std::uint64_t>(program.diagnostics.size()));
  for (const CompileDiagnostic& d : program.diagnostics) put(w, d);
  w.putArray(program.vertexSpirv);
  w.putArray(program.fragmentSpirv);
  w.put(static_cast<std::uint8_t>(program.uniformBlock.has_value()));
  if (program.uniformBlock) put(w, *program.uniformBlock);
  w.put(static_cast<std::uint64_t>(program.vertexInputs.size()));
  for (const VertexInput& input : program.vertexInputs) {
    w.put(input.name);
    w.put(input.location);
    w.put(static_cast<std::int32_t>(input.components));
    w.put(input.declaredType);
  }
  return sealRecord(programTag(), key, w.take());
}

std::optional<VulkanProgram> decodeCompiledProgram(const Digest& key, std::string_view bytes) {
  const std::optional<std::string_view> payload = openRecord(programTag(), key, bytes);
  if (!payload) return std::nullopt;
  ByteReader r(*payload);
  VulkanProgram program;
  const auto ok = r.get<std::uint8_t>();
  if (ok > 1) r.fail();
  program.ok = ok == 1;
  program.log = r.getString();
  const auto diagnostics = r.get<std::uint64_t>();
  for (std::uint64_t k = 0; r.ok() && k < diagnostics; ++k)
    program.diagnostics.push_back(getDiagnostic(r));
  program.vertexSpirv = r.getArray<std::uint32_t>();
  program.fragmentSpirv = r.getArray<std::uint32_t>();
  const auto hasBlock = r.get<std::uint8_t>();
  if (hasBlock > 1) r.fail();
  if (hasBlock == 1) program.uniformBlock = getBlock(r);
  const auto inputs = r.get<std::uint64_t>();
  for (std::uint64_t k = 0; r.ok() && k < inputs; ++k) {
    VertexInput input;
    input.name = r.getString();
    input.location = r.get<std::uint32_t>();
    input.components = r.get<std::int32_t>();
    input.declaredType = r.getString();
    program.vertexInputs.push_back(std::move(input));
  }
  // A program that compiled has a vertex stage.
  if (!r.ok() || !r.atEnd() || (program.ok && program.vertexSpirv.empty())) return std::nullopt;
  return program;
}

CompiledProgramStore::CompiledProgramStore(std::filesystem::path dir) {
  if (!dir.empty()) files_.emplace(std::move(dir));
}

VulkanProgram CompiledProgramStore::compile(const ProgramSource& source) const {
  if (!files_) return compileForVulkan(source);
  return files_->keptOrComputed(compiledProgramKey(source), decodeCompiledProgram,
                                encodeCompiledProgram, [&] { return compileForVulkan(source); });
}

}  // namespace snell::vk

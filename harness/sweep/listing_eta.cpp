#include "sweep/listing_eta.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <regex>

namespace snell::sweep {
namespace {

bool namedEta(const std::string& name) {
  return name.size() >= 3 && std::tolower(static_cast<unsigned char>(name[0])) == 'e' &&
         std::tolower(static_cast<unsigned char>(name[1])) == 't' &&
         std::tolower(static_cast<unsigned char>(name[2])) == 'a';
}

// Replaces the number of `const float NAME = number;` in `text`; false when
// the line is not there.
bool replaceConstant(std::string& text, const std::string& name, const std::string& literal) {
  const std::regex line("(const\\s+float\\s+" + name + "\\s*=\\s*)([-+0-9.eEf]+)(\\s*;)");
  std::smatch match;
  if (!std::regex_search(text, match, line)) return false;
  // Spliced by position: a format string's $N would read the literal's digits.
  text.replace(static_cast<std::size_t>(match.position(2)),
               static_cast<std::size_t>(match.length(2)), literal);
  return true;
}

}  // namespace

std::string glslFloat(double value) {
  // 9 significant digits round-trip a float; GLSL 1.10 needs a point or an exponent.
  std::string text = fmt::format("{:.9g}", static_cast<double>(static_cast<float>(value)));
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

EtaBinding etaBinding(const Manifest& manifest) {
  EtaBinding binding;
  for (const auto& [name, value] : manifest.constants)
    if (namedEta(name)) binding.constants.push_back(name);
  for (const Binding& u : manifest.uniforms)
    if (namedEta(u.name) && std::holds_alternative<Value>(u.source) &&
        std::get<Value>(u.source).type == ValueType::Float)
      binding.uniforms.push_back(u.name);
  std::vector<std::string> all = binding.constants;
  all.insert(all.end(), binding.uniforms.begin(), binding.uniforms.end());
  if (all.empty()) return binding;
  binding.main = all.front();
  for (const char* preferred : {"EtaG", "Eta", "etaRatio"})
    if (std::find(all.begin(), all.end(), preferred) != all.end()) binding.main = preferred;
  if (auto c = manifest.constants.find(binding.main); c != manifest.constants.end())
    binding.published = c->second;
  for (const Binding& u : manifest.uniforms)
    if (u.name == binding.main) binding.published = std::get<Value>(u.source).data.at(0);
  return binding;
}

std::optional<EtaVariant> withEta(const Manifest& manifest, const ProgramSource& program,
                                  const EtaBinding& binding, double eta, std::string& why) {
  EtaVariant variant{manifest, program};
  const double scale = binding.published != 0 ? eta / binding.published : 1.0;
  for (const std::string& name : binding.constants) {
    // The value the oracle reads and the text the shader compiles are the
    // same float.
    const double value = static_cast<float>(manifest.constants.at(name) * scale);
    variant.manifest.constants[name] = value;
    const std::string literal = glslFloat(value);
    const bool inVertex = replaceConstant(variant.program.vertex, name, literal);
    const bool inFragment = replaceConstant(variant.program.fragment, name, literal);
    if (!inVertex && !inFragment) {
      why = fmt::format("constant {} is not written as `const float {} = number;` in the program",
                        name, name);
      return std::nullopt;
    }
  }
  for (Binding& u : variant.manifest.uniforms)
    if (std::find(binding.uniforms.begin(), binding.uniforms.end(), u.name) !=
        binding.uniforms.end()) {
      Value& v = std::get<Value>(u.source);
      v.data.at(0) = static_cast<float>(v.data.at(0) * scale);
    }
  return variant;
}

}  // namespace snell::sweep

#include "backends/vk/legacy_adapter.h"

#include <fmt/format.h>

#include <cctype>
#include <map>
#include <optional>
#include <string_view>

namespace snell {
namespace {

bool identifierStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool identifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

// The legacy lookups and the GLSL 1.40 overloads that do the same.
std::optional<std::string_view> textureFunction(std::string_view name) {
  static const std::map<std::string_view, std::string_view> kFunctions = {
      {"texture1D", "texture"},
      {"texture2D", "texture"},
      {"texture3D", "texture"},
      {"textureCube", "texture"},
      {"texture1DProj", "textureProj"},
      {"texture2DProj", "textureProj"},
      {"texture3DProj", "textureProj"},
      {"texture1DLod", "textureLod"},
      {"texture2DLod", "textureLod"},
      {"texture3DLod", "textureLod"},
      {"textureCubeLod", "textureLod"},
      {"texture1DProjLod", "textureProjLod"},
      {"texture2DProjLod", "textureProjLod"},
      {"texture3DProjLod", "textureProjLod"},
  };
  const auto found = kFunctions.find(name);
  if (found == kFunctions.end()) return std::nullopt;
  return found->second;
}

// gl_ModelViewMatrix -> snell_ModelViewMatrix, and so on.
std::string snellName(std::string_view builtin) {
  return "snell_" + std::string(builtin.substr(3));
}

// "gl_MultiTexCoord3": 3; nullopt when the digit is missing or out of range.
std::optional<int> trailingUnit(std::string_view name, std::string_view prefix) {
  if (name.size() != prefix.size() + 1 || name.substr(0, prefix.size()) != prefix)
    return std::nullopt;
  const char digit = name.back();
  if (digit < '0' || digit > '7') return std::nullopt;
  return digit - '0';
}

struct Declaration {
  LegacyRenaming renaming;
  std::string text;  // "uniform mat4 snell_ModelViewMatrix;"
};

class Adapter {
 public:
  Adapter(const std::string& source, LegacyStage stage) : in_(source), stage_(stage) {}

  LegacyAdapted run() {
    while (at_ < in_.size()) step();
    if (fragColor_) declareFragColor();
    LegacyAdapted adapted;
    const std::string prologue = prologueLines();
    if (versionAt_) {
      // The published `#version` line becomes the prologue; `#line N` in
      // GLSL below 3.30 numbers the next line N + 1, the line after it.
      std::string block = "#version 140";
      if (!prologue.empty()) block += "\n" + prologue + fmt::format("#line {}", versionLine_);
      out_.insert(*versionAt_, block);
    } else {
      out_.insert(0, "#version 140\n" + prologue + "#line 0\n");
    }
    adapted.text = std::move(out_);
    for (auto& [rank, declaration] : declarations_)
      adapted.renamings.push_back(std::move(declaration.renaming));
    return adapted;
  }

 private:
  bool vertex() const { return stage_ == LegacyStage::Vertex; }

  // The extension line and the declarations, each line ending in '\n'.
  std::string prologueLines() const {
    std::string lines;
    bool locations = sawLayout_;
    for (const auto& [rank, declaration] : declarations_)
      locations |= declaration.text.rfind("layout(", 0) == 0;
    if (locations) lines += "#extension GL_ARB_explicit_attrib_location : enable\n";
    std::string declared;
    for (const auto& [rank, declaration] : declarations_)
      declared += (declared.empty() ? "" : " ") + declaration.text;
    if (!declared.empty()) lines += declared + "\n";
    return lines;
  }

  void step() {
    const char c = in_[at_];
    if (c == '\n') {
      ++line_;
      lineStart_ = true;
      out_ += c;
      ++at_;
    } else if (space(c)) {
      out_ += c;
      ++at_;
    } else if (in_.compare(at_, 2, "//") == 0) {
      const std::size_t end = in_.find('\n', at_);
      copyTo(end == std::string::npos ? in_.size() : end);
    } else if (in_.compare(at_, 2, "/*") == 0) {
      const std::size_t end = in_.find("*/", at_ + 2);
      copyTo(end == std::string::npos ? in_.size() : end + 2);
    } else if (c == '#' && lineStart_) {
      directive();
    } else if (identifierStart(c)) {
      lineStart_ = false;
      identifier();
    } else if (std::isdigit(static_cast<unsigned char>(c)) ||
               (c == '.' && at_ + 1 < in_.size() &&
                std::isdigit(static_cast<unsigned char>(in_[at_ + 1])))) {
      lineStart_ = false;
      number();
    } else {
      lineStart_ = false;
      out_ += c;
      ++at_;
    }
  }

  // Copies in_[at_, end) as it is, counting its line breaks.
  void copyTo(std::size_t end) {
    for (; at_ < end; ++at_) {
      if (in_[at_] == '\n') ++line_;
      out_ += in_[at_];
    }
  }

  // The first `#version` is replaced (in run()); any other directive is
  // scanned as code, so a #define that names a built-in is adapted too.
  void directive() {
    lineStart_ = false;
    std::size_t name = at_ + 1;
    while (name < in_.size() && (in_[name] == ' ' || in_[name] == '\t')) ++name;
    if (!versionAt_ && in_.compare(name, 7, "version") == 0 &&
        (name + 7 == in_.size() || !identifierChar(in_[name + 7]))) {
      versionAt_ = out_.size();
      versionLine_ = line_;
      const std::size_t end = in_.find('\n', at_);
      at_ = end == std::string::npos ? in_.size() : end;
      return;
    }
    out_ += '#';
    ++at_;
  }

  // A number with its suffix or exponent letters ("1.0e5", "2u"), so that
  // no part of it is taken for an identifier.
  void number() {
    while (at_ < in_.size() && (identifierChar(in_[at_]) || in_[at_] == '.')) out_ += in_[at_++];
  }

  // After an identifier ending at `from`: `[ N ]` with N one digit. Returns
  // N and moves `end` past the bracket; the line breaks skipped on the way
  // are counted in `breaks`.
  std::optional<int> literalIndex(std::size_t from, std::size_t& end, int& breaks) const {
    std::size_t p = from;
    int skipped = 0;
    auto skip = [&] {
      while (p < in_.size() && space(in_[p])) skipped += in_[p++] == '\n';
    };
    skip();
    if (p >= in_.size() || in_[p] != '[') return std::nullopt;
    ++p;
    skip();
    if (p >= in_.size() || in_[p] < '0' || in_[p] > '9') return std::nullopt;
    const int index = in_[p++] - '0';
    if (p < in_.size() && identifierChar(in_[p])) return std::nullopt;  // "[10]", "[1u]"
    skip();
    if (p >= in_.size() || in_[p] != ']') return std::nullopt;
    end = p + 1;
    breaks = skipped;
    return index;
  }

  // After `ftransform`: `( )`.
  bool emptyCall(std::size_t from, std::size_t& end, int& breaks) const {
    std::size_t p = from;
    int skipped = 0;
    auto skip = [&] {
      while (p < in_.size() && space(in_[p])) skipped += in_[p++] == '\n';
    };
    skip();
    if (p >= in_.size() || in_[p] != '(') return false;
    ++p;
    skip();
    if (p >= in_.size() || in_[p] != ')') return false;
    end = p + 1;
    breaks = skipped;
    return true;
  }

  // Writes `text` for the tokens up to `end`, and the line breaks they
  // spanned after it, so every later line keeps its number.
  void replaceUpTo(std::size_t end, const std::string& text, int breaks) {
    out_ += text;
    out_.append(static_cast<std::size_t>(breaks), '\n');
    line_ += breaks;
    at_ = end;
  }

  void declare(int rank, LegacyRenaming::Kind kind, const std::string& builtin,
               const std::string& renamed, const std::string& text) {
    declarations_.try_emplace(rank, Declaration{{kind, builtin, renamed}, text});
  }

  void uniform(int rank, const std::string& builtin, const std::string& renamed, const char* type) {
    declare(100 + rank, LegacyRenaming::Kind::Uniform, builtin, renamed,
            fmt::format("uniform {} {};", type, renamed));
  }

  void input(int rank, const std::string& builtin, const std::string& renamed, const char* type) {
    declare(rank, LegacyRenaming::Kind::Input, builtin, renamed,
            fmt::format("in {} {};", type, renamed));
  }

  void output(int location, const std::string& builtin, const std::string& renamed) {
    declare(200 + location, LegacyRenaming::Kind::Output, builtin, renamed,
            fmt::format("layout(location = {}) out vec4 {};", location, renamed));
  }

  // glslang's automatic locations do not step around explicit ones, so the
  // output gets location 0 explicitly only where the text already places
  // its outputs (probes inserted with `layout(location = k)`); beside
  // outputs without a location (or alone) it is placed as they are, and a
  // lone output lands at 0 either way.
  void declareFragColor() {
    const bool explicitly = sawLayout_ || declarations_.lower_bound(200) != declarations_.end();
    declare(200, LegacyRenaming::Kind::Output, "gl_FragColor", "snell_FragColor",
            explicitly ? "layout(location = 0) out vec4 snell_FragColor;"
                       : "out vec4 snell_FragColor;");
  }

  void identifier() {
    std::size_t end = at_;
    while (end < in_.size() && identifierChar(in_[end])) ++end;
    const std::string_view name(in_.data() + at_, end - at_);
    const std::string replacement = replace(name, end);
    if (replacement.empty()) {
      out_.append(name);
      at_ = end;
    }
  }

  // The adapted text for identifier `name` (ending at `end`), already
  // written; or "" to copy the identifier as it is.
  std::string replace(std::string_view name, std::size_t end) {
    std::size_t after = end;
    int breaks = 0;
    if (name == "layout") sawLayout_ = true;
    if (name == "attribute" && vertex()) return write(end, "in");
    if (name == "varying") return write(end, vertex() ? "out" : "in");
    if (const auto texture = textureFunction(name)) return write(end, std::string(*texture));

    if (!vertex() && name == "gl_FragColor") {
      fragColor_ = true;
      return write(end, "snell_FragColor");
    }
    if (!vertex() && name == "gl_FragCoord") {
      // OpenGL counts window rows from the bottom; a Vulkan fragment shader
      // may only count them from the top (OriginUpperLeft). The harness
      // gives the framebuffer's height, and y is mirrored back.
      declare(150, LegacyRenaming::Kind::Uniform, kFramebufferHeightUniform,
              kFramebufferHeightUniform,
              fmt::format("uniform float {0}; vec4 snell_FragCoord() {{ return "
                          "vec4(gl_FragCoord.x, {0} - gl_FragCoord.y, gl_FragCoord.zw); }}",
                          kFramebufferHeightUniform));
      return write(end, "snell_FragCoord()");
    }
    if (!vertex() && name == "gl_FragData") {
      if (const auto index = literalIndex(end, after, breaks)) {
        const std::string renamed = fmt::format("snell_FragData{}", *index);
        output(*index, fmt::format("gl_FragData[{}]", *index), renamed);
        return write(after, renamed, breaks);
      }
      return "";
    }

    if (vertex() && name == "gl_Vertex") {
      input(0, "gl_Vertex", "snell_Vertex", "vec4");
      return write(end, "snell_Vertex");
    }
    if (vertex() && name == "gl_Normal") {
      input(1, "gl_Normal", "snell_Normal", "vec3");
      return write(end, "snell_Normal");
    }
    if (const auto unit = trailingUnit(name, "gl_MultiTexCoord"); unit && vertex()) {
      input(10 + *unit, std::string(name), snellName(name), "vec4");
      return write(end, snellName(name));
    }
    if (vertex() && name == "ftransform" && emptyCall(end, after, breaks)) {
      // Its definition, which fixed-function transformation equals.
      uniform(2, "gl_ModelViewProjectionMatrix", "snell_ModelViewProjectionMatrix", "mat4");
      input(0, "gl_Vertex", "snell_Vertex", "vec4");
      return write(after, "(snell_ModelViewProjectionMatrix * snell_Vertex)", breaks);
    }

    static const std::map<std::string_view, std::pair<int, const char*>> kMatrices = {
        {"gl_ModelViewMatrix", {0, "mat4"}},
        {"gl_ProjectionMatrix", {1, "mat4"}},
        {"gl_ModelViewProjectionMatrix", {2, "mat4"}},
        {"gl_NormalMatrix", {3, "mat3"}},
    };
    if (const auto matrix = kMatrices.find(name); matrix != kMatrices.end()) {
      uniform(matrix->second.first, std::string(name), snellName(name), matrix->second.second);
      return write(end, snellName(name));
    }
    if (name == "gl_TextureMatrix") {
      if (const auto unit = literalIndex(end, after, breaks); unit && *unit < 8) {
        const std::string renamed = fmt::format("snell_TextureMatrix{}", *unit);
        uniform(10 + *unit, fmt::format("gl_TextureMatrix[{}]", *unit), renamed, "mat4");
        return write(after, renamed, breaks);
      }
    }
    return "";
  }

  std::string write(std::size_t end, const std::string& text, int breaks = 0) {
    replaceUpTo(end, text, breaks);
    return text;
  }

  const std::string& in_;
  LegacyStage stage_;
  std::string out_;
  std::size_t at_ = 0;
  int line_ = 1;
  bool lineStart_ = true;  // nothing but white space since the last line break
  bool sawLayout_ = false;
  bool fragColor_ = false;
  std::optional<std::size_t> versionAt_;  // where the published #version line was, in out_
  int versionLine_ = 0;
  std::map<int, Declaration> declarations_;  // by rank: inputs, uniforms, outputs
};

}  // namespace

LegacyAdapted adaptLegacyForVulkan(const std::string& source, LegacyStage stage) {
  return Adapter(source, stage).run();
}

}  // namespace snell

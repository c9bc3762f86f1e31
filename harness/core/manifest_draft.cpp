#include "core/manifest_draft.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <vector>

#include "core/errors.h"
#include "core/glsl_declarations.h"
#include "core/glsl_statements.h"
#include "core/manifest.h"
#include "core/shader_conventions.h"
#include "core/utf8.h"

namespace snell {
namespace {

namespace fs = std::filesystem;

// At most this many fragment captures fit beside the listing's own colour
// output (core/manifest.cpp says the same to a hand-written manifest).
constexpr std::size_t kMaxFragmentCaptures = 7;

std::string readStage(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw UsageError(
        fmt::format("{}: cannot be read; check the file's permissions", path.string()));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The one file in `dir` with `extension`, or the one the user named.
std::string stageFile(const fs::path& dir, const std::string& given, const char* extension,
                      const char* stage, const char* option, bool required) {
  if (!given.empty()) {
    if (!fs::is_regular_file(dir / given))
      throw UsageError(fmt::format("{}: no such {} stage file in {}; {} names a file in the folder",
                                   given, stage, dir.string(), option));
    // The manifest names its stages relative to its folder (a sibling's
    // through "..", as the catalog's glass-to-air listing does): a path
    // given absolute was written as given, which holds on this machine only.
    const fs::path relative =
        fs::weakly_canonical(dir / given).lexically_relative(fs::weakly_canonical(dir));
    return relative.empty() ? given : relative.generic_string();
  }
  std::vector<std::string> found;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == extension)
      found.push_back(entry.path().filename().string());
  std::sort(found.begin(), found.end());
  if (found.size() > 1)
    throw UsageError(fmt::format("{} holds {} {} stages ({}); name one with {} FILE", dir.string(),
                                 found.size(), stage, fmt::join(found, ", "), option));
  if (found.empty() && required)
    throw UsageError(
        fmt::format("{} holds no GLSL {} stage (*{}); put the listing's files there, "
                    "or name the file with {} FILE",
                    dir.string(), stage, extension, option));
  return found.empty() ? std::string() : found.front();
}

void requireMain(const std::string& source, const fs::path& path) {
  if (mainBody(withoutComments(source)) == std::string::npos)
    throw UsageError(
        fmt::format("{}: no `void main()`; snell init reads GLSL stage files: check "
                    "that this is one",
                    path.string()));
}

int identifierUses(const std::string& code, const std::string& name) {
  int uses = 0;
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (std::size_t at = code.find(name); at != std::string::npos; at = code.find(name, at + 1)) {
    const std::size_t end = at + name.size();
    uses += (at == 0 || !word(code[at - 1])) && (end >= code.size() || !word(code[end]));
  }
  return uses;
}

// `#version 330 core` -> core; none, below 1.40, or `compatibility`: a
// legacy listing, which needs a compatibility context.
bool legacyVersion(const std::string& source) {
  static const std::regex kVersion(R"(#\s*version\s+(\d+)\s*(\w*))");
  std::smatch match;
  const std::string text = withoutComments(source);
  if (!std::regex_search(text, match, kVersion)) return true;
  return std::stoi(match[1].str()) < 140 || match[2].str() == "compatibility";
}

std::string tomlKey(const std::string& name) {
  const bool bare = std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
  return bare ? name : fmt::format("\"{}\"", name);
}

// A TOML basic string. A byte that starts no UTF-8 character (a folder
// named in Latin-1) is written as the character of that code (\u00XX): TOML
// has no escape for a raw byte.
std::string tomlString(const std::string& text) {
  std::string out = "\"";
  for (std::size_t at = 0; at < text.size();) {
    const char c = text[at];
    const std::size_t length = utf8CharacterAt(text, at).length;
    if (length == 0) {
      out += fmt::format("\\u{:04X}", static_cast<unsigned char>(c));
      ++at;
      continue;
    }
    if (c == '"' || c == '\\') out += '\\';
    out.append(text, at, length);
    at += length;
  }
  return out + "\"";
}

// One `key = value  # comment` line, keys padded to a column.
struct Line {
  std::string key, value, comment;
};

void writeLines(std::ostringstream& out, const std::vector<Line>& lines) {
  std::size_t keyWidth = 0, valueWidth = 0;
  for (const Line& l : lines) {
    keyWidth = std::max(keyWidth, tomlKey(l.key).size());
    valueWidth = std::max(valueWidth, l.value.size());
  }
  for (const Line& l : lines) {
    out << fmt::format("{:<{}} = ", tomlKey(l.key), keyWidth);
    if (l.comment.empty())
      out << l.value << "\n";
    else
      out << fmt::format("{:<{}}  # {}\n", l.value, valueWidth, l.comment);
  }
}

// loadManifest refuses a value starting "FILL IN", quoting what follows.
std::string placeholder(const std::string& type) {
  const bool vowel = std::string("aeiou").find(type.front()) != std::string::npos;
  return tomlString(fmt::format("FILL IN: {} {}", vowel ? "an" : "a", type));
}

std::string uniformHint(const std::string& type) {
  if (type == "float") return "a number: the value your application sets (or \"default\" for 0)";
  if (type == "vec2" || type == "vec3" || type == "vec4")
    return fmt::format("[{} numbers] as your application sets them, or \"scene.<semantic>\"",
                       type.back());
  if (type == "mat3" || type == "mat4")
    return fmt::format(
        "\"scene.<semantic>\" or {{ type = \"{}\", value = [{} numbers, column "
        "by column] }}",
        type, type == "mat3" ? 9 : 16);
  return fmt::format(
      "snell sets float, vec2-4, mat3 and mat4 uniforms, not a {}: declare it as a float in "
      "the listing you gate, or give the case a hand-written oracle",
      type);
}

struct Stage {
  std::string file;
  std::string source;
  std::string code;  // comments blanked
  std::vector<GlslDeclaration> declarations;
};

Stage readStageFile(const fs::path& dir, const std::string& file) {
  // The manifest names the file in a TOML string, which must be UTF-8.
  if (!isUtf8(file))
    throw UsageError(
        fmt::format("{}: the file's name is not UTF-8, which a manifest cannot name; "
                    "rename the file",
                    utf8SpellingOutOthers((dir / file).string())));
  Stage stage{file, readStage(dir / file), {}, {}};
  requireMain(stage.source, dir / file);
  stage.code = withoutComments(stage.source);
  stage.declarations = readGlobalDeclarations(stage.source);
  return stage;
}

// Declared, and used somewhere besides the declaration.
bool read(const Stage& stage, const GlslDeclaration& d) {
  return identifierUses(stage.code, d.name) >= 2;
}

void inputsSection(std::ostringstream& out, const Stage& vertex) {
  std::vector<Line> lines;
  std::vector<std::string> unread;
  for (const GlslDeclaration& d : vertex.declarations) {
    if (d.qualifier != "in" && d.qualifier != "attribute") continue;
    if (!read(vertex, d)) {
      unread.push_back(d.name);
      continue;
    }
    if (const auto bound = conventionalInput(d))
      lines.push_back({d.name, tomlString("scene." + bound->semantic),
                       fmt::format("{} {}: {}", d.type, d.name, bound->why)});
    else
      lines.push_back({d.name, placeholder(d.type),
                       fmt::format("{} {}: a per-vertex semantic (scene.position, scene.normal, "
                                   "scene.tangent, scene.texcoord) or \"default\" (0, 0, 0, 1)",
                                   d.type, d.name)});
  }
  // Fixed-function attributes a legacy listing reads (shaders/README.md).
  for (const auto& [builtin, semantic] : {std::pair{"gl_Vertex", "position"},
                                          {"gl_Normal", "normal"},
                                          {"gl_MultiTexCoord0", "texcoord"}})
    if (identifierUses(vertex.code, builtin) > 0)
      lines.push_back(
          {builtin, tomlString(std::string("scene.") + semantic), "fixed-function attribute"});
  if (lines.empty() && unread.empty()) return;
  out << "\n[inputs]\n";
  writeLines(out, lines);
  if (!unread.empty())
    out << fmt::format("# Declared but never read, so left unbound: {}\n", fmt::join(unread, ", "));
}

void uniformsSection(std::ostringstream& out, const Stage& vertex,
                     const std::optional<Stage>& fragment) {
  std::vector<GlslDeclaration> uniforms;
  std::vector<const Stage*> stages = {&vertex};
  if (fragment) stages.push_back(&*fragment);
  for (const Stage* stage : stages)
    for (const GlslDeclaration& d : stage->declarations)
      if (d.qualifier == "uniform" &&
          std::none_of(uniforms.begin(), uniforms.end(),
                       [&](const GlslDeclaration& u) { return u.name == d.name; }))
        uniforms.push_back(d);
  std::vector<Line> lines;
  std::vector<std::string> unread;
  for (const GlslDeclaration& d : uniforms) {
    const bool used =
        std::any_of(stages.begin(), stages.end(), [&](const Stage* s) { return read(*s, d); });
    if (!used) {
      unread.push_back(d.name);
      continue;
    }
    if (const auto bound = conventionalUniform(d, uniforms))
      lines.push_back({d.name, tomlString("scene." + bound->semantic),
                       fmt::format("{} {}: {}", d.type, d.name, bound->why)});
    else
      lines.push_back({d.name, placeholder(d.type),
                       fmt::format("{} {}: {}", d.type, d.name, uniformHint(d.type))});
  }
  // Fixed-function matrices: GL derives gl_NormalMatrix and
  // gl_ModelViewProjectionMatrix (and ftransform()) from these two.
  const auto uses = [&](std::initializer_list<const char*> names) {
    return std::any_of(stages.begin(), stages.end(), [&](const Stage* s) {
      return std::any_of(names.begin(), names.end(),
                         [&](const char* n) { return identifierUses(s->code, n) > 0; });
    });
  };
  if (uses({"gl_ModelViewMatrix", "gl_NormalMatrix", "gl_ModelViewProjectionMatrix", "ftransform"}))
    lines.push_back({"gl_ModelViewMatrix", tomlString("scene.modelview"), "fixed-function state"});
  if (uses({"gl_ProjectionMatrix", "gl_ModelViewProjectionMatrix", "ftransform"}))
    lines.push_back(
        {"gl_ProjectionMatrix", tomlString("scene.projection"), "fixed-function state"});
  if (lines.empty() && unread.empty()) return;
  out << "\n[uniforms]\n";
  writeLines(out, lines);
  if (!unread.empty())
    out << fmt::format("# Declared but never read, so left unbound: {}\n", fmt::join(unread, ", "));
}

struct Capture {
  std::string name, type;
  int line = 0;
  std::string comment;
};

bool lookup(const GlslStatement& s) {
  static const std::set<std::string> kLookups = {
      "texture",     "textureCube",  "texture2D",      "textureLod",    "textureProj",
      "textureGrad", "texture2DLod", "textureCubeLod", "texture2DProj", "textureOffset"};
  const std::vector<std::string> ids = identifiersIn(s.text);
  return std::any_of(ids.begin(), ids.end(),
                     [](const std::string& id) { return kLookups.count(id) > 0; });
}

// `vec3 up = vec3(0.0, 1.0, 0.0)`: nothing but constructors and literals.
bool constantInitialiser(const std::string& statement) {
  static const std::set<std::string> kConstructors = {"float", "vec2", "vec3", "vec4"};
  const std::size_t equals = statement.find('=');
  if (equals == std::string::npos) return false;
  const std::vector<std::string> ids = identifiersIn(statement.substr(equals + 1));
  return std::all_of(ids.begin(), ids.end(),
                     [](const std::string& id) { return kConstructors.count(id) > 0; });
}

// The vec3 locals main() computes before its last texture lookup (the
// directions a lookup is made with), and the fragment inputs they read.
std::vector<Capture> fragmentCaptures(const Stage& fragment, std::vector<std::string>& leftOut) {
  const std::vector<GlslStatement> statements = mainStatements(fragment.source);
  std::size_t lastLookup = 0;
  for (std::size_t k = 0; k < statements.size(); ++k)
    if (lookup(statements[k])) lastLookup = k + 1;
  // Declared with a value: `vec3 refr;` holds nothing yet at its line (and
  // in the per-channel chromatic pattern it is a colour its channels' lookups
  // fill in, not a direction).
  static const std::regex kVec3Local(
      R"(^(const\s+)?((highp|mediump|lowp)\s+)?vec3\s+([A-Za-z_]\w*)\s*=)");
  std::vector<Capture> inputs, locals;
  // Statements before the last lookup's own (which makes a colour).
  for (std::size_t k = 0; k + 1 < lastLookup; ++k) {
    std::smatch match;
    if (!std::regex_search(statements[k].text, match, kVec3Local)) continue;
    if (constantInitialiser(statements[k].text))
      continue;                           // vec3(0.0, 1.0, 0.0): no vector computed
    if (lookup(statements[k])) continue;  // a colour, not a direction the oracle computes
    locals.push_back({match[4].str(), "vec3", statements[k].lastLine, "computed here"});
    for (const std::string& id : identifiersIn(statements[k].text)) {
      for (const GlslDeclaration& d : fragment.declarations) {
        if ((d.qualifier != "in" && d.qualifier != "varying") || d.name != id) continue;
        if (std::any_of(inputs.begin(), inputs.end(),
                        [&](const Capture& c) { return c.name == id; }))
          continue;
        if (d.type == "float" || d.type == "vec2" || d.type == "vec3")
          inputs.push_back(
              {d.name, d.type, statements[k].lastLine,
               fmt::format("input, as the driver interpolated it (declared line {})", d.line)});
        else
          leftOut.push_back(
              fmt::format("{} (a {} input: only float, vec2 and vec3 read back)", d.name, d.type));
      }
    }
  }
  std::vector<Capture> all = inputs;
  all.insert(all.end(), locals.begin(), locals.end());
  while (all.size() > kMaxFragmentCaptures) {
    leftOut.push_back(fmt::format("{} (line {}: at most {} captures fit)", all.back().name,
                                  all.back().line, kMaxFragmentCaptures));
    all.pop_back();
  }
  return all;
}

void captureSection(std::ostringstream& out, const DraftRequest& request, const Stage& vertex,
                    const std::optional<Stage>& fragment) {
  std::vector<std::string> leftOut;
  const auto gated = [&](const Stage& stage, bool isFragment, const std::string& name, int line) {
    const std::string why =
        request.whyNotGated ? request.whyNotGated(stage.file, stage.source, isFragment, name, line)
                            : std::string();
    if (!why.empty()) leftOut.push_back(fmt::format("{} ({})", name, why));
    return why.empty();
  };
  std::vector<std::string> outputs;
  for (const GlslDeclaration& d : vertex.declarations)
    if ((d.qualifier == "out" || d.qualifier == "varying") && gated(vertex, false, d.name, 0))
      outputs.push_back(tomlString(d.name));
  std::vector<Capture> captures =
      fragment ? fragmentCaptures(*fragment, leftOut) : std::vector<Capture>{};
  const auto isInput = [](const Capture& c) { return c.comment.rfind("input", 0) == 0; };
  std::erase_if(captures, [&](const Capture& c) {
    return !isInput(c) && !gated(*fragment, true, c.name, c.line);
  });
  // Inputs are captured for the values computed from them: with none of
  // those left, nothing in the fragment stage would be checked.
  if (std::all_of(captures.begin(), captures.end(), isInput)) captures.clear();
  if (outputs.empty() && captures.empty()) {
    // Outputs that were there but cannot be gated say why: a syntax error,
    // an #include, a construct outside the derived oracle's subset.
    if (!leftOut.empty())
      throw UsageError(fmt::format("{}{}{}: nothing the derived oracle can gate: {}", vertex.file,
                                   fragment ? " and " : "", fragment ? fragment->file : "",
                                   fmt::join(leftOut, "; ")));
    throw UsageError(fmt::format(
        "{}{}{}: nothing to read back: the vertex stage declares no outputs and the fragment "
        "stage computes no vec3 before a texture lookup; write [capture] by hand "
        "(shaders/README.md)",
        vertex.file, fragment ? " and " : "", fragment ? fragment->file : ""));
  }
  out << "\n[capture]\n";
  if (!outputs.empty()) {
    out << "# Every output of the vertex stage, read back and held against the derived\n"
           "# oracle.\n";
    out << fmt::format("vertex = [{}]\n", fmt::join(outputs, ", "));
  }
  if (!captures.empty()) {
    out << fmt::format(
        "# Read in {} after the statement that ends on `line`: the vec3s\n"
        "# computed before its texture lookup (checked), and the inputs they read\n"
        "# (the derived oracle starts from them).\n",
        fragment->file);
    out << "fragment = [\n";
    std::size_t width = 0;
    for (const Capture& c : captures) width = std::max(width, tomlString(c.name).size() + 1);
    for (const Capture& c : captures)
      out << fmt::format("  {{ name = {:<{}} type = \"{}\", line = {} }},  # {}\n",
                         tomlString(c.name) + ",", width, c.type, c.line, c.comment);
    out << "]\n";
  }
  for (const std::string& what : leftOut) out << fmt::format("# Not captured: {}\n", what);
}

// A vertex stage that reads no matrix passes its positions to clip space
// as they are (a Shadertoy-style full-screen pass): only the full-screen
// scene, one triangle over the viewport, draws it as meant.
bool clipSpacePositions(const Stage& vertex) {
  for (const GlslDeclaration& d : vertex.declarations)
    if (d.qualifier == "uniform" && d.type.rfind("mat", 0) == 0 && read(vertex, d)) return false;
  for (const char* builtin :
       {"gl_ModelViewMatrix", "gl_ModelViewProjectionMatrix", "gl_ProjectionMatrix", "ftransform"})
    if (identifierUses(vertex.code, builtin) > 0) return false;
  return true;
}

// Writes the cases; whether any compares an image.
bool casesSection(std::ostringstream& out, const Stage& vertex,
                  const std::optional<Stage>& fragment) {
  const bool hasFragment = fragment.has_value();
  // The image check's reference is the fragment stage evaluated by the
  // derived oracle, which has no gl_FragCoord (a screen-space listing's
  // pixel position): such a listing gets its vectors checked, and says why.
  if (hasFragment && clipSpacePositions(vertex) &&
      identifierUses(fragment->code, "gl_FragCoord") > 0) {
    out << R"(
# The vertex stage reads no matrix, so its positions are clip space: the
# full-screen scene (one triangle over a 128 x 128 viewport) draws it. The
# fragment stage reads gl_FragCoord, which the derived oracle's reference
# image cannot follow: vectors only (an image case needs a hand-written
# oracle's reference).
[[case]]
scene  = "fullscreen"
checks = ["vectors"]
)";
    return false;
  }
  if (hasFragment && clipSpacePositions(vertex)) {
    out << R"(
# The vertex stage reads no matrix, so its positions are clip space: the
# full-screen scene (one triangle over a 128 x 128 viewport) draws it. The
# image tolerance is the one derived for a colour that is one filtered
# environment lookup (shaders/orange-book/14.1-fresnel/manifest.toml); a
# colour computed otherwise needs its own derivation.
[[case]]
scene  = "fullscreen"
checks = ["vectors", "image"]
image  = { fail = 0.004, warn = 0.002, failpercent = 0.0, hardfail = 0.05 }
)";
    return true;
  }
  out << R"(
# The vectors on the torus: concave regions, self-occlusion, inner silhouettes.
[[case]]
scene  = "torus"
checks = ["vectors"]
)";
  if (!hasFragment) {
    out << R"(
# A sphere scaled unevenly: its normal matrix is no rotation, so a normal
# used without normalize() is off here, where the sphere's and the torus's
# are unit already.
[[case]]
scene  = "stretched"
checks = ["vectors"]
)";
    out << "\n# No fragment stage, so no image to compare; add one to `stages` for an image "
           "case.\n";
    return false;
  }
  out << R"(
# Image tolerance (linear float, per channel), as derived for the catalog's
# environment lookups: bilinear weights may be quantised to
# subTexelPrecisionBits, at least 4 in Vulkan, so a filtered value may be off
# by 2^-4 times the largest step between neighbouring texels, which the
# scene's textures keep at or below 0.05: 0.0031. fp32 interpolation moves a
# lookup by about 1e-6, worth 1e-5 at most: fail at 0.004, warn at half
# that, every compared pixel must pass, and beyond 0.05 is a wrong texel.
# A listing whose colour is not one texture lookup needs its own derivation.
[[case]]
scene  = "sphere"
checks = ["vectors", "image"]
image  = { fail = 0.004, warn = 0.002, failpercent = 0.0, hardfail = 0.05 }

# A sphere scaled unevenly: its normal matrix is no rotation, so a normal
# used without normalize() is off here, where the sphere's and the torus's
# are unit already. The derived oracle follows the listing's own text: the
# image against its golden is what shows such a change.
[[case]]
scene  = "stretched"
checks = ["vectors", "image"]
image  = { fail = 0.004, warn = 0.002, failpercent = 0.0, hardfail = 0.05 }
)";
  return true;
}

// A folder name as an id's name: what an id may not hold (a space, say)
// becomes '-'.
std::string idName(const std::string& folder) {
  std::string name = folder;
  for (char& c : name)
    if (!isListingIdCharacter(c)) c = '-';
  return name;
}

std::string defaultId(const fs::path& dir) {
  const fs::path absolute = fs::weakly_canonical(fs::absolute(dir));
  const std::string name = idName(absolute.filename().string());
  const std::string parent = idName(absolute.parent_path().filename().string());
  return parent.empty() ? name : parent + "/" + name;
}

}  // namespace

std::string draftManifest(const DraftRequest& request) { return draftOf(request).text; }

Draft draftOf(const DraftRequest& request) {
  const fs::path& dir = request.dir;
  if (!fs::is_directory(dir))
    throw UsageError(fmt::format("{}: {}; snell init DIR reads the GLSL files in DIR", dir.string(),
                                 fs::exists(dir) ? "a file, not a folder" : "no such folder"));
  const Stage vertex =
      readStageFile(dir, stageFile(dir, request.vertexFile, ".vert", "vertex", "--vertex", true));
  std::optional<Stage> fragment;
  if (const std::string file =
          stageFile(dir, request.fragmentFile, ".frag", "fragment", "--fragment", false);
      !file.empty())
    fragment = readStageFile(dir, file);
  if (fragment && fragment->file == vertex.file)
    throw UsageError(fmt::format(
        "{}: named as both the vertex and the fragment stage; name the fragment stage's file "
        "with --fragment, or leave the option out",
        vertex.file));

  std::ostringstream out;
  out << fmt::format(
      "# Drafted by `snell init` from {}{}{}.\n"
      "# Lines holding \"FILL IN\" are yours: `snell run` refuses the manifest,\n"
      "# naming the line, until each holds a value (shaders/README.md lists the\n"
      "# scene semantics).\n",
      vertex.file, fragment ? " and " : "", fragment ? fragment->file : "");
  std::vector<Line> head;
  const std::string id = request.id.empty() ? defaultId(dir) : request.id;
  if (const std::string problem = listingIdProblem(id); !problem.empty())
    throw UsageError(request.id.empty()
                         ? fmt::format("{}: {}; name it with --id", dir.string(), problem)
                         : "--id: " + problem);
  head.push_back({"id", tomlString(id), "unique; case ids are <id>/<scene>"});
  // The folder's own name, also for "." or a trailing slash.
  head.push_back({"title", tomlString(fs::weakly_canonical(fs::absolute(dir)).filename().string()),
                  "one line for people"});
  writeLines(out, head);
  out << "# Where the listing comes from: the document or URL, and the listing or\n"
         "# section in it.\n";
  out << "source = { file = \"FILL IN: the document or URL\", where = \"FILL IN: the listing or "
         "section\" }\n";
  if (legacyVersion(vertex.source))
    out << "# No #version 1.40 or later: a legacy listing, run in a compatibility context.\n"
           "profile = \"compatibility\"\n";
  out << (fragment ? fmt::format("stages = {{ vertex = {}, fragment = {} }}\n",
                                 tomlString(vertex.file), tomlString(fragment->file))
                   : fmt::format("stages = {{ vertex = {} }}\n", tomlString(vertex.file)));
  out << "# No `oracle`: the derived oracle, built from the listing's own text, holds\n"
         "# what is read back to what the GLSL and Vulkan precision rules allow.\n";
  inputsSection(out, vertex);
  uniformsSection(out, vertex, fragment);
  captureSection(out, request, vertex, fragment);
  const bool imageCases = casesSection(out, vertex, fragment);
  // The comments quote the shader's lines, which may be in another
  // encoding (a Latin-1 comment): TOML must be UTF-8, so other bytes are
  // spelled out.
  return {utf8SpellingOutOthers(out.str()), imageCases};
}

DraftWritten writeDraftManifest(const DraftRequest& request, bool force) {
  const Draft draft = draftOf(request);
  const fs::path path = request.dir / "manifest.toml";
  if (fs::exists(path) && !force)
    throw UsageError(
        fmt::format("{} exists; snell init never overwrites a manifest: pass --force "
                    "to replace it",
                    path.string()));
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file << draft.text;
  file.close();
  if (!file)
    throw UsageError(
        fmt::format("{}: cannot be written; check the folder's permissions", path.string()));
  return {path, draft.imageCases};
}

}  // namespace snell

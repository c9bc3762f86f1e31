#include "core/manifest.h"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "core/errors.h"
#include "core/toml_keys.h"

namespace snell {
namespace {

// The first name a list gives a second time, or null.
const std::string* firstRepeated(const std::vector<std::string>& names) {
  for (std::size_t k = 1; k < names.size(); ++k)
    if (std::find(names.begin(), names.begin() + k, names[k]) != names.begin() + k)
      return &names[k];
  return nullptr;
}

namespace fs = std::filesystem;

// A line number (capture, compile_error) past int's range is no file's line;
// kept as a number, it would be cut to 32 bits and name another line.
constexpr std::int64_t kMaxLine = std::numeric_limits<int>::max();

class ManifestReader {
 public:
  explicit ManifestReader(fs::path path) : path_(std::move(path)) {}

  [[noreturn]] void fail(int line, const std::string& what) const {
    if (line > 0) throw UsageError(fmt::format("{}:{}: {}", path_.string(), line, what));
    throw UsageError(fmt::format("{}: {}", path_.string(), what));
  }

  static int lineOf(const toml::node& node) { return static_cast<int>(node.source().begin.line); }

  // `snell init` writes "FILL IN: <what>" where only the author knows the
  // value; a manifest still holding one must not run on a guess.
  void refusePlaceholder(const std::string& text, int line, std::string_view key) const {
    static constexpr std::string_view kPlaceholder = "FILL IN";
    if (text.rfind(kPlaceholder, 0) != 0) return;
    std::string what(text.substr(kPlaceholder.size()));
    what.erase(0, what.find_first_not_of(": "));
    fail(line, fmt::format("`{}` is still the placeholder \"{}\" that snell init wrote: replace "
                           "it with {} (the comment by it says what fits)",
                           key, text, what.empty() ? "a value" : what));
  }

  void onlyKeys(const toml::table& table, std::initializer_list<std::string_view> known,
                std::string_view where) const {
    rejectUnknownKeys(table, known, path_, where);
  }

  std::string requiredString(const toml::table& table, std::string_view key, int tableLine) const {
    const toml::node* node = table.get(key);
    if (!node)
      fail(tableLine, fmt::format("missing field `{}`; add it (see shaders/README.md)", key));
    if (!node->is_string()) fail(lineOf(*node), fmt::format("`{}` must be a string", key));
    std::string text(*node->value<std::string>());
    refusePlaceholder(text, lineOf(*node), key);
    return text;
  }

  // `oracle = "name"`, `"derived"`, `["name", "derived"]`, or nothing (derived).
  void oracles(const toml::table& root, Manifest& m) const {
    const toml::node* node = root.get("oracle");
    if (!node) {
      m.derivedOracle = true;
      return;
    }
    m.oracleLine = lineOf(*node);
    std::vector<std::string> names;
    if (const auto* name = node->as_string()) {
      names.push_back(name->get());
    } else if (const toml::array* array = node->as_array(); array && !array->empty()) {
      for (const toml::node& item : *array) {
        if (!item.as_string()) break;
        names.push_back(item.as_string()->get());
      }
      if (names.size() != array->size()) names.clear();
    }
    if (names.empty() || names.size() > 2)
      fail(m.oracleLine,
           "`oracle` must be a hand-written oracle's name, \"derived\", or both as an array "
           "([\"name\", \"derived\"]); leave it out for the derived oracle alone");
    for (const std::string& name : names) {
      if (name == "derived") {
        m.derivedOracle = true;
      } else if (nearestKey(name, {"derived"}) == "derived") {
        // A hand-written oracle's name is checked where the oracles are
        // known; a near miss of "derived" is said here, before a message
        // about the name as a hand-written oracle's.
        fail(m.oracleLine, fmt::format("`oracle` names '{}'; did you mean \"derived\" (the "
                                       "oracle derived from the listing's own text)?",
                                       name));
      } else if (m.oracle.empty()) {
        m.oracle = name;
      } else {
        fail(m.oracleLine, fmt::format("`oracle` names two hand-written oracles ('{}', '{}'): "
                                       "keep one, and \"derived\" beside it if wanted",
                                       m.oracle, name));
      }
    }
  }

  std::string optionalString(const toml::table& table, std::string_view key) const {
    const toml::node* node = table.get(key);
    if (!node) return {};
    if (!node->is_string()) fail(lineOf(*node), fmt::format("`{}` must be a string", key));
    return std::string(*node->value<std::string>());
  }

  const toml::table& requiredTable(const toml::table& table, std::string_view key,
                                   int tableLine) const {
    const toml::node* node = table.get(key);
    if (!node)
      fail(tableLine, fmt::format("missing table `{}`; add it (see shaders/README.md)", key));
    if (!node->is_table()) fail(lineOf(*node), fmt::format("`{}` must be a table", key));
    return *node->as_table();
  }

  std::vector<std::string> stringArray(const toml::node& node, std::string_view key) const {
    const toml::array* array = node.as_array();
    if (!array) fail(lineOf(node), fmt::format("`{}` must be an array of strings", key));
    std::vector<std::string> out;
    for (const toml::node& element : *array) {
      if (!element.is_string())
        fail(lineOf(element), fmt::format("`{}` must hold strings only", key));
      out.emplace_back(*element.value<std::string>());
    }
    return out;
  }

  static bool numeric(const toml::node& node) {
    return node.is_floating_point() || node.is_integer();
  }

  // A number as the shader's float: one that is not finite as a float (nan,
  // inf, 1e300) or that rounds to 0 from a non-zero value (1e-50) is
  // refused here, where it was written, not found as a case whose every
  // component the spec leaves undefined.
  float floatOf(const toml::node& node, const std::string& name) const {
    const double value = *node.value<double>();
    const float rounded = static_cast<float>(value);
    if (!std::isfinite(rounded))
      fail(lineOf(node), fmt::format("`{}`: {} is not a finite float (at most about 3.4e38); give "
                                     "a finite number",
                                     name, value));
    if (rounded == 0.0f && value != 0.0)
      fail(lineOf(node), fmt::format("`{}`: {} rounds to 0 as a float (the smallest is about "
                                     "1.4e-45); give 0 or a larger number",
                                     name, value));
    return rounded;
  }

  // A literal: a number, an array of 2-4 numbers (a vector), or
  // { type = "mat3", value = [...] } for the cases a length cannot tell.
  Value literal(const toml::node& node, const std::string& name) const {
    if (numeric(node)) return Value{ValueType::Float, {floatOf(node, name)}};
    ValueType type{};
    const toml::array* array = nullptr;
    if (const toml::table* typed = node.as_table()) {
      onlyKeys(*typed, {"type", "value"}, fmt::format("the literal of `{}`", name));
      const std::string typeName = requiredString(*typed, "type", lineOf(node));
      static const std::pair<const char*, ValueType> kTypes[] = {
          {"float", ValueType::Float}, {"vec2", ValueType::Vec2}, {"vec3", ValueType::Vec3},
          {"vec4", ValueType::Vec4},   {"mat3", ValueType::Mat3}, {"mat4", ValueType::Mat4}};
      auto it = std::find_if(std::begin(kTypes), std::end(kTypes),
                             [&](const auto& entry) { return typeName == entry.first; });
      if (it == std::end(kTypes))
        fail(lineOf(node), fmt::format("`{}`: unknown type `{}`; use float, vec2, vec3, vec4, "
                                       "mat3 or mat4",
                                       name, typeName));
      type = it->second;
      const toml::node* value = typed->get("value");
      if (!value) fail(lineOf(node), fmt::format("`{}`: missing `value`", name));
      array = value->as_array();
      if (!array) fail(lineOf(*value), fmt::format("`{}`: `value` must be an array", name));
    } else if ((array = node.as_array())) {
      if (array->size() < 2 || array->size() > 4)
        fail(lineOf(node),
             fmt::format("`{}`: a vector literal has 2 to 4 numbers, this one has {}; "
                         "write a matrix as {{ type = \"mat4\", value = [...] }}",
                         name, array->size()));
      type = static_cast<ValueType>(static_cast<int>(ValueType::Vec2) + array->size() - 2);
    } else {
      fail(lineOf(node), fmt::format("`{}` must be \"scene.<semantic>\", a number, an array or "
                                     "{{ type = ..., value = [...] }}",
                                     name));
    }
    Value out{type, {}};
    if (static_cast<int>(array->size()) != componentCount(type))
      fail(lineOf(node), fmt::format("`{}`: a {} has {} components, the manifest gives {}", name,
                                     glslTypeName(type), componentCount(type), array->size()));
    for (const toml::node& element : *array) {
      if (!numeric(element)) fail(lineOf(element), fmt::format("`{}`: not a number", name));
      out.data.push_back(floatOf(element, name));
    }
    return out;
  }

  std::vector<Binding> bindings(const toml::table& root, std::string_view key) const {
    std::vector<Binding> out;
    const toml::node* node = root.get(key);
    if (!node) return out;
    const toml::table* table = node->as_table();
    if (!table) fail(lineOf(*node), fmt::format("`{}` must be a table", key));
    for (const auto& [name, value] : *table) {
      Binding binding{std::string(name.str()), std::string(), lineOf(value)};
      if (value.is_string()) {
        const std::string text(*value.value<std::string>());
        refusePlaceholder(text, binding.line, binding.name);
        if (text == "default") {
          binding.apiDefault = true;
          out.push_back(std::move(binding));
          continue;
        }
        if (text.rfind("scene.", 0) != 0)
          fail(binding.line,
               fmt::format("`{}` = \"{}\": a binding string names a scene semantic "
                           "and starts with \"scene.\" (or is \"default\" for the API's "
                           "initial value)",
                           binding.name, text));
        binding.source = text.substr(6);
      } else {
        binding.source = literal(value, binding.name);
      }
      out.push_back(std::move(binding));
    }
    return out;
  }

  // fragment = [ { name = "refractview", type = "vec3", line = 12 }, ... ]
  std::vector<FragmentCapture> fragmentCaptures(const toml::node& node,
                                                bool noFragmentStage) const {
    const toml::array* array = node.as_array();
    if (!array || !array->is_array_of_tables())
      fail(lineOf(node),
           "`capture.fragment` must be an array of { name = ..., type = ..., line = ... }");
    if (noFragmentStage)
      fail(lineOf(node), "`capture.fragment` needs a fragment stage; add `fragment` to `stages`");
    std::vector<FragmentCapture> out;
    for (const toml::node& element : *array) {
      const toml::table& table = *element.as_table();
      onlyKeys(table, {"name", "type", "line"}, "a `capture.fragment` entry");
      FragmentCapture capture;
      capture.manifestLine = lineOf(element);
      capture.name = requiredString(table, "name", capture.manifestLine);
      const std::string type = requiredString(table, "type", capture.manifestLine);
      if (type == "float")
        capture.type = ValueType::Float;
      else if (type == "vec2")
        capture.type = ValueType::Vec2;
      else if (type == "vec3")
        capture.type = ValueType::Vec3;
      else
        fail(capture.manifestLine,
             fmt::format("capture `{}`: type `{}` cannot be read back; use float, vec2 or vec3 "
                         "(the fourth channel marks the pixels that wrote it)",
                         capture.name, type));
      const toml::node* line = table.get("line");
      if (!line || !line->is_integer() || *line->value<std::int64_t>() < 1 ||
          *line->value<std::int64_t>() > kMaxLine)
        fail(capture.manifestLine,
             fmt::format("capture `{}`: `line` must be the fragment file's line (from 1) whose "
                         "statement computes it",
                         capture.name));
      capture.line = static_cast<int>(*line->value<std::int64_t>());
      for (const FragmentCapture& earlier : out)
        if (earlier.name == capture.name)
          fail(capture.manifestLine, fmt::format("capture `{}` is listed twice", capture.name));
      out.push_back(std::move(capture));
    }
    if (out.size() > 7)
      fail(lineOf(node), fmt::format("`capture.fragment` lists {} values; at most 7 fit beside "
                                     "the listing's own colour output",
                                     out.size()));
    return out;
  }

  // [compile_error.gl] stage = "fragment", line = 4, pattern = "syntax error"
  std::map<std::string, ExpectedDiagnostic> expectedErrors(const toml::table& root,
                                                           const Manifest& m) const {
    std::map<std::string, ExpectedDiagnostic> out;
    const toml::node* node = root.get("compile_error");
    if (!node) {
      if (m.expect == Expectation::CompileError)
        fail(1,
             "`expect = \"compile-error\"` needs the expected diagnostic per API: "
             "[compile_error.gl] and [compile_error.vk] with stage, line and (optionally) "
             "pattern");
      return out;
    }
    if (m.expect != Expectation::CompileError)
      fail(lineOf(*node),
           "`compile_error` is only for a listing with `expect = \"compile-error\"`");
    const toml::table* table = node->as_table();
    if (!table) fail(lineOf(*node), "`compile_error` must be a table: [compile_error.gl] ...");
    onlyKeys(*table, {"gl", "vk"}, "`compile_error` (one table per API)");
    for (const auto& [api, value] : *table) {
      const toml::table* entry = value.as_table();
      if (!entry) fail(lineOf(value), fmt::format("`compile_error.{}` must be a table", api.str()));
      onlyKeys(*entry, {"stage", "line", "pattern"}, fmt::format("`compile_error.{}`", api.str()));
      ExpectedDiagnostic d;
      d.manifestLine = lineOf(value);
      d.stage = requiredString(*entry, "stage", d.manifestLine);
      if (d.stage != "vertex" && d.stage != "fragment")
        fail(d.manifestLine, fmt::format("`compile_error.{}.stage` must be \"vertex\" or "
                                         "\"fragment\"",
                                         api.str()));
      const toml::node* line = entry->get("line");
      if (!line || !line->is_integer() || *line->value<std::int64_t>() < 1 ||
          *line->value<std::int64_t>() > kMaxLine)
        fail(d.manifestLine, fmt::format("`compile_error.{}.line` must be the line (from 1) the "
                                         "diagnostic points at",
                                         api.str()));
      d.line = static_cast<int>(*line->value<std::int64_t>());
      d.pattern = optionalString(*entry, "pattern");
      out[std::string(api.str())] = d;
    }
    for (const char* api : {"gl", "vk"})
      if (!out.count(api) && !m.notSupported.count(api))
        fail(lineOf(*node), fmt::format("`compile_error` has no `{}` entry: name the diagnostic "
                                        "that API's compiler gives",
                                        api));
    return out;
  }

  // image = { fail = 0.004, warn = 0.002, failpercent = 0, hardfail = 0.05 }
  ImageTolerance imageTolerance(const toml::table& caseTable, int caseLine) const {
    const toml::node* node = caseTable.get("image");
    if (!node || !node->is_table())
      fail(caseLine,
           "the \"image\" check needs `image = { fail = ..., warn = ..., failpercent = "
           "..., hardfail = ... }` with the derivation in a comment");
    const toml::table& table = *node->as_table();
    onlyKeys(table, {"fail", "warn", "failpercent", "hardfail"}, "`image`");
    auto number = [&](std::string_view key) {
      const toml::node* value = table.get(key);
      if (!value) fail(lineOf(*node), fmt::format("`image` is missing `{}`", key));
      // nan and inf are numbers to TOML; a threshold must be a finite one.
      if (!numeric(*value) || !(*value->value<double>() >= 0) ||
          !std::isfinite(*value->value<double>()))
        fail(lineOf(*value), fmt::format("`image.{}` must be a finite number >= 0", key));
      return *value->value<double>();
    };
    ImageTolerance t{number("fail"), number("warn"), number("failpercent"), number("hardfail")};
    if (t.failPercent > 100)
      fail(lineOf(*table.get("failpercent")),
           "`image.failpercent` is a percentage of the pixels: at most 100");
    if (t.warn > t.fail) fail(lineOf(*node), "`image.warn` must not exceed `image.fail`");
    if (t.hardFail < t.fail) fail(lineOf(*node), "`image.hardfail` must not be below `image.fail`");
    return t;
  }

  Manifest read() const {
    toml::table root;
    try {
      root = toml::parse_file(path_.string());
    } catch (const toml::parse_error& error) {
      fail(static_cast<int>(error.source().begin.line),
           fmt::format("not valid TOML: {}", error.description()));
    }
    onlyKeys(root,
             {"id", "title", "source", "profile", "stages", "oracle", "constants", "timeout",
              "inputs", "uniforms", "capture", "expect", "compile_error", "max_undefined",
              "not_supported", "case"},
             "the manifest");
    Manifest m;
    m.path = path_;
    m.id = requiredString(root, "id", 1);
    if (const std::string problem = listingIdProblem(m.id); !problem.empty())
      fail(lineOf(*root.get("id")), problem);
    m.title = requiredString(root, "title", 1);
    const toml::table& source = requiredTable(root, "source", 1);
    onlyKeys(source, {"file", "where"}, "`source`");
    m.source.file = requiredString(source, "file", lineOf(source));
    m.source.where = requiredString(source, "where", lineOf(source));

    const std::string profile = optionalString(root, "profile");
    if (profile.empty() || profile == "core")
      m.profile = Profile::Core;
    else if (profile == "compatibility")
      m.profile = Profile::Compatibility;
    else
      fail(lineOf(*root.get("profile")),
           fmt::format("profile `{}`: use core or compatibility", profile));

    const toml::table& stages = requiredTable(root, "stages", 1);
    onlyKeys(stages, {"vertex", "fragment"}, "`stages`");
    m.vertexFile = requiredString(stages, "vertex", lineOf(stages));
    m.fragmentFile = optionalString(stages, "fragment");
    oracles(root, m);

    if (const toml::node* constants = root.get("constants")) {
      const toml::table* table = constants->as_table();
      if (!table) fail(lineOf(*constants), "`constants` must be a table of numbers");
      for (const auto& [name, value] : *table) {
        if (!numeric(value))
          fail(lineOf(value), fmt::format("constant `{}` must be a number", name.str()));
        floatOf(value, std::string(name.str()));  // kept as written: the decimal is folded
        m.constants[std::string(name.str())] = *value.value<double>();
      }
    }
    if (const toml::node* timeout = root.get("timeout")) {
      const double seconds = numeric(*timeout) ? *timeout->value<double>() : 0.0;
      if (!(seconds > 0 && seconds <= kMaxCaseTimeoutSeconds))
        fail(lineOf(*timeout),
             fmt::format("`timeout` must be a number of seconds above 0 and at most {:g} (a day)",
                         kMaxCaseTimeoutSeconds));
      m.timeoutSeconds = *timeout->value<double>();
    }
    m.inputs = bindings(root, "inputs");
    m.uniforms = bindings(root, "uniforms");

    const toml::table& capture = requiredTable(root, "capture", 1);
    onlyKeys(capture, {"vertex", "fragment"}, "`capture`");
    m.captureLine = lineOf(capture);
    if (const toml::node* vertex = capture.get("vertex")) {
      m.captureVertex = stringArray(*vertex, "capture.vertex");
      if (const std::string* again = firstRepeated(m.captureVertex))
        fail(lineOf(*vertex), fmt::format("`capture.vertex` names `{}` twice", *again));
    }
    if (const toml::node* fragment = capture.get("fragment"))
      m.captureFragment = fragmentCaptures(*fragment, m.fragmentFile.empty());
    // A hand-written oracle mirrors one stage; the derived oracle follows
    // the listing's text through both.
    if (!m.captureVertex.empty() && !m.captureFragment.empty() && !m.oracle.empty())
      fail(lineOf(capture),
           fmt::format("`capture` lists both vertex outputs and fragment values, and oracle `{}` "
                       "mirrors one stage: keep the one it mirrors (the derived oracle alone "
                       "may take both)",
                       m.oracle));
    if (m.captureVertex.empty() && m.captureFragment.empty())
      fail(lineOf(capture),
           "`capture` names nothing to read back; list outputs in "
           "`capture.vertex` or values in `capture.fragment`");

    const std::string expect = optionalString(root, "expect");
    if (expect.empty() || expect == "pass")
      m.expect = Expectation::Pass;
    else if (expect == "compile-error")
      m.expect = Expectation::CompileError;
    else
      fail(lineOf(*root.get("expect")),
           fmt::format("expect `{}`: use \"pass\" or \"compile-error\"", expect));
    if (const toml::node* undefined = root.get("max_undefined")) {
      if (!numeric(*undefined) || *undefined->value<double>() < 0 ||
          *undefined->value<double>() > 1)
        fail(lineOf(*undefined), "`max_undefined` must be a fraction from 0 to 1 (0.01 is 1 %)");
      m.maxUndefinedFraction = *undefined->value<double>();
    }
    if (const toml::node* unsupported = root.get("not_supported")) {
      const toml::table* table = unsupported->as_table();
      if (!table)
        fail(lineOf(*unsupported), "`not_supported` must be a table: { vk = \"reason\" }");
      for (const auto& [backend, reason] : *table) {
        if (backend.str() != "gl" && backend.str() != "vk")
          fail(lineOf(reason),
               fmt::format("not_supported: unknown backend `{}`; use gl or vk", backend.str()));
        if (!reason.is_string() || reason.value<std::string>()->empty())
          fail(lineOf(reason),
               fmt::format("not_supported.{} must give the reason as a string", backend.str()));
        m.notSupported[std::string(backend.str())] = *reason.value<std::string>();
      }
    }
    m.expectedErrors = expectedErrors(root, m);

    const toml::node* cases = root.get("case");
    if (!cases) fail(1, "no [[case]]: add at least one, e.g. [[case]] scene = \"sphere\"");
    const toml::array* caseArray = cases->as_array();
    if (!caseArray || !caseArray->is_array_of_tables())
      fail(lineOf(*cases), "`case` must be written as [[case]] tables");
    for (const toml::node& node : *caseArray) {
      const toml::table& table = *node.as_table();
      onlyKeys(table, {"scene", "checks", "image"}, "a [[case]]");
      CaseSpec spec;
      spec.line = lineOf(node);
      spec.scene = requiredString(table, "scene", spec.line);
      spec.line = lineOf(*table.get("scene"));  // point messages at the scene, not the header
      // A scene's name is a folder below --out and --golden (the case's id
      // ends in it): a path there ("../../x") put a case's images and
      // goldens outside both, on top of each other's.
      if (spec.scene.empty() || spec.scene == "." || spec.scene == ".." ||
          !std::all_of(spec.scene.begin(), spec.scene.end(), isListingIdCharacter))
        fail(spec.line,
             fmt::format("scene \"{}\" is not a scene's name: a name is letters, digits, '.', "
                         "'-', '_' and '+' (no '/'), as in \"sphere\"; the scenes are the files "
                         "of scenes/ without .toml",
                         spec.scene));
      if (const toml::node* checks = table.get("checks")) {
        spec.checks = stringArray(*checks, "checks");
        if (spec.checks.empty())
          fail(lineOf(*checks),
               "`checks` is empty: a case checks \"vectors\", \"image\" or "
               "both (leave `checks` out for \"vectors\")");
        if (const std::string* again = firstRepeated(spec.checks))
          fail(lineOf(*checks), fmt::format("`checks` names \"{}\" twice", *again));
      } else {
        spec.checks = {"vectors"};
      }
      // A case's id is the listing's id and its scene: two cases of one
      // scene would be two results under one id.
      for (const CaseSpec& earlier : m.cases)
        if (earlier.scene == spec.scene)
          fail(spec.line, fmt::format("a second [[case]] on scene \"{}\" (the first is at line "
                                      "{}): a case's id is the listing's and its scene; keep one",
                                      spec.scene, earlier.line));
      // Which names are known is the runner's registry (runner/checks/):
      // case validation says, before any driver loads.
      if (spec.has("image")) {
        // The picture is the fragment stage's output: a listing of one
        // vertex stage has none to compare.
        if (m.fragmentFile.empty())
          fail(spec.line,
               "an image check needs a fragment stage: add `fragment` to `stages`, or "
               "check \"vectors\" only");
        spec.image = imageTolerance(table, spec.line);
      } else if (const toml::node* image = table.get("image")) {
        fail(lineOf(*image),
             "`image` tolerances on a case that does not check \"image\": add "
             "\"image\" to its `checks`, or drop `image`");
      }
      m.cases.push_back(std::move(spec));
    }
    return m;
  }

 private:
  fs::path path_;
};

std::string readFile(const fs::path& path, const fs::path& manifest, const char* what) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw UsageError(fmt::format("{}: {} file {} cannot be read; check `stages` in the manifest",
                                 manifest.string(), what, path.string()));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

bool CaseSpec::has(const std::string& check) const {
  return std::find(checks.begin(), checks.end(), check) != checks.end();
}

bool isListingIdCharacter(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_' ||
         c == '+';
}

std::string listingIdProblem(const std::string& id) {
  const std::string form =
      "an id is one or more '/'-separated names of letters, digits, '.', '-', '_' and '+' "
      "(as in \"orange-book/14.1-fresnel\"): it becomes a folder below --out and --golden";
  if (id.empty()) return "the id is empty; " + form;
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = std::min(id.find('/', start), id.size());
    const std::string name = id.substr(start, end - start);
    if (name.empty())
      return fmt::format("id `{}` has an empty name (a leading, trailing or doubled '/'); {}", id,
                         form);
    if (name == "." || name == "..")
      return fmt::format("id `{}` has a `{}` name, which would leave its folder; {}", id, name,
                         form);
    for (char c : name)
      if (!isListingIdCharacter(c))
        return fmt::format("id `{}` holds {}; {}", id,
                           c == ' ' ? std::string("a space")
                           : std::isprint(static_cast<unsigned char>(c))
                               ? fmt::format("`{}`", c)
                               : fmt::format("the byte 0x{:02x}", static_cast<unsigned char>(c)),
                           form);
    if (end == id.size()) return {};
    start = end + 1;
  }
}

Manifest loadManifest(const fs::path& path) {
  if (!fs::is_regular_file(path))
    throw UsageError(fmt::format("{}: no such manifest file", path.string()));
  return ManifestReader(path).read();
}

std::vector<Manifest> loadManifests(const fs::path& dir) {
  if (!fs::is_directory(dir))
    throw UsageError(fmt::format("{}: not a folder of listings; pass --shaders DIR", dir.string()));
  std::vector<Manifest> manifests;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().filename() == "manifest.toml")
      manifests.push_back(loadManifest(entry.path()));
  std::sort(manifests.begin(), manifests.end(),
            [](const Manifest& a, const Manifest& b) { return a.id < b.id; });
  for (std::size_t k = 1; k < manifests.size(); ++k)
    if (manifests[k].id == manifests[k - 1].id)
      throw UsageError(fmt::format("{}: id `{}` is also used by {}; ids must be unique",
                                   manifests[k].path.string(), manifests[k].id,
                                   manifests[k - 1].path.string()));
  return manifests;
}

std::vector<Manifest> loadCatalog(const fs::path& dir) {
  std::vector<Manifest> manifests = loadManifests(dir);
  if (manifests.empty())
    throw UsageError(fmt::format(
        "{}: no listings here (no manifest.toml below it); pass --shaders a folder of listings, "
        "or start one with `snell init DIR`",
        dir.string()));
  return manifests;
}

ProgramSource loadProgram(const Manifest& manifest) {
  const fs::path dir = manifest.path.parent_path();
  ProgramSource program;
  program.profile = manifest.profile;
  program.vertexPath = (dir / manifest.vertexFile).string();
  program.vertex = readFile(program.vertexPath, manifest.path, "vertex");
  if (!manifest.fragmentFile.empty()) {
    program.fragmentPath = (dir / manifest.fragmentFile).string();
    program.fragment = readFile(program.fragmentPath, manifest.path, "fragment");
  }
  return program;
}

}  // namespace snell

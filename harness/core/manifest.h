#pragma once
// A listing's manifest: everything listing-specific, so the harness stays
// generic and a user can gate their own shaders by writing one.
#include <filesystem>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "core/program_source.h"
#include "core/values.h"

namespace snell {

struct SourceCitation {
  std::string file;   // a file in shared/sources, or a user's own reference
  std::string where;  // "Listings 14.1 and 14.2"
};

// A uniform or input bound either to a scene semantic ("scene.modelview")
// or to a literal value written in the manifest.
struct Binding {
  std::string name;                         // the GLSL name
  std::variant<std::string, Value> source;  // semantic (without "scene.") or literal
  int line = 0;                             // where it is written, for messages
  // `"default"`: the author wants the API's initial value (0, or (0,0,0,1)
  // for an input) and says so; snell sets nothing.
  bool apiDefault = false;
};

// OpenImageIO idiff's rules for one image comparison (see compare/).
struct ImageTolerance {
  double fail = 0;
  double warn = 0;
  double failPercent = 0;
  double hardFail = 0;
};

struct CaseSpec {
  std::string scene;
  std::vector<std::string> checks;  // "vectors", "image"
  ImageTolerance image;             // required with the "image" check
  int line = 0;
  bool has(const std::string& check) const;
};

// A value read back from the fragment stage: after the statement that ends
// on `line` of the fragment file, `name` (any GLSL expression of `type` in
// scope there) is written to a float render target of its own. Captures an
// oracle names as inputs feed it; those it names as outputs are checked.
struct FragmentCapture {
  std::string name;
  ValueType type = ValueType::Vec3;  // float, vec2 or vec3: the fourth channel marks "written"
  int line = 0;                      // in the fragment file
  int manifestLine = 0;              // where it is written, for messages
};

// What a listing is expected to do when it runs.
enum class Expectation { Pass, CompileError };

// The diagnostic a listing kept as published must fail with on one API:
// an error at `line` of the `stage` file, whose text contains `pattern`
// (when given). Any other failure to compile is a Fail, not the expected
// error.
struct ExpectedDiagnostic {
  std::string stage;    // "vertex" or "fragment"
  int line = 0;         // in that stage's file
  std::string pattern;  // a piece of the message; empty: any error at that line
  int manifestLine = 0;
};

struct Manifest {
  std::filesystem::path path;  // the manifest file
  std::string id;
  std::string title;
  SourceCitation source;
  Profile profile = Profile::Core;
  std::string vertexFile;  // relative to the manifest's folder
  std::string fragmentFile;
  // `oracle`: the hand-written oracle that mirrors the listing line by line
  // (its intent: an edited shader fails against it), "derived" for the one
  // built from the listing's own text (the spec: a driver outside it fails,
  // whatever the shader says), or both as an array. Absent means derived.
  std::string oracle;          // the hand-written oracle's name; empty when none
  bool derivedOracle = false;  // the derived oracle gates the listing too
  int oracleLine = 0;
  ConstantMap constants;
  std::vector<Binding> inputs;
  std::vector<Binding> uniforms;
  std::vector<std::string> captureVertex;
  std::vector<FragmentCapture> captureFragment;
  int captureLine = 0;
  // `expect = "compile-error"`: as published, the listing must not compile;
  // the case passes as ExpectedCompileError with the diagnostic quoted.
  Expectation expect = Expectation::Pass;
  // `[compile_error.gl]`, `[compile_error.vk]`: the expected diagnostic per
  // API, required with `expect = "compile-error"`.
  std::map<std::string, ExpectedDiagnostic> expectedErrors;
  // `max_undefined`: the largest fraction of a capture's samples the spec
  // may leave undefined before the case fails (nothing gated is no pass).
  double maxUndefinedFraction = 0.01;
  // `not_supported = { vk = "reason" }`: backends the listing cannot run on,
  // each with the reason the report gives.
  std::map<std::string, std::string> notSupported;
  std::vector<CaseSpec> cases;
  double timeoutSeconds = 60;  // per case; `snell run --timeout` overrides
};

// The longest time a case may be given, in seconds (a day): the same
// bound as `snell run --timeout`.
inline constexpr double kMaxCaseTimeoutSeconds = 86400.0;

// Why `id` cannot be a listing's id, or empty when it can. A case id is a
// path below --out and --golden (<id>/<scene>/...), and a filter and an
// expectations file name it: one or more '/'-separated names of letters,
// digits, '.', '-', '_' and '+', none of them "." or "..".
std::string listingIdProblem(const std::string& id);
// A character an id's names may hold.
bool isListingIdCharacter(char c);

// Parses one manifest. Every problem is a UsageError of the form
// "FILE:LINE: what is wrong; what to do".
Manifest loadManifest(const std::filesystem::path& path);

// Every manifest.toml below `dir`, sorted by id; duplicate ids are an error.
std::vector<Manifest> loadManifests(const std::filesystem::path& dir);
// The same for a command that runs or lists the catalog: a folder with no
// manifest.toml below it is a UsageError (a mistyped --shaders), not a run
// of nothing.
std::vector<Manifest> loadCatalog(const std::filesystem::path& dir);

// The stage files as published; a missing file is a UsageError.
ProgramSource loadProgram(const Manifest& manifest);

}  // namespace snell

// snell init's draft: bindings by convention, placeholders loadManifest
// refuses, captures of both stages, and the catalog's own manifests as the
// truth its guesses are held to.
#include "core/manifest_draft.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <tuple>

#include "core/case.h"
#include "core/errors.h"
#include "core/manifest.h"
#include "core/manifest_check.h"

namespace snell {
namespace {

namespace fs = std::filesystem;

// LearnOpenGL, "Cubemaps", refraction (vertex and fragment shaders as printed).
constexpr const char* kLearnOpenGlVertex = R"(#version 330 core
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;

out vec3 Normal;
out vec3 Position;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

void main()
{
    Normal = mat3(transpose(inverse(model))) * aNormal;
    Position = vec3(model * vec4(aPos, 1.0));
    gl_Position = projection * view * vec4(Position, 1.0);
}
)";

constexpr const char* kLearnOpenGlFragment = R"(#version 330 core
out vec4 FragColor;

in vec3 Normal;
in vec3 Position;

uniform vec3 cameraPos;
uniform samplerCube skybox;

void main()
{
    float ratio = 1.00 / 1.52;
    vec3 I = normalize(Position - cameraPos);
    vec3 R = refract(I, normalize(Normal), ratio);
    FragColor = vec4(texture(skybox, R).rgb, 1.0);
}
)";

// three.js RawShaderMaterial: the built-ins declared by hand, GLSL ES 1.00 style.
constexpr const char* kThreeVertex = R"(precision highp float;
uniform mat4 modelMatrix;
uniform mat4 modelViewMatrix;
uniform mat4 projectionMatrix;
uniform mat3 normalMatrix;
uniform vec3 cameraPosition;
uniform float refractionRatio;
attribute vec3 position;
attribute vec3 normal;
varying vec3 vRefract;
void main() {
  vec4 worldPosition = modelMatrix * vec4(position, 1.0);
  vec3 worldNormal = normalize(mat3(modelMatrix) * normal);
  vec3 I = worldPosition.xyz - cameraPosition;
  vRefract = refract(normalize(I), worldNormal, refractionRatio);
  vec3 unused = normalMatrix * normal;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
)";

constexpr const char* kThreeFragment = R"(precision highp float;
uniform samplerCube envMap;
varying vec3 vRefract;
void main() {
  gl_FragColor = textureCube(envMap, vRefract);
}
)";

class ManifestDraft : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("snell-draft-" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  void put(const std::string& file, const std::string& text) { std::ofstream(dir_ / file) << text; }

  // The draft with the citation filled in, as its author would, written
  // beside the stages and loaded.
  Manifest draftAndLoad(const std::string& fill = "") {
    std::string text = draftManifest({dir_, "", "", ""});
    text = std::regex_replace(text, std::regex("source = .*"),
                              "source = { file = \"https://example.org\", where = \"here\" }");
    if (!fill.empty()) text = std::regex_replace(text, std::regex("\"FILL IN: [^\"]*\""), fill);
    std::ofstream(dir_ / "manifest.toml") << text;
    return loadManifest(dir_ / "manifest.toml");
  }

  static std::string semantic(const std::vector<Binding>& bindings, const std::string& name) {
    for (const Binding& b : bindings)
      if (b.name == name) return b.apiDefault ? "default" : std::get<std::string>(b.source);
    return "(unbound)";
  }

  // The manifest checks snell run makes before any driver loads.
  static void expectRunnable(const Manifest& m) {
    for (const CaseSpec& spec : m.cases) {
      const ResolvedBindings bindings = resolveBindings(m, makeScene(spec.scene));
      EXPECT_NO_THROW(checkManifestAgainstProgram(m, loadProgram(m), bindings)) << spec.scene;
    }
  }

  fs::path dir_;
};

TEST_F(ManifestDraft, LearnOpenGlRefractionBindsWithoutRenaming) {
  put("refraction.vert", kLearnOpenGlVertex);
  put("refraction.frag", kLearnOpenGlFragment);
  const Manifest m = draftAndLoad();
  EXPECT_TRUE(m.derivedOracle);
  EXPECT_EQ(m.oracle, "");
  EXPECT_EQ(m.profile, Profile::Core);
  EXPECT_EQ(m.vertexFile, "refraction.vert");
  EXPECT_EQ(m.fragmentFile, "refraction.frag");
  EXPECT_EQ(semantic(m.inputs, "aPos"), "position");
  EXPECT_EQ(semantic(m.inputs, "aNormal"), "normal");
  EXPECT_EQ(semantic(m.uniforms, "model"), "model");
  EXPECT_EQ(semantic(m.uniforms, "view"), "view");
  EXPECT_EQ(semantic(m.uniforms, "projection"), "projection");
  EXPECT_EQ(semantic(m.uniforms, "cameraPos"), "eye_position");
  EXPECT_EQ(semantic(m.uniforms, "skybox"), "environment");
  EXPECT_EQ(m.captureVertex, (std::vector<std::string>{"Normal", "Position"}));
  // I and R before the lookup, with the lines that compute them; the
  // inputs they read, from the first statement that reads each.
  std::vector<std::tuple<std::string, ValueType, int>> fragment;
  for (const FragmentCapture& c : m.captureFragment) fragment.emplace_back(c.name, c.type, c.line);
  EXPECT_EQ(fragment,
            (std::vector<std::tuple<std::string, ValueType, int>>{{"Position", ValueType::Vec3, 13},
                                                                  {"Normal", ValueType::Vec3, 14},
                                                                  {"I", ValueType::Vec3, 13},
                                                                  {"R", ValueType::Vec3, 14}}));
  ASSERT_EQ(m.cases.size(), 3u);
  EXPECT_EQ(m.cases[0].checks, std::vector<std::string>{"vectors"});
  EXPECT_EQ(m.cases[1].checks, (std::vector<std::string>{"vectors", "image"}));
  EXPECT_EQ(m.cases[1].image.fail, 0.004);
  // The stretched sphere, whose normal matrix is no rotation.
  EXPECT_EQ(m.cases[2].scene, "stretched");
  EXPECT_EQ(m.cases[2].checks, (std::vector<std::string>{"vectors", "image"}));
  EXPECT_NE(m.cases[0].scene, m.cases[1].scene);  // case ids stay unique
  expectRunnable(m);
}

// A folder named in Latin-1 becomes the draft's title: written as the
// character of that code, where a spelled-out \xNN was no TOML escape and
// the draft could not be read.
TEST_F(ManifestDraft, ATitleFromAFolderNamedInAnotherEncodingIsValidToml) {
  const fs::path folder = dir_ / (std::string("caf") + "\xe9");
  fs::create_directories(folder);
  std::ofstream(folder / "refraction.vert") << kLearnOpenGlVertex;
  std::string text = draftManifest({folder, "", "", "x/cafe"});
  text = std::regex_replace(text, std::regex("source = .*"),
                            "source = { file = \"https://example.org\", where = \"here\" }");
  std::ofstream(folder / "manifest.toml") << text;
  EXPECT_EQ(loadManifest(folder / "manifest.toml").title, "caf\u00e9");
}

// A full-screen listing whose colour reads gl_FragCoord: the image case the
// draft had was refused by run (the derived reference image has no
// gl_FragCoord); the draft checks its vectors and says why.
TEST_F(ManifestDraft, AScreenSpaceListingIsDraftedWithVectorsOnly) {
  const fs::path listing = SNELL_SOURCE_ROOT "/shaders/shadertoy/lens";
  fs::copy_file(listing / "lens.frag", dir_ / "lens.frag");
  fs::copy_file(listing / "fullscreen.vert", dir_ / "fullscreen.vert");
  const Draft draft = draftOf({dir_, "", "", ""});
  EXPECT_FALSE(draft.imageCases);
  EXPECT_NE(draft.text.find("reads gl_FragCoord"), std::string::npos) << draft.text;
  const Manifest m = draftAndLoad();
  ASSERT_EQ(m.cases.size(), 1u);
  EXPECT_EQ(m.cases[0].scene, "fullscreen");
  EXPECT_EQ(m.cases[0].checks, std::vector<std::string>{"vectors"});
}

// A file name that is not UTF-8, which a manifest's TOML cannot name, is
// refused, naming the file.
TEST_F(ManifestDraft, AFileNameThatIsNotUtf8IsRefused) {
  put(std::string("r\xe9") + "fraction.vert", kLearnOpenGlVertex);
  try {
    draftManifest({dir_, "", "", ""});
    FAIL() << "drafted";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("r\\xe9fraction.vert: the file's name is not UTF-8"),
              std::string::npos)
        << error.what();
  }
}

// A statement that looks a colour up is no direction to check: Listing
// 14.1's fragment stage (two lookups and a mix) gets no fragment capture,
// where capturing `refractColor` and the input it reads left the derived
// oracle nothing to compute, and snell run refused the draft.
TEST_F(ManifestDraft, ALookedUpColourIsNotCaptured) {
  const fs::path listing = SNELL_SOURCE_ROOT "/shaders/orange-book/14.1-fresnel";
  fs::copy_file(listing / "fresnel.vert", dir_ / "fresnel.vert");
  fs::copy_file(listing / "fresnel.frag", dir_ / "fresnel.frag");
  const Manifest m = draftAndLoad();
  EXPECT_TRUE(m.captureFragment.empty()) << m.captureFragment.size();
  EXPECT_EQ(m.captureVertex, (std::vector<std::string>{"Reflect", "Refract", "Ratio"}));
  expectRunnable(m);
}

// The per-channel chromatic pattern: `vec3 refr;` is declared empty and
// filled channel by channel from lookups. It is a colour, and at its line it
// holds nothing: it is not captured (a capture there made a draft that
// `snell run` refused), and the vertex stage's directions are.
TEST_F(ManifestDraft, AColourFilledChannelByChannelIsNotCaptured) {
  put("chroma.vert", R"(#version 450
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform vec3 cameraPos;
uniform float eta;
layout (location = 0) out vec3 RefractR;
layout (location = 1) out vec3 RefractB;
void main() {
  vec4 world = model * vec4(aPos, 1.0);
  vec3 N = normalize(mat3(model) * aNormal);
  vec3 I = normalize(world.xyz - cameraPos);
  RefractR = refract(I, N, eta);
  RefractB = refract(I, N, eta * 1.02);
  gl_Position = projection * view * world;
}
)");
  put("chroma.frag", R"(#version 450
layout (location = 0) in vec3 RefractR;
layout (location = 1) in vec3 RefractB;
layout (binding = 0) uniform samplerCube skybox;
layout (location = 0) out vec4 FragColor;
void main() {
  vec3 refr;
  refr.r = texture(skybox, RefractR).r;
  refr.g = 0.0;
  refr.b = texture(skybox, RefractB).b;
  FragColor = vec4(refr, 1.0);
}
)");
  const Manifest m = draftAndLoad("0.66");
  EXPECT_TRUE(m.captureFragment.empty()) << m.captureFragment.size();
  EXPECT_EQ(m.captureVertex, (std::vector<std::string>{"RefractR", "RefractB"}));
  expectRunnable(m);
}

TEST_F(ManifestDraft, ThreeJsBuiltInsBindAndAPlainUniformIsLeftToTheAuthor) {
  put("glass.vert", kThreeVertex);
  put("glass.frag", kThreeFragment);
  const std::string text = draftManifest({dir_, "", "", ""});
  EXPECT_TRUE(std::regex_search(text, std::regex("\nrefractionRatio +\\= \"FILL IN: a float\"")))
      << text;
  const Manifest m = draftAndLoad("0.66");
  EXPECT_EQ(m.profile, Profile::Compatibility);  // no #version: GLSL 1.10
  EXPECT_EQ(semantic(m.inputs, "position"), "position");
  EXPECT_EQ(semantic(m.inputs, "normal"), "normal");
  EXPECT_EQ(semantic(m.uniforms, "modelMatrix"), "model");
  EXPECT_EQ(semantic(m.uniforms, "modelViewMatrix"), "modelview");
  EXPECT_EQ(semantic(m.uniforms, "projectionMatrix"), "projection");
  EXPECT_EQ(semantic(m.uniforms, "normalMatrix"), "normal_matrix");  // eye space, beside modelview
  EXPECT_EQ(semantic(m.uniforms, "cameraPosition"), "eye_position");
  EXPECT_EQ(semantic(m.uniforms, "envMap"), "environment");
  EXPECT_EQ(m.captureVertex, std::vector<std::string>{"vRefract"});
  EXPECT_TRUE(m.captureFragment.empty());  // the fragment computes no vector of its own
  expectRunnable(m);
}

TEST_F(ManifestDraft, AnUnfilledPlaceholderIsRefusedWithItsLine) {
  put("glass.vert", kThreeVertex);
  put("glass.frag", kThreeFragment);
  try {
    draftAndLoad();
    FAIL() << "a manifest with a placeholder loaded";
  } catch (const UsageError& error) {
    const std::string text = draftManifest({dir_, "", "", ""});
    std::size_t line = 1;
    const std::size_t end = text.find("\nrefractionRatio ");
    ASSERT_NE(end, std::string::npos) << text;
    for (std::size_t at = 0; at <= end; ++at) line += text[at] == '\n';
    const std::string message = error.what();
    EXPECT_NE(message.find(fmt::format("manifest.toml:{}:", line)), std::string::npos) << message;
    EXPECT_NE(message.find("`refractionRatio` is still the placeholder \"FILL IN: a float\""),
              std::string::npos)
        << message;
  }
}

// A bool uniform: the draft says snell cannot set one, and "default" for it
// is refused as that, not as a texture binding.
TEST_F(ManifestDraft, ABoolUniformIsOneSnellCannotSet) {
  put("flip.vert", R"(#version 330 core
in vec3 aPos;
uniform bool flip;
out vec3 R;
void main() {
  R = flip ? aPos : -aPos;
  gl_Position = vec4(aPos, 1.0);
}
)");
  const std::string text = draftManifest({dir_, "", "", ""});
  EXPECT_NE(text.find("not a bool"), std::string::npos) << text;
  const Manifest m = draftAndLoad("\"default\"");
  const ResolvedBindings bindings = resolveBindings(m, makeScene(m.cases.at(0).scene));
  try {
    checkManifestAgainstProgram(m, loadProgram(m), bindings);
    FAIL() << "a bool uniform bound to \"default\" was taken";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("`flip` is a bool, which snell cannot set"),
              std::string::npos)
        << error.what();
  }
}

TEST_F(ManifestDraft, TheCitationPlaceholderIsRefusedToo) {
  put("refraction.vert", kLearnOpenGlVertex);
  writeDraftManifest({dir_, "", "", ""}, false);
  try {
    loadManifest(dir_ / "manifest.toml");
    FAIL() << "a manifest without its citation loaded";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("still the placeholder \"FILL IN: the document"),
              std::string::npos)
        << error.what();
  }
}

TEST_F(ManifestDraft, NormalMatrixBesideAModelMatrixIsTheWorldSpaceOne) {
  put("a.vert", R"(#version 330 core
in vec3 aPos;
in vec3 aNormal;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform mat3 normalMatrix;
uniform mat3 weird;
out vec3 N;
void main() {
  N = normalMatrix * weird * aNormal;
  gl_Position = projection * view * model * vec4(aPos, 1.0);
}
)");
  const Manifest m = draftAndLoad("\"scene.normal_matrix\"");
  EXPECT_EQ(semantic(m.uniforms, "normalMatrix"), "model_normal_matrix");
  EXPECT_EQ(semantic(m.uniforms, "weird"), "normal_matrix");  // the author's fill
  EXPECT_EQ(m.fragmentFile, "");
  ASSERT_EQ(m.cases.size(), 2u);  // no fragment stage: no image case
  EXPECT_EQ(m.cases[1].scene, "stretched");
  EXPECT_EQ(m.cases[1].checks, std::vector<std::string>{"vectors"});
}

TEST_F(ManifestDraft, UnreadDeclarationsAreLeftOutAndSaidSo) {
  put("a.vert", R"(#version 330 core
in vec3 aPos;
in vec3 aColor;
uniform mat4 projection;
uniform float unusedScale;
out vec3 P;
void main() { P = aPos; gl_Position = projection * vec4(aPos, 1.0); }
)");
  const std::string text = draftManifest({dir_, "", "", ""});
  EXPECT_NE(text.find("# Declared but never read, so left unbound: aColor"), std::string::npos)
      << text;
  EXPECT_NE(text.find("# Declared but never read, so left unbound: unusedScale"), std::string::npos)
      << text;
  EXPECT_EQ(text.find("FILL IN: a float"), std::string::npos) << text;
}

TEST_F(ManifestDraft, LegacyBuiltInsBindTheFixedFunctionState) {
  put("a.vert", R"(#version 120
varying vec3 N;
void main() { N = gl_NormalMatrix * gl_Normal; gl_Position = ftransform(); }
)");
  const Manifest m = draftAndLoad();
  EXPECT_EQ(m.profile, Profile::Compatibility);
  EXPECT_EQ(semantic(m.inputs, "gl_Normal"), "normal");
  EXPECT_EQ(semantic(m.uniforms, "gl_ModelViewMatrix"), "modelview");
  EXPECT_EQ(semantic(m.uniforms, "gl_ProjectionMatrix"), "projection");
  expectRunnable(m);
}

std::string errorOf(const DraftRequest& request) {
  try {
    draftManifest(request);
  } catch (const UsageError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no error";
  return {};
}

TEST_F(ManifestDraft, BadFoldersGetOneClearMessage) {
  EXPECT_NE(errorOf({dir_ / "missing", "", "", ""}).find("no such folder"), std::string::npos);
  EXPECT_NE(errorOf({dir_, "", "", ""}).find("holds no GLSL vertex stage (*.vert)"),
            std::string::npos);
  put("a.vert", "void main() {}\n");
  put("b.vert", "void main() {}\n");
  EXPECT_NE(errorOf({dir_, "", "", ""})
                .find("holds 2 vertex stages (a.vert, b.vert); name one "
                      "with --vertex"),
            std::string::npos);
  EXPECT_NE(errorOf({dir_, "c.vert", "", ""}).find("c.vert: no such vertex stage file"),
            std::string::npos);
  put("notes.vert", "this is not GLSL\n");
  EXPECT_NE(errorOf({dir_, "notes.vert", "", ""}).find("notes.vert: no `void main()`"),
            std::string::npos);
  // Nothing to read back: no outputs, no fragment stage.
  EXPECT_NE(errorOf({dir_, "a.vert", "", ""}).find("nothing to read back"), std::string::npos);
}

TEST_F(ManifestDraft, AnExistingManifestIsNeverOverwrittenWithoutForce) {
  put("refraction.vert", kLearnOpenGlVertex);
  put("manifest.toml", "mine\n");
  EXPECT_THROW(writeDraftManifest({dir_, "", "", ""}, false), UsageError);
  std::ifstream in(dir_ / "manifest.toml");
  std::string kept;
  std::getline(in, kept);
  EXPECT_EQ(kept, "mine");
  writeDraftManifest({dir_, "", "", ""}, true);
  std::ifstream replaced(dir_ / "manifest.toml");
  std::getline(replaced, kept);
  EXPECT_EQ(kept.rfind("# Drafted by `snell init`", 0), 0u) << kept;
}

// The catalog's manifests were written by hand: every binding the draft
// makes from the same stage files must agree with them (a guess that is
// not clear must be left to the author, not made).
TEST(ManifestDraftCatalog, EveryConventionalBindingAgreesWithTheCatalog) {
  int agreed = 0;
  for (const Manifest& m : loadManifests(SNELL_SOURCE_ROOT "/shaders")) {
    if (m.expect != Expectation::Pass) continue;
    const fs::path dir = m.path.parent_path();
    std::string text;
    try {
      text = draftManifest({dir, m.vertexFile, m.fragmentFile, ""});
    } catch (const UsageError& error) {
      ADD_FAILURE() << m.id << ": " << error.what();
      continue;
    }
    const std::regex binding(R"re(^("?[\w\[\]]+"?)\s*=\s*"scene\.(\w+)")re");
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
      std::smatch match;
      if (!std::regex_search(line, match, binding)) continue;
      std::string name = match[1].str();
      if (name.front() == '"') name = name.substr(1, name.size() - 2);
      std::string expected = "(unbound)";
      for (const auto* list : {&m.inputs, &m.uniforms})
        for (const Binding& b : *list)
          if (b.name == name && !b.apiDefault && std::holds_alternative<std::string>(b.source))
            expected = std::get<std::string>(b.source);
      EXPECT_EQ(match[2].str(), expected) << m.id << ": " << line;
      ++agreed;
    }
  }
  EXPECT_GT(agreed, 50);
}

}  // namespace
}  // namespace snell

#include "runner/fragment_vector_check.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>

#include "core/errors.h"
#include "core/phase_clock.h"
#include "oracle/vertex_oracle.h"
#include "runner/builtin_eval.h"
#include "runner/failure_report.h"
#include "runner/image_check.h"
#include "runner/listing_oracles.h"

namespace snell {
namespace {

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

void checkCapturesAgainstOracle(const Manifest& m, const NamedOracle& named) {
  const VertexOracle& oracle = *named.oracle;
  const std::string& label = named.label;
  // The derived oracle computes every capture that is not one of the
  // stage's inputs; an input it does not read is left unread.
  const bool derived = label == kDerivedOracleLabel;
  const std::vector<std::string> inputs = oracle.inputs(), outputs = oracle.outputs();
  bool anyOutput = false;
  for (const FragmentCapture& capture : m.captureFragment) {
    if (contains(outputs, capture.name))
      anyOutput = true;
    else if (!derived && !contains(inputs, capture.name))
      throw UsageError(fmt::format(
          "{}:{}: capture `{}` is neither an input nor an output of oracle `{}` (inputs: {}; "
          "outputs: {}); capture only what the oracle reads or computes",
          m.path.string(), capture.manifestLine, capture.name, label, fmt::join(inputs, ", "),
          fmt::join(outputs, ", ")));
  }
  for (const std::string& input : inputs)
    if (std::none_of(m.captureFragment.begin(), m.captureFragment.end(),
                     [&](const FragmentCapture& c) { return c.name == input; }))
      throw UsageError(
          fmt::format("{}:{}: oracle `{}` reads `{}`; capture it in "
                      "`capture.fragment` at a line where it holds its value",
                      m.path.string(), m.captureLine, label, input));
  if (!anyOutput)
    throw UsageError(
        fmt::format("{}:{}: `capture.fragment` reads none of oracle `{}`'s outputs "
                    "({}), so nothing would be checked",
                    m.path.string(), m.captureLine, label, fmt::join(outputs, ", ")));
}

struct Pixel {
  int x = 0, y = 0;
};

// The values of one probe at the chosen pixels, packed as the oracle reads them.
std::vector<float> valuesAt(const Image& probe, const std::vector<Pixel>& pixels, int components) {
  std::vector<float> data;
  data.reserve(pixels.size() * static_cast<std::size_t>(components));
  for (const Pixel& p : pixels) {
    const float* texel = probe.at(p.x, p.y);
    data.insert(data.end(), texel, texel + components);
  }
  return data;
}

// Whether a probe's write reached pixel (x, y): its alpha is 1 there.
bool written(const Image& probe, int x, int y) { return probe.at(x, y)[3] == 1.0f; }

// The probes' images turned into what the oracle and the comparison read:
// the pixels where every input of every oracle was written, the oracles'
// inputs there, and the captured outputs.
struct ProbeValues {
  std::vector<Pixel> pixels;
  AttributeMap inputs;
  std::vector<CapturedVarying> observed;
  std::string unwritten;  // output probes missing where the inputs were written
};

ProbeValues probeValues(const Manifest& m, const Scene& scene,
                        const std::vector<NamedOracle>& oracles, const RenderOutcome& outcome) {
  // Charged as a vertex capture's split of its buffer into varyings is.
  const PhaseScope reading(Phase::ReadBack);
  std::vector<std::string> inputNames;
  for (const NamedOracle& oracle : oracles)
    for (const std::string& name : oracle.oracle->inputs())
      if (!contains(inputNames, name)) inputNames.push_back(name);
  const auto isOracleInput = [&](const FragmentCapture& capture) {
    return contains(inputNames, capture.name);
  };
  std::vector<const Image*> inputProbes;
  for (std::size_t k = 0; k < m.captureFragment.size(); ++k)
    if (isOracleInput(m.captureFragment[k])) inputProbes.push_back(&outcome.probes[k]);

  ProbeValues found;
  for (int y = 0; y < scene.height; ++y)
    for (int x = 0; x < scene.width; ++x)
      if (std::all_of(inputProbes.begin(), inputProbes.end(),
                      [&](const Image* probe) { return written(*probe, x, y); }))
        found.pixels.push_back({x, y});

  const auto isInput = [&](const FragmentCapture& capture) {
    return isOracleInput(capture) ||
           std::none_of(oracles.begin(), oracles.end(), [&](const NamedOracle& oracle) {
             return contains(oracle.oracle->outputs(), capture.name);
           });
  };
  for (std::size_t k = 0; k < m.captureFragment.size(); ++k) {
    const FragmentCapture& capture = m.captureFragment[k];
    const int components = componentCount(capture.type);
    std::vector<float> values = valuesAt(outcome.probes[k], found.pixels, components);
    if (isInput(capture)) {
      found.inputs[capture.name] = AttributeStream{capture.name, components, std::move(values)};
      continue;
    }
    const std::size_t missing = static_cast<std::size_t>(
        std::count_if(found.pixels.begin(), found.pixels.end(),
                      [&](const Pixel& p) { return !written(outcome.probes[k], p.x, p.y); }));
    if (missing)
      found.unwritten += fmt::format(
          "{}: not written at {} of the {} pixels where the oracle's "
          "inputs were (line {} did not run there)\n",
          capture.name, missing, found.pixels.size(), capture.line);
    found.observed.push_back(CapturedVarying{capture.name, components, std::move(values)});
  }
  return found;
}

std::string describe(const VaryingCheck& v, const std::vector<Pixel>& pixels,
                     const AttributeMap& inputs, const UniformMap& uniforms,
                     const FragmentCapture& capture, const std::string& fragmentPath) {
  std::string text = fmt::format(
      "{}: {} of {} components outside the spec interval (read after {}:{}); worst "
      "first:\n",
      v.name, v.failed, v.checked, fragmentPath, capture.line);
  for (const ComponentFailure& f : v.worstFailures) {
    const Pixel& p = pixels.at(f.vertex);
    text += fmt::format(
        "  pixel ({}, {}) [{}]: got {:.9g}, exact {:.9g}, allowed [{:.9g}, {:.9g}]{}\n"
        "    inputs: {}\n",
        p.x, p.y, f.component, f.observed, f.reference, f.lo, f.hi,
        f.ways > 1 ? fmt::format(" (nearest of {} ways)", f.ways) : "",
        sampleInputs(inputs, uniforms, f.vertex));
  }
  return text;
}

std::vector<FragmentProbe> probesOf(const Manifest& m) {
  std::vector<FragmentProbe> probes;
  for (const FragmentCapture& capture : m.captureFragment)
    probes.push_back({capture.name, capture.type, capture.line});
  return probes;
}

void requireDrawingScene(const Manifest& m, const Scene& scene) {
  if (!scene.draws())
    throw UsageError(
        fmt::format("scene `{}` draws nothing, so no fragment runs; "
                    "`capture.fragment` of {} needs a scene with [image]",
                    scene.name, m.id));
}

}  // namespace

void checkFragmentCaptures(const Manifest& m, const ProgramSource& program, const Scene& scene) {
  if (m.captureFragment.empty()) return;
  requireDrawingScene(m, scene);
  for (const NamedOracle& oracle : vectorOracles(m, CaptureStage::Fragment))
    checkCapturesAgainstOracle(m, oracle);
  insertFragmentProbes(program.fragment, program.fragmentPath, probesOf(m),
                       ProbeOutputStyle::Outputs);
}

FragmentVectorCheck checkFragmentVectors(Backend& backend, const Manifest& m, const Scene& scene,
                                         const ResolvedBindings& bindings,
                                         OracleCache& oracleCache) {
  requireDrawingScene(m, scene);
  const std::vector<NamedOracle> oracles = vectorOracles(m, CaptureStage::Fragment);
  for (const NamedOracle& oracle : oracles) checkCapturesAgainstOracle(m, oracle);

  RenderJob job = sceneRenderJob(m, scene, bindings);
  job.probes = probesOf(m);
  const RenderOutcome outcome = backend.render(job);
  FragmentVectorCheck check;
  if (!outcome.compile.ok) {
    check.compiled = false;
    check.compileLog = outcome.compile.log;
    return check;
  }

  const ProbeValues probed = probeValues(m, scene, oracles, outcome);
  const std::vector<Pixel>& pixels = probed.pixels;
  const AttributeMap& inputs = probed.inputs;
  check.pixels = pixels.size();
  check.unwritten = probed.unwritten;

  for (const NamedOracle& oracle : oracles) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<OracleVarying> expected = [&] {
      const PhaseScope phase(Phase::Oracle);
      return oracleCache.evaluate(oracle, {bindings.uniforms, m.constants, inputs, pixels.size(),
                                           precisionRulesForApi(backend.driverInfo().api)});
    }();
    check.oracleSeconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const PhaseScope comparing(Phase::Compare);
    std::string failures;
    for (const CapturedVarying& values : probed.observed) {
      const auto found =
          std::find_if(expected.begin(), expected.end(),
                       [&](const OracleVarying& v) { return v.name == values.name; });
      VaryingCheck varying = checkVarying(*found, values);
      const auto capture =
          std::find_if(m.captureFragment.begin(), m.captureFragment.end(),
                       [&](const FragmentCapture& c) { return c.name == values.name; });
      if (varying.failed)
        failures += describe(varying, pixels, inputs, bindings.uniforms, *capture,
                             job.program.fragmentPath);
      // With two oracles the second one's checks carry its label.
      if (&oracle != &oracles.front()) varying.name += " (" + oracle.label + ")";
      check.varyings.push_back(std::move(varying));
    }
    if (oracles.size() > 1 && !failures.empty())
      failures = "against oracle " + oracle.label + ":\n" + failures;
    check.failures += failures;
  }
  if (!check.failures.empty())
    check.failures = constantsDisagreement(m, job.program) + check.failures;
  return check;
}

}  // namespace snell

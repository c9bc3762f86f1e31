#include "sweep/listing_draw.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <sstream>

#include "core/errors.h"

namespace snell::sweep {

std::string whyNotSwept(const Manifest& manifest) {
  if (manifest.expect == Expectation::CompileError)
    return "does not compile as published (expect = \"compile-error\"); its corrected listing "
           "is swept";
  if (manifest.oracle.empty())
    return "has no hand-written oracle, which the sweep holds a listing's draws against";
  if (manifest.captureVertex.empty()) {
    std::vector<std::string> scenes;
    for (const CaseSpec& c : manifest.cases)
      if (std::find(scenes.begin(), scenes.end(), c.scene) == scenes.end())
        scenes.push_back(c.scene);
    return fmt::format(
        "reads back from the fragment stage only: its inputs come from a scene's pixels "
        "(interpolated or screen-space), which no sweep vertex can set; `snell run` covers "
        "it on its scene{} ({})",
        scenes.size() == 1 ? "" : "s", fmt::join(scenes, ", "));
  }
  return "";
}

PreparedDraw prepareDraw(const DrawSpec& spec, const Scene& base) {
  PreparedDraw draw;
  draw.spec = spec;
  const Manifest published = loadManifest(spec.manifestPath);
  const ProgramSource program = loadProgram(published);
  draw.eta = etaBinding(published);
  draw.manifest = published;
  draw.program = program;
  draw.etaValue = draw.eta.empty() ? 0.0 : draw.eta.published;
  if (spec.eta > 0 && !draw.eta.empty()) {
    std::string why;
    std::optional<EtaVariant> variant = withEta(published, program, draw.eta, spec.eta, why);
    if (!variant) throw SetupError(fmt::format("{}: {}", spec.manifestPath, why));
    draw.manifest = std::move(variant->manifest);
    draw.program = std::move(variant->program);
    draw.etaValue = spec.eta;
  }
  const SweepGrid grid = spec.quick ? quickGrid() : fullGrid();
  // Bad inputs once per listing (unit frame, as published), not at every eta.
  const bool badInputs = spec.frame == "unit" && spec.eta == 0;
  // Dense around the critical angle of every eta the listing refracts with.
  std::vector<double> etas = {draw.etaValue};
  for (const std::string& name : draw.eta.constants)
    etas.push_back(draw.manifest.constants.at(name));
  for (const Binding& u : draw.manifest.uniforms)
    for (const std::string& name : draw.eta.uniforms)
      if (u.name == name) etas.push_back(std::get<Value>(u.source).data.at(0));
  // A diffraction listing divides by dot(N, H): where its eye and light
  // are literal eye-space positions, the draw adds the normals that take
  // that to 0.
  std::optional<std::array<double, 3>> eye, light;
  for (const Binding& u : draw.manifest.uniforms) {
    if (!std::holds_alternative<Value>(u.source)) continue;
    const Value& v = std::get<Value>(u.source);
    if (v.type != ValueType::Vec3) continue;
    std::string name = u.name;
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const std::array<double, 3> p = {v.data[0], v.data[1], v.data[2]};
    if (name == "eyeposition") eye = p;
    if (name == "lightposition") light = p;
  }
  std::optional<HalfVector> half;
  if (eye && light && draw.manifest.oracle.find("diffraction") != std::string::npos)
    half = halfVectorAt(*eye, *light);
  draw.diffraction = half.has_value();
  draw.points = listingPoints(grid, etas, badInputs, half ? &*half : nullptr);
  draw.scene = listingScene(base, draw.points, spec.frame == "stretched");
  draw.bindings = resolveBindings(draw.manifest, draw.scene);
  return draw;
}

std::string drawLine(const DrawSpec& spec) {
  return fmt::format("{}\t{}\t{:.17g}\t{}", spec.manifestPath, spec.frame, spec.eta,
                     spec.quick ? "quick" : "full");
}

DrawSpec parseDrawLine(const std::string& line) {
  std::stringstream in(line);
  DrawSpec spec;
  std::string eta, grid;
  if (!std::getline(in, spec.manifestPath, '\t') || !std::getline(in, spec.frame, '\t') ||
      !std::getline(in, eta, '\t') || !std::getline(in, grid))
    throw UsageError(fmt::format("not a sweep draw line: `{}`", line));
  spec.eta = std::stod(eta);
  spec.quick = grid == "quick";
  return spec;
}

}  // namespace snell::sweep

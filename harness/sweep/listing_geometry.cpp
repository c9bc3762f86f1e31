#include "sweep/listing_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/camera_math.h"

namespace snell::sweep {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// The view ray runs along -z to the vertex at (0, 0, -1); the normal turns
// from +z towards +x by the incidence angle.
ListingPoint anglePoint(double degrees, const std::string& input) {
  ListingPoint point;
  point.input = input;
  point.angleDegrees = degrees;
  const double a = degrees * kDegree;
  point.trueNormal = {std::sin(a), 0.0, std::cos(a)};
  point.normal = {static_cast<float>(point.trueNormal[0]), 0.0f,
                  static_cast<float>(point.trueNormal[2])};
  return point;
}

void addBadInputs(std::vector<ListingPoint>& points) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  auto add = [&](const std::string& label, double degrees, auto change) {
    ListingPoint point = anglePoint(degrees, label);
    change(point);
    points.push_back(point);
  };
  for (double degrees : {30.0, 60.0}) {
    // I is the vertex position (seen from the origin): its length is what a
    // listing that does not normalize I (the Cg tutorial's) sees.
    add("unnormalized-I-x3", degrees, [](ListingPoint& p) { p.position = {0, 0, -3}; });
    add("unnormalized-I-x0.25", degrees, [](ListingPoint& p) { p.position = {0, 0, -0.25f}; });
    add("unnormalized-N-x3", degrees, [](ListingPoint& p) {
      for (float& x : p.normal) x *= 3;
    });
    add("unnormalized-N-x0.5", degrees, [](ListingPoint& p) {
      for (float& x : p.normal) x *= 0.5f;
    });
  }
  add("I=-N", 0, [](ListingPoint&) {});
  add("zero-N", 30, [](ListingPoint& p) { p.normal = {0, 0, 0}; });
  add("zero-I", 30, [](ListingPoint& p) { p.position = {0, 0, 0}; });
  add("denormal-N", 30, [](ListingPoint& p) {
    for (float& x : p.normal) x *= 1e-40f;  // below FLT_MIN: may be flushed to 0
  });
  add("denormal-I", 30, [](ListingPoint& p) { p.position = {0, 0, -1e-40f}; });
  add("huge-N", 30, [](ListingPoint& p) {
    for (float& x : p.normal) x *= 1e30f;  // its square overflows fp32
  });
  add("huge-I", 30, [](ListingPoint& p) { p.position = {0, 0, -1e30f}; });
  add("nan-N", 30, [&](ListingPoint& p) { p.normal[2] = nan; });
  add("nan-I", 30, [&](ListingPoint& p) { p.position[2] = nan; });
  add("inf-N", 30, [&](ListingPoint& p) { p.normal[2] = inf; });
  add("inf-I", 30, [&](ListingPoint& p) { p.position[2] = -inf; });
}

using Vec3 = std::array<double, 3>;

Vec3 scaleBy(const std::array<float, 3>& v, const std::array<double, 3>& s, bool divide) {
  Vec3 out;
  for (int c = 0; c < 3; ++c) out[c] = divide ? v[c] / s[c] : v[c] * s[c];
  return out;
}

}  // namespace

HalfVector halfVectorAt(const std::array<double, 3>& eye, const std::array<double, 3>& light) {
  const Vec3 vertex = {0, 0, -1};
  Vec3 l, e, h;
  for (int c = 0; c < 3; ++c) {
    l[c] = light[c] - vertex[c];
    e[c] = eye[c] - vertex[c];
  }
  l = normalized(l);
  e = normalized(e);
  for (int c = 0; c < 3; ++c) h[c] = l[c] + e[c];
  return {normalized(h)};
}

namespace {

// The normal turned from +z by `degrees` towards -H's part across the view
// ray: dot(N, H) = cos(a) Hz - sin(a) |H_perp| is 0 at a = atan(Hz / |H_perp|).
void addHalfVectorPoints(std::vector<ListingPoint>& points, const HalfVector& half) {
  const Vec3& h = half.h;
  const double across = std::hypot(h[0], h[1]);
  if (across == 0) return;  // H along the view ray: N . H reaches 0 only at grazing
  const Vec3 away = {-h[0] / across, -h[1] / across, 0};
  const double zero = std::atan2(h[2], across) / kDegree;
  std::vector<double> angles = {zero};
  for (double offset : {1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1.0, 3.0, 10.0}) {
    angles.push_back(zero - offset);
    angles.push_back(zero + offset);
  }
  for (double degrees : angles) {
    if (degrees < 0 || degrees > 180) continue;
    ListingPoint p;
    p.input = "dot(N,H)->0";
    p.angleDegrees = degrees;
    const double a = degrees * kDegree;
    for (int c = 0; c < 3; ++c) {
      p.trueNormal[c] = (c == 2 ? std::cos(a) : 0.0) + std::sin(a) * away[c];
      p.normal[c] = static_cast<float>(p.trueNormal[c]);
    }
    p.dotNH = p.trueNormal[0] * h[0] + p.trueNormal[1] * h[1] + p.trueNormal[2] * h[2];
    points.push_back(p);
  }
}

}  // namespace

std::vector<ListingPoint> listingPoints(const SweepGrid& grid, const std::vector<double>& etas,
                                        bool badInputs, const HalfVector* half) {
  std::vector<ListingPoint> points;
  std::vector<double> angles = anglesFor(grid, 1.0);
  for (double eta : etas) {
    const std::vector<double> more = anglesFor(grid, eta);
    angles.insert(angles.end(), more.begin(), more.end());
  }
  std::sort(angles.begin(), angles.end());
  angles.erase(std::unique(angles.begin(), angles.end()), angles.end());
  for (double degrees : angles) points.push_back(anglePoint(degrees, "grid"));
  // The silhouette triangle: its far vertex at 90 - spacing is in the grid
  // only by chance, its middle never.
  for (double degrees : {90 - kSilhouetteSpacingDegrees, 90 - kSilhouetteSpacingDegrees / 2})
    points.push_back(anglePoint(degrees, "grid"));
  for (double degrees : {90.5, 91.0, 95.0, 100.0, 120.0, 150.0, 179.0, 180.0})
    points.push_back(anglePoint(degrees, "back-face"));
  if (half) addHalfVectorPoints(points, *half);
  if (badInputs) addBadInputs(points);
  return points;
}

Scene listingScene(const Scene& base, const std::vector<ListingPoint>& points, bool stretched) {
  Scene scene = base;
  scene.name = stretched ? "sweep-listing-stretched" : "sweep-listing";
  scene.description = stretched ? "sweep points on a model scaled by (1, 2.5, 0.4)"
                                : "sweep points, model space = eye space";
  const std::array<double, 3> s = stretched ? kStretch : std::array<double, 3>{1, 1, 1};
  AttributeStream position{"position", 4, {}}, normal{"normal", 3, {}}, tangent{"tangent", 3, {}};
  AttributeStream texcoord{"texcoord", 2, {}};
  for (const ListingPoint& p : points) {
    // Model space: positions divided by the scale (so M * p is the eye-space
    // position), normals multiplied by it and normalised (the model's own
    // unit normals, which NormalMatrix = M^-T maps back to the true
    // direction, not to unit length); tangents (in the plane of incidence,
    // perpendicular to the normal) are divided, as M maps them.
    const Vec3 modelPosition = scaleBy(p.position, s, true);
    Vec3 modelNormal = scaleBy(p.normal, s, false);
    if (stretched) modelNormal = normalized(modelNormal);
    // Perpendicular to the normal: in the xz plane for the grid, and for
    // the points turned out of it the direction of the turn.
    Vec3 t3 = cross({0, 1, 0}, {p.trueNormal[0], p.trueNormal[1], p.trueNormal[2]});
    t3 = std::hypot(t3[0], t3[1], t3[2]) > 1e-9 ? normalized(t3) : Vec3{1, 0, 0};
    const std::array<float, 3> t = {static_cast<float>(t3[0]), static_cast<float>(t3[1]),
                                    static_cast<float>(t3[2])};
    const Vec3 modelTangent = scaleBy(t, s, true);
    for (double x : modelPosition) position.data.push_back(static_cast<float>(x));
    position.data.push_back(1.0f);
    for (double x : modelNormal) normal.data.push_back(static_cast<float>(x));
    for (double x : modelTangent) tangent.data.push_back(static_cast<float>(x));
    texcoord.data.insert(texcoord.data.end(), {0.5f, 0.5f});
  }
  scene.attributes = {{"position", std::move(position)},
                      {"normal", std::move(normal)},
                      {"tangent", std::move(tangent)},
                      {"texcoord", std::move(texcoord)}};
  scene.vertexCount = points.size();
  Mat4d model = identity4();
  for (int c = 0; c < 3; ++c) model[c * 4 + c] = s[c];
  const Mat4d projection = [&] {
    Mat4d p{};
    const Value& v = base.values.at("projection");
    for (int k = 0; k < 16; ++k) p[k] = v.data[k];
    return p;
  }();
  scene.values["model"] = toMat4Value(model);
  scene.values["modelview"] = toMat4Value(model);
  scene.values["modelview_projection"] = toMat4Value(multiply(projection, model));
  scene.values["normal_matrix"] = normalMatrixValue(model);
  scene.values["texture_matrix"] = toMat4Value(identity4());
  scene.values["eye_position"] = Value{ValueType::Vec3, {0, 0, 0}};
  return scene;
}

}  // namespace snell::sweep

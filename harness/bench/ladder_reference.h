#pragma once
// Which physics reference a ladder of methods is measured against, read
// from the methods' manifests: a ladder whose methods name a glass (the
// Sellmeier terms B1..B4, C1..C4 in `constants`) or per-channel indices
// (EtaR, EtaG, EtaB) is a dispersion ladder, measured against the spectral
// reference of its glass; one whose methods give `InternalHits` is a
// refraction ladder, measured against the sphere traced through both
// interfaces and its internal reflections (bench/sphere_trace_image.h) at
// each method's `Eta`; otherwise each method's `Eta` picks a Fresnel
// reference.
#include <map>
#include <string>
#include <vector>

#include "bench/fresnel_reference_image.h"
#include "core/manifest.h"
#include "core/scene.h"
#include "oracle/physics/sellmeier.h"

namespace snell::bench {

// The glass whose Sellmeier terms a manifest's constants give, or nullptr
// when it gives none. Terms that match no glass the physics reference
// knows (N-BK7, water) throw UsageError naming the manifest.
const physics::SellmeierGlass* manifestGlass(const Manifest& manifest);

class LadderReference {
 public:
  // Computes the reference images at size x size. Throws UsageError for a
  // method the reference cannot be chosen for (no Eta; a dispersion ladder
  // naming no glass, or two).
  LadderReference(const std::vector<Manifest>& methods, const Scene& scene, int size,
                  int wavelengths);
  // What the constructor throws for these methods, without computing any
  // image.
  static void check(const std::vector<Manifest>& methods);

  const std::string& model() const { return model_; }
  const ReferenceImage& imageFor(const Manifest& method) const;
  const ReferenceImage& first() const { return images_.begin()->second; }

 private:
  bool dispersion_ = false;
  bool refraction_ = false;
  std::string model_;
  std::map<double, ReferenceImage> images_;  // by Eta; one entry (key 0) for dispersion
};

}  // namespace snell::bench

#pragma once
// The ablation table: how much each effect the physics reference could
// model changes the picture, so that the reference is shown to stop where
// the next step changes nothing the metrics can see. Each row adds one
// effect to the row before and gives the change between the two pictures
// in the bench's metrics. Geometric steps (glass of index 1.5, the Fresnel
// ladder's): the first interface only (what the methods and the Fresnel
// reference model), then the second interface (the ray refracted in
// leaves through the back), then each internal reflection. Spectral steps
// (N-BK7, the dispersion reference): the wavelength count doubled. The
// geometric steps stop at the first that changes nothing visible.
#include <filesystem>
#include <string>
#include <vector>

#include "bench/image_error.h"
#include "core/scene.h"

namespace snell::bench {

struct AblationRow {
  std::string effect;  // what this step adds to the one before
  ImageError change;   // the picture with it against the picture without
  // Whether the change is above the metrics' noise (errorNoise) in any of
  // RMS, mean or 95th percentile CIEDE2000.
  bool visible = false;
};

struct AblationTable {
  int size = 0;  // square image, pixels
  std::vector<AblationRow> geometric;
  std::vector<AblationRow> spectral;
};

// internalHits: the most surface hits from inside modelled (1 is the
// second interface); wavelengths: doublings from 4 up to it.
AblationTable ablationTable(const Scene& scene, int size, int internalHits = 24,
                            int wavelengths = 256);

std::string ablationText(const AblationTable& table);
void writeAblationJson(const AblationTable& table, const std::filesystem::path& path);

}  // namespace snell::bench

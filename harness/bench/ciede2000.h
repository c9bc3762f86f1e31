#pragma once
// CIEDE2000 colour difference (CIE 142-2001), as written out step by step
// in Sharma, Wu & Dalal, "The CIEDE2000 color-difference formula:
// implementation notes, supplementary test data, and mathematical
// observations", Color Research and Application 30(1), 21-30 (2005), with
// kL = kC = kH = 1; and the conversion from linear sRGB to CIELAB that
// feeds it.
namespace snell::bench {

struct Lab {
  double L = 0, a = 0, b = 0;
};

double ciede2000(const Lab& first, const Lab& second);

// Linear sRGB (IEC 61966-2-1 primaries, D65) to CIE 1976 L*a*b* relative to
// the D65 white of the same standard; components are clamped to [0, 1]
// first, the range a display shows.
Lab linearSrgbToLab(double r, double g, double b);

}  // namespace snell::bench

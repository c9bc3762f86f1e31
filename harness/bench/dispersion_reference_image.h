#pragma once
// The physics reference for the dispersion method ladder, on the CPU in
// double with no graphics API. Per pixel, on the analytic unit sphere, at
// each of `wavelengths` wavelengths (the centres of equal bins over 380 to
// 780 nm): the glass's index from its Sellmeier fit refracts the eye ray at
// the first interface and gives the exact unpolarised Fresnel reflectance;
// the environment in the refracted and the reflected directions is mixed
// by it. The colour seen at each wavelength is weighted by that
// wavelength's linear sRGB response (CIE 1931 functions through the IEC
// 61966-2-1 matrix, oracle/physics/cie1931.h) and the sum divided by the
// sum of the weights: the environment's RGB is taken as constant across
// each channel's response, so with no dispersion the picture is the
// environment's own colour and a grey environment stays grey.
#include "bench/fresnel_reference_image.h"
#include "core/scene.h"
#include "oracle/physics/sellmeier.h"

namespace snell::bench {

// Enough wavelengths that doubling them changes nothing the metrics see
// (the ablation table of `snell bench` shows it).
inline constexpr int kReferenceWavelengths = 128;

inline constexpr const char* kDispersionReferenceModel =
    "the glass's Sellmeier index at each wavelength (bin centres over 380-780 nm), "
    "refracted at the first interface of the analytic unit sphere with exact unpolarised "
    "Fresnel reflectance, weighted by the CIE 1931 functions (Wyman-Sloan-Shirley fit) "
    "through the IEC 61966-2-1 XYZ to linear sRGB matrix and normalised so that white stays "
    "white; environment looked up through the scene's texture matrix with bilinear base-level "
    "cube sampling";

ReferenceImage dispersionReferenceImage(const Scene& scene, const physics::SellmeierGlass& glass,
                                        int wavelengths, int width, int height);

}  // namespace snell::bench

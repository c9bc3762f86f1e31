#pragma once
// Reflectance of a smooth interface between two dielectrics, for
// unpolarised light: the exact Fresnel equations and Schlick's
// approximation, in double. Light goes from index n1 into index n2; cos_i is
// the cosine of the angle between the incident ray and the normal, in [0, 1].
// Bad input (cos_i outside [0, 1], an index that is not a finite positive
// number) throws UsageError.
namespace snell::physics {

struct FresnelReflectance {
  double s = 1.0;            // Rs, perpendicular (TE) polarisation
  double p = 1.0;            // Rp, parallel (TM) polarisation
  double unpolarised = 1.0;  // R = (Rs + Rp) / 2
  bool totalInternalReflection = false;

  double transmitted() const { return 1.0 - unpolarised; }  // T = 1 - R (no absorption)
};

// cos^2 of the refraction angle, 1 - (n1/n2)^2 (1 - cos_i^2), held to a few
// ulps even near the critical angle where it cancels to 0; negative past it.
double transmittedCosineSquared(double cosIncident, double n1, double n2);

// The Fresnel equations (Born & Wolf, section 1.5.2), with R = 1 past the
// critical angle.
FresnelReflectance fresnelExact(double cosIncident, double n1, double n2);

// ((n1 - n2) / (n1 + n2))^2, the reflectance at normal incidence.
double normalIncidenceReflectance(double n1, double n2);

// Schlick (1994): R0 + (1 - R0) (1 - cos_i)^5, always with cos_i.
double fresnelSchlick(double cosIncident, double n1, double n2);

// Schlick with the cosine taken on the less dense side, as the
// approximation asks: cos_t when light leaves the denser medium (n1 > n2),
// and R = 1 past the critical angle; cos_i otherwise.
double fresnelSchlickDenseSide(double cosIncident, double n1, double n2);

}  // namespace snell::physics

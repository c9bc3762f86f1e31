#version 140
// Written for snell (dispersion method ladder, rung 6 of 6): the spectrum
// sampled at Wavelengths wavelengths, the centres of equal bins over 380 to
// 780 nm. At each, the glass's index from its Sellmeier fit refracts the
// ray and gives the exact unpolarised Fresnel reflectance (Born & Wolf
// 1.5.2); the colour seen at that wavelength is weighted by the wavelength's
// linear sRGB response (the CIE 1931 colour matching functions, Wyman, Sloan
// & Shirley's 2013 multi-lobe fit, through the IEC 61966-2-1 XYZ to sRGB
// matrix) and the sum divided by the sum of the weights, so a grey
// environment stays grey. Per fragment.

uniform samplerCube Cubemap;
uniform mat4 TextureMatrix;

const int   Wavelengths = 32;
const float FirstNm = 380.0;
const float LastNm  = 780.0;

// N-BK7, SCHOTT data sheet: n^2 - 1 = sum Bk L^2 / (L^2 - Ck), L in
// micrometres (a fourth term, zero here, holds four-term fits such as water's).
const float B1 = 1.03961212;
const float B2 = 0.231792344;
const float B3 = 1.01046945;
const float B4 = 0.0;
const float C1 = 0.00600069867;
const float C2 = 0.0200179144;
const float C3 = 103.560653;
const float C4 = 0.0;

in vec3 EyePosition;
in vec3 EyeNormal;

out vec4 FragColor;

float sellmeierIndex(float nm)
{
    float L2 = (nm / 1000.0) * (nm / 1000.0);
    return sqrt(1.0 + B1 * L2 / (L2 - C1) + B2 * L2 / (L2 - C2)
                    + B3 * L2 / (L2 - C3) + B4 * L2 / (L2 - C4));
}

// A Gaussian with different widths below and above its peak.
float lobe(float nm, float weight, float peak, float below, float above)
{
    float t = (nm - peak) / (nm < peak ? below : above);
    return weight * exp(-0.5 * t * t);
}

vec3 linearSrgbResponse(float nm)
{
    float x = lobe(nm, 1.056, 599.8, 37.9, 31.0) + lobe(nm, 0.362, 442.0, 16.0, 26.7)
            + lobe(nm, -0.065, 501.1, 20.4, 26.2);
    float y = lobe(nm, 0.821, 568.8, 46.9, 40.5) + lobe(nm, 0.286, 530.9, 16.3, 31.1);
    float z = lobe(nm, 1.217, 437.0, 11.8, 36.0) + lobe(nm, 0.681, 459.0, 26.0, 13.8);
    const mat3 XyzToSrgb = mat3( 3.2406, -0.9689,  0.0557,
                                -1.5372,  1.8758, -0.2040,
                                -0.4986,  0.0415,  1.0570);
    return XyzToSrgb * vec3(x, y, z);
}

// R = (Rs + Rp) / 2 for light from index 1 into index 1 / eta.
float fresnel(float cosI, float eta)
{
    float cosT2 = 1.0 - eta * eta * (1.0 - cosI * cosI);
    if (cosT2 <= 0.0) return 1.0;
    float cosT = sqrt(cosT2);
    float rs = (eta * cosI - cosT) / (eta * cosI + cosT);
    float rp = (eta * cosT - cosI) / (eta * cosT + cosI);
    return 0.5 * (rs * rs + rp * rp);
}

vec3 environment(vec3 direction)
{
    return vec3(texture(Cubemap, vec3(TextureMatrix * vec4(direction, 1.0))));
}

void main()
{
    vec3 i = normalize(EyePosition);
    vec3 n = normalize(EyeNormal);
    float cosI = clamp(dot(-i, n), 0.0, 1.0);
    vec3 reflectColor = environment(reflect(i, n));

    vec3 sum = vec3(0.0);
    vec3 weights = vec3(0.0);
    for (int k = 0; k < Wavelengths; ++k) {
        float nm = FirstNm + (float(k) + 0.5) * (LastNm - FirstNm) / float(Wavelengths);
        float eta = 1.0 / sellmeierIndex(nm);
        vec3 response = linearSrgbResponse(nm);
        vec3 seen = mix(environment(refract(i, n, eta)), reflectColor, fresnel(cosI, eta));
        sum += response * seen;
        weights += response;
    }

    FragColor = vec4(sum / weights, 1.0);
}

#version 140
// Written for snell (dispersion method ladder, rung 1 of 6): one refracted
// ray per colour channel, each with its own index (EtaR, EtaG, EtaB =
// n1 / n2 from air into the glass), the Orange Book's values (Listing
// 14.4). Each channel mixes its refracted and the reflected colour by the
// exact unpolarised Fresnel reflectance at its own index (Born & Wolf
// 1.5.2), so only the dispersion differs from the reference. Per fragment.

uniform samplerCube Cubemap;
uniform mat4 TextureMatrix;

const float EtaR = 0.65;
const float EtaG = 0.67;
const float EtaB = 0.69;

in vec3 EyePosition;
in vec3 EyeNormal;

out vec4 FragColor;

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
    vec3 refractColor;
    refractColor.r = environment(refract(i, n, EtaR)).r;
    refractColor.g = environment(refract(i, n, EtaG)).g;
    refractColor.b = environment(refract(i, n, EtaB)).b;
    vec3 Ratio = vec3(fresnel(cosI, EtaR), fresnel(cosI, EtaG), fresnel(cosI, EtaB));

    FragColor = vec4(mix(refractColor, reflectColor, Ratio), 1.0);
}

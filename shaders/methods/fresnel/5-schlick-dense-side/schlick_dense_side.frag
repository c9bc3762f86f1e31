#version 140
// Written for snell (Fresnel method ladder, rung 5 of 6): Schlick's
// approximation with the cosine taken on the less dense side, as Schlick
// (1994) asks: cos(theta_t) when light comes from the denser medium
// (Eta = n1 / n2 > 1), where plain Schlick with cos(theta_i) misses total
// internal reflection; cos(theta_i) otherwise. Per fragment.

uniform samplerCube Cubemap;
uniform mat4 TextureMatrix;

const float Eta = 0.6666667; // n1 / n2: air into glass of index 1.5
const float FresnelPower = 5.0;

const float F = ((1.0-Eta) * (1.0-Eta)) / ((1.0+Eta) * (1.0+Eta));

in vec3 EyePosition;
in vec3 EyeNormal;

out vec4 FragColor;

void main()
{
    vec3 i = normalize(EyePosition);
    vec3 n = normalize(EyeNormal);

    float cosI  = clamp(dot(-i, n), 0.0, 1.0);
    float cosT2 = 1.0 - Eta * Eta * (1.0 - cosI * cosI);
    float Ratio = 1.0; // past the critical angle: total internal reflection
    if (cosT2 > 0.0) {
        float c = Eta > 1.0 ? sqrt(cosT2) : cosI;
        Ratio = F + (1.0 - F) * pow(1.0 - c, FresnelPower);
    }

    vec3 Refract = vec3(TextureMatrix * vec4(refract(i, n, Eta), 1.0));
    vec3 Reflect = vec3(TextureMatrix * vec4(reflect(i, n), 1.0));

    vec3 refractColor = vec3(texture(Cubemap, Refract));
    vec3 reflectColor = vec3(texture(Cubemap, Reflect));

    FragColor = vec4(mix(refractColor, reflectColor, Ratio), 1.0);
}

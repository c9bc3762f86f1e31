#version 140
// Written for snell (Fresnel method ladder, rung 4 of 6): Schlick's
// approximation, the reflected and refracted directions per fragment.

uniform samplerCube Cubemap;
uniform mat4 TextureMatrix;

const float Eta = 0.6666667; // 1 / 1.5: air into glass of index 1.5
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
    float Ratio = F + (1.0 - F) * pow(1.0 - cosI, FresnelPower);

    vec3 Refract = vec3(TextureMatrix * vec4(refract(i, n, Eta), 1.0));
    vec3 Reflect = vec3(TextureMatrix * vec4(reflect(i, n), 1.0));

    vec3 refractColor = vec3(texture(Cubemap, Refract));
    vec3 reflectColor = vec3(texture(Cubemap, Reflect));

    FragColor = vec4(mix(refractColor, reflectColor, Ratio), 1.0);
}

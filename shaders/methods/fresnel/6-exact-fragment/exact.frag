#version 140
// Written for snell (Fresnel method ladder, rung 6 of 6): the exact Fresnel
// equations for unpolarised light (Born & Wolf 1.5.2), R = (Rs + Rp) / 2,
// per fragment. Light goes from air (n1 = 1) into glass (n2 = 1 / Eta).

uniform samplerCube Cubemap;
uniform mat4 TextureMatrix;

const float Eta = 0.6666667; // n1 / n2: air into glass of index 1.5

in vec3 EyePosition;
in vec3 EyeNormal;

out vec4 FragColor;

void main()
{
    vec3 i = normalize(EyePosition);
    vec3 n = normalize(EyeNormal);

    float cosI  = clamp(dot(-i, n), 0.0, 1.0);
    float cosT2 = 1.0 - Eta * Eta * (1.0 - cosI * cosI);
    float Ratio = 1.0;
    if (cosT2 > 0.0) {
        float cosT = sqrt(cosT2);
        float rs = (Eta * cosI - cosT) / (Eta * cosI + cosT);
        float rp = (Eta * cosT - cosI) / (Eta * cosT + cosI);
        Ratio = 0.5 * (rs * rs + rp * rp);
    }

    vec3 Refract = vec3(TextureMatrix * vec4(refract(i, n, Eta), 1.0));
    vec3 Reflect = vec3(TextureMatrix * vec4(reflect(i, n), 1.0));

    vec3 refractColor = vec3(texture(Cubemap, Refract));
    vec3 reflectColor = vec3(texture(Cubemap, Reflect));

    FragColor = vec4(mix(refractColor, reflectColor, Ratio), 1.0);
}

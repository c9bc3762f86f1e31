#version 140
// Written for snell (Fresnel method ladder, rung 2 of 6): the empirical
// reflectance bias + scale * pow(1 + dot(I, N), power) of the Shadertoy post
// "Reflections and Refractions", with its hand-tweaked constants, per vertex.

in vec4      MCvertex;
in vec3      MCnormal;

uniform mat4 MVMatrix;
uniform mat4 MVPMatrix;
uniform mat3 NormalMatrix;
uniform mat4 TextureMatrix;

const float Eta = 0.6666667; // 1 / 1.5: air into glass of index 1.5
const float Bias = 0.0;
const float Scale = 0.25;
const float Power = 1.97;

out vec3  Reflect;
out vec3  Refract;
out float Ratio;

void main()
{
    vec4 ecPosition  = MVMatrix * MCvertex;
    vec3 ecPosition3 = ecPosition.xyz / ecPosition.w;

    vec3 i = normalize(ecPosition3);
    vec3 n = normalize(NormalMatrix * MCnormal);

    Ratio = Bias + Scale * pow(1.0 + dot(i, n), Power);

    Refract = refract(i, n, Eta);
    Refract = vec3(TextureMatrix * vec4(Refract, 1.0));

    Reflect = reflect(i, n);
    Reflect = vec3(TextureMatrix * vec4(Reflect, 1.0));

    gl_Position = MVPMatrix * MCvertex;
}

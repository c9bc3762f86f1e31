#version 140
// Written for snell (Fresnel method ladder, rung 1 of 6): the reflected and
// refracted directions per vertex, as the Orange Book computes them.

in vec4      MCvertex;
in vec3      MCnormal;

uniform mat4 MVMatrix;
uniform mat4 MVPMatrix;
uniform mat3 NormalMatrix;
uniform mat4 TextureMatrix;

const float Eta = 0.6666667; // 1 / 1.5: air into glass of index 1.5

out vec3  Reflect;
out vec3  Refract;

void main()
{
    vec4 ecPosition  = MVMatrix * MCvertex;
    vec3 ecPosition3 = ecPosition.xyz / ecPosition.w;

    vec3 i = normalize(ecPosition3);
    vec3 n = normalize(NormalMatrix * MCnormal);

    Refract = refract(i, n, Eta);
    Refract = vec3(TextureMatrix * vec4(Refract, 1.0));

    Reflect = reflect(i, n);
    Reflect = vec3(TextureMatrix * vec4(Reflect, 1.0));

    gl_Position = MVPMatrix * MCvertex;
}

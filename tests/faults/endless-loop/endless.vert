#version 140

in vec4      MCvertex;
in vec3      MCnormal;

uniform mat4 MVMatrix;
uniform mat4 MVPMatrix;
uniform mat3 NormalMatrix;
uniform mat4 TextureMatrix;

// The loop bound and step are uniforms, so no compiler can prove the loop
// ends or remove it; the manifest binds Step = 0.0, so it never ends.
// llvmpipe and lavapipe stop a loop after 65535 iterations (gallivm's loop
// limiter), so the body is made slow as well: 65535 iterations of 64
// dependent sin() per vertex is minutes of work on a CPU driver.
uniform float Limit;
uniform float Step;

const float Eta = 0.66; // Ratio of indices of refraction
const float FresnelPower = 5.0;

const float F = ((1.0-Eta) * (1.0-Eta)) / ((1.0+Eta) * (1.0+Eta));

out vec3  Reflect;
out vec3  Refract;
out float Ratio;

void main()
{
    vec4 ecPosition  = MVMatrix * MCvertex;
    vec3 ecPosition3 = ecPosition.xyz / ecPosition.w;

    vec3 i = normalize(ecPosition3);
    vec3 n = normalize(NormalMatrix * MCnormal);

    Ratio  = F + (1.0 - F) * pow((1.0 - dot(-i, n)), FresnelPower);

    Refract = refract(i, n, Eta);
    Refract = vec3(TextureMatrix * vec4(Refract, 1.0));

    Reflect = reflect(i, n);
    Reflect = vec3(TextureMatrix * vec4(Reflect, 1.0));

    float k = 0.0;
    for (float a = 0.0; a < Limit; a += Step)
    {
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
        k = sin(k + a);
    }
    Ratio += k;

    gl_Position = MVPMatrix * MCvertex;
}

#version 330 core
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;

uniform mat4 modelViewMatrix;
uniform mat4 projectionMatrix;
uniform mat3 normalMatrix;
uniform float eta;
uniform float fresnelPower;

out vec3 Reflect;
out vec3 Refract;
out float Ratio;

void main()
{
    vec4 ecPos = modelViewMatrix * vec4(aPos, 1.0);
    vec3 I = normalize(ecPos.xyz);
    vec3 N = normalize(normalMatrix * aNormal);
    float F = ((1.0 - eta) * (1.0 - eta)) / ((1.0 + eta) * (1.0 + eta));
    Ratio = F + (1.0 - F) * pow(1.0 - dot(-I, N), fresnelPower);
    Refract = refract(I, N, eta);
    Reflect = reflect(I, N);
    gl_Position = projectionMatrix * ecPos;
}

#version 450
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;

layout (set = 0, binding = 0) uniform Camera {
    mat4 model;
    mat4 view;
    mat4 projection;
    vec3 cameraPos;
    float eta;
} cam;

layout (location = 0) out vec3 Refract;

void main()
{
    vec4 world = cam.model * vec4(aPos, 1.0);
    vec3 N = normalize(mat3(cam.model) * aNormal);
    vec3 I = normalize(world.xyz - cam.cameraPos);
    Refract = refract(I, N, cam.eta);
    gl_Position = cam.projection * cam.view * world;
}

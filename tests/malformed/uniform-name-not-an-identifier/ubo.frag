#version 450
layout (location = 0) in vec3 Refract;
layout (binding = 1) uniform samplerCube skybox;
layout (location = 0) out vec4 FragColor;
void main() { FragColor = vec4(texture(skybox, Refract).rgb, 1.0); }

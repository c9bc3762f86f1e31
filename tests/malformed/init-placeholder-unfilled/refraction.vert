#version 330 core
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;
out vec3 Refracted;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform vec3 cameraPos;
uniform float ratio;
void main()
{
    vec3 Position = vec3(model * vec4(aPos, 1.0));
    vec3 Normal = mat3(transpose(inverse(model))) * aNormal;
    Refracted = refract(normalize(Position - cameraPos), normalize(Normal), ratio);
    gl_Position = projection * view * vec4(Position, 1.0);
}

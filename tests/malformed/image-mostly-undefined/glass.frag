#version 330 core
in vec3 Reflect;
in vec3 Refract;
in float Ratio;
uniform samplerCube envMap;
out vec4 FragColor;
void main()
{
    vec3 refl = texture(envMap, Reflect).rgb;
    vec3 refr = texture(envMap, Refract).rgb;
    FragColor = vec4(mix(refr, refl, Ratio), 1.0);
}

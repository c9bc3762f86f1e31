#version 140
// Written for snell (Fresnel method ladder): the environment in the
// refracted and reflected directions, mixed by the vertex stage's Ratio.

uniform samplerCube Cubemap;

in vec3  Reflect;
in vec3  Refract;
in float Ratio;

out vec4 FragColor;

void main()
{
    vec3 refractColor = vec3(texture(Cubemap, Refract));
    vec3 reflectColor = vec3(texture(Cubemap, Reflect));

    FragColor = vec4(mix(refractColor, reflectColor, Ratio), 1.0);
}

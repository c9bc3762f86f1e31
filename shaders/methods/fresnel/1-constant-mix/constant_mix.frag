#version 140
// Written for snell (Fresnel method ladder, rung 1 of 6): one reflectance
// for every angle. 0.1 is near the exact reflectance of glass (index 1.5)
// averaged over the hemisphere (0.092).

uniform samplerCube Cubemap;

const float Mix = 0.1;

in vec3 Reflect;
in vec3 Refract;

out vec4 FragColor;

void main()
{
    vec3 refractColor = vec3(texture(Cubemap, Refract));
    vec3 reflectColor = vec3(texture(Cubemap, Reflect));

    FragColor = vec4(mix(refractColor, reflectColor, Mix), 1.0);
}

Qvarying vec3 Reflect;
varying vec3 Refract;
varying float Ratio;
uniform samplerCube tex;
void main(void)
{
vec3 refractColor = vec3 (textureCube(tex,Refract));
vec3 reflectColor = vec3 (textureCube(tex,Reflect));
vec3 Color = mix(refractColor, reflectColor, Ratio);
gl_FragColor = vec4( Color,1.0);
}

varying vec3 Reflect;
varying vec3 RefractR;
varying vec3 RefractG;
varying vec3 RefractB;
varying float Ratio;
uniform samplerCube tex;
void main(void)
{
vec3 refractColor ;
refractColor.r= vec3 (textureCube(tex,RefractR)).r;
refractColor.g= vec3 (textureCube(tex,RefractG)).g;
refractColor.b= vec3 (textureCube(tex,RefractB)).b;
vec3 reflectColor = vec3 (textureCube(tex,Reflect));
vec3 Color = mix(refractColor, reflectColor, Ratio);
gl_FragColor = vec4( Color,1.0);
}

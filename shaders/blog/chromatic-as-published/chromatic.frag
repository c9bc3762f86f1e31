varying vec3 Reflect;
varying vec3 RefractR;
varying vec3 RefractG;
varying vec3 RefractB;
varying float Ratio;
uniform sampler2d tex;
void main(void)
{
vec3 refractColor ;
refractColor.r= vec3 (texture2D(tex,RefractR));
refractColor.g= vec3 (texture2D(tex,RefractG));
refractColor.b= vec3 (texture2D(tex,RefractB));
vec3 reflectColor = vec3 (texture2D(tex,Reflect));
vec3 Color = mix(refractColor, reflectColor, Ratio);
gl_FragColor = vec4( Color,1.0);
}

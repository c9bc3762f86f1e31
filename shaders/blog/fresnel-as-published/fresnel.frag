varying vec3 Reflect;
varying vec3 Refract;
varying float Ratio;
uniform sampler2d tex;
void main(void)
{
vec3 refractColor = vec3 (texture2D(tex,Refract));
vec3 reflectColor = vec3 (texture2D(tex,Reflect));
vec3 Color = mix(refractColor, reflectColor, Ratio);
gl_FragColor = vec4( Color,1.0);
}

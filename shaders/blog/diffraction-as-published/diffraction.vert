uniform vec3 eyeposition;
uniform vec3 lightposition;
vec4 HighlightColor=(1.0,1.0,1.0,1.0);
varying vec4 Color;
attribute vec3 Tangent;
vec3 lambda2rgb(float lambda)
{
const float ultraviolet =400.0;
const float infrared =700.0;
//轉(zhuǎn)換可見(jiàn)光到0~1
float a = (lambda - ultraviolet)/(infrared - ultraviolet);
const float c = 10.0; //圖的寬度
vec3 b = vec3(a) - vec3(0.75,0.5,0.25);
return max((1.0 - c*b*b), 0.0);
}
void main(void)
{
vec3 objPosition = vec3 (gl_ModelViewMatrix * gl_Vertex);
vec3 Normal = normalize (gl_NormalMatrix * gl_Normal);
vec3 LightDir = normalize (lightposition - objPosition);
vec3 EyeDir = normalize (eyeposition - objPosition);
vec3 HalfVec = normalize (LightDir + EyeDir);

vec3 T=normalize(gl_NormalMatrix * Tangent);
float u = abs(dot(T, HalfVec));

vec3 diffColor=vec3(0.0);

const int numspectralorders=3;
for(int m=1; m<=numspectralorders;++m)
{
float lambda =660 * u / float(m);
diffColor += lambda2rgb(lambda);
}

float w = dot(Normal , HalfVec);
float e = 2 * u / w;
vec3 hilight = exp(-e * e) * HighlightColor.rgb;


const float diffAtten = 0.8;
Color = vec4(diffAtten * diffColor + hilight, 1.0);

gl_Position = ftransform();


}

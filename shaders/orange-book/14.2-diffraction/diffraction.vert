#version 140

uniform mat4 MVMatrix;
uniform mat4 MVPMatrix;
uniform mat3 NormalMatrix;
uniform vec3 EyePosition;
uniform vec3 LightPosition;
vec4 HighlightColor = vec4(1.0, 1.0, 1.0, 1.0);
out vec4 Color;
in vec4 MCVertex;
in vec3 MCNormal;
in vec3 Tangent;

vec3 lambda2rgb(float lambda)
{
    const float ultraviolet = 400.0;
    const float infrared = 700.0;
    // map visible wavelengths to 0..1
    float a = (lambda - ultraviolet) / (infrared - ultraviolet);
    const float c = 10.0; // width of the bumps
    vec3 b = vec3(a) - vec3(0.75, 0.5, 0.25);
    return max((1.0 - c * b * b), 0.0);
}

void main(void)
{
    vec3 objPosition = vec3(MVMatrix * MCVertex);
    vec3 Normal = normalize(NormalMatrix * MCNormal);
    vec3 LightDir = normalize(LightPosition - objPosition);
    vec3 EyeDir = normalize(EyePosition - objPosition);
    vec3 HalfVec = normalize(LightDir + EyeDir);

    vec3 T = normalize(NormalMatrix * Tangent);
    float u = abs(dot(T, HalfVec));

    vec3 diffColor = vec3(0.0);

    const int numspectralorders = 3;
    for (int m = 1; m <= numspectralorders; ++m)
    {
        float lambda = 660.0 * u / float(m);
        diffColor += lambda2rgb(lambda);
    }

    float w = dot(Normal, HalfVec);
    float e = 2.0 * u / w;
    vec3 hilight = exp(-e * e) * HighlightColor.rgb;

    const float diffAtten = 0.8;
    Color = vec4(diffAtten * diffColor + hilight, 1.0);

    gl_Position = MVPMatrix * MCVertex;
}

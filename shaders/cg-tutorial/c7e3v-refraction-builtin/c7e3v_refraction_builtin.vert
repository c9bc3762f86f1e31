#version 140

in vec4 position;
in vec3 normal;

out vec3 T;

uniform float etaRatio;
uniform vec3 eyePositionW;
uniform mat4 modelViewProj;
uniform mat4 modelToWorld;

void main()
{
  gl_Position = modelViewProj * position;

  // Compute position and normal in world space
  vec3 positionW = (modelToWorld * position).xyz;
  vec3 N = mat3(modelToWorld) * normal;
  N = normalize(N);

  // Compute the incident and refracted vectors
  vec3 I = positionW - eyePositionW;
  T = refract(I, N, etaRatio);
}

#version 140

vec3 cgRefract(vec3 I, vec3 N, float etaRatio)
{
  float cosI = dot(-I, N);
  float cosT2 = 1.0f - etaRatio * etaRatio *
                       (1.0f - cosI * cosI);
  vec3 T = etaRatio * I +
           ((etaRatio * cosI - sqrt(abs(cosT2))) * N);
  return T * vec3(cosT2 > 0.0);
}

in vec4 position;
in vec2 texCoord;
in vec3 normal;

out vec2 oTexCoord;
out vec3 T;

uniform float etaRatio;
uniform vec3 eyePositionW;
uniform mat4 modelViewProj;
uniform mat4 modelToWorld;

void main()
{
  gl_Position = modelViewProj * position;
  oTexCoord = texCoord;

  // Compute position and normal in world space
  vec3 positionW = (modelToWorld * position).xyz;
  vec3 N = mat3(modelToWorld) * normal;
  N = normalize(N);

  // Compute the incident and refracted vectors
  vec3 I = positionW - eyePositionW;
  T = cgRefract(I, N, etaRatio);
}

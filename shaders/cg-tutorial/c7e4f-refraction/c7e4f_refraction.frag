#version 140

in vec2 oTexCoord;
in vec3 T;

out vec4 color;

uniform float transmittance;
uniform sampler2D decalMap;
uniform samplerCube environmentMap;

void main()
{
  // Fetch the decal base color
  vec4 decalColor = texture(decalMap, oTexCoord);

  // Fetch refracted environment color
  vec4 refractedColor = texture(environmentMap, T);

  // Compute the final color
  color = mix(decalColor, refractedColor, transmittance);
}

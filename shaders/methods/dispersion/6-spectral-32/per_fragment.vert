#version 140
// Written for snell (dispersion method ladder, every rung): the eye-space
// position and normal, for a fragment stage that does all the optics. The
// same stage as the Fresnel ladder's per-fragment rungs.

in vec4      MCvertex;
in vec3      MCnormal;

uniform mat4 MVMatrix;
uniform mat4 MVPMatrix;
uniform mat3 NormalMatrix;

out vec3 EyePosition;
out vec3 EyeNormal;

void main()
{
    vec4 ecPosition = MVMatrix * MCvertex;
    EyePosition = ecPosition.xyz / ecPosition.w;
    EyeNormal   = normalize(NormalMatrix * MCnormal);

    gl_Position = MVPMatrix * MCvertex;
}

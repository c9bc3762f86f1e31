#version 140
// Written for snell (refraction method ladder, rung 2 of 3): both interfaces, no
// internal reflection. The ray refracted into the unit sphere (its centre from
// MVMatrix) is followed to each hit of the surface from inside, up to
// InternalHits: there the part the exact Fresnel equations transmit leaves
// for the environment and the rest is reflected inside (all of it past the
// critical angle: total internal reflection, which a perfect sphere never
// reaches, but a listing cannot assume); what is still inside after the
// last hit is dropped.

uniform samplerCube Cubemap;
uniform mat4 TextureMatrix;
uniform mat4 MVMatrix;

const float Eta = 0.6666667; // n1 / n2: air into glass of index 1.5
const int InternalHits = 1;

in vec3 EyePosition;
in vec3 EyeNormal;

out vec4 FragColor;

// R = (Rs + Rp) / 2 for light from index n1 into n2, eta = n1 / n2.
float fresnel(float cosI, float eta)
{
    float cosT2 = 1.0 - eta * eta * (1.0 - cosI * cosI);
    if (cosT2 <= 0.0) return 1.0;
    float cosT = sqrt(cosT2);
    float rs = (eta * cosI - cosT) / (eta * cosI + cosT);
    float rp = (eta * cosT - cosI) / (eta * cosT + cosI);
    return 0.5 * (rs * rs + rp * rp);
}

vec3 environment(vec3 direction)
{
    return vec3(texture(Cubemap, vec3(TextureMatrix * vec4(direction, 1.0))));
}

void main()
{
    vec3 i = normalize(EyePosition);
    vec3 n = normalize(EyeNormal);
    vec3 centre = vec3(MVMatrix * vec4(0.0, 0.0, 0.0, 1.0));

    float cosI = clamp(dot(-i, n), 0.0, 1.0);
    float r = fresnel(cosI, Eta);
    vec3 colour = r * environment(reflect(i, n));
    float weight = 1.0 - r;

    vec3 p = EyePosition;
    vec3 d = refract(i, n, Eta);
    for (int k = 0; k < InternalHits; ++k) {
        // The next hit of p + t d with the unit sphere, from inside.
        vec3 o = p - centre;
        float b = dot(o, d);
        float t = -b + sqrt(max(b * b - dot(o, o) + 1.0, 0.0));
        p = p + t * d;
        vec3 m = normalize(p - centre);
        float inside = fresnel(clamp(dot(d, m), 0.0, 1.0), 1.0 / Eta);
        colour += weight * (1.0 - inside) * environment(refract(d, -m, 1.0 / Eta));
        weight *= inside;
        d = reflect(d, -m);
    }

    FragColor = vec4(colour, 1.0);
}

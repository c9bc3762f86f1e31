Quniform vec3 iResolution;
uniform samplerCube iChannel2;

const float max_distance = 100.0;
const vec3 sphere_center = vec3(0.0, 0.0, 2.0);

float raymarch(vec3 ray_dir)
{
    float dist = 0.0;
    for (int i = 0; i < 64; i++) {
        float d = length(ray_dir * dist - sphere_center) - 1.0;
        if (d < 0.0001) return dist;
        dist += d;
    }
    return max_distance;
}

void main(void)
{
    vec2 uv = (2.0 * gl_FragCoord.xy - iResolution.xy) / iResolution.y;
    float refract_koef = 1.02;

    vec3 up = vec3(0.0, 1.0, 0.0);
    vec3 forward = vec3(0.0, 0.0, 1.0);
    vec3 right = cross(up, forward);
    vec3 ray_dir = normalize(up * uv.y + right *uv.x + forward);

    float dist = raymarch(ray_dir);
    if (dist < max_distance) {
        vec3 point_normal = normalize(ray_dir * dist - sphere_center);
        vec3 refracted_ray = refract(ray_dir, -point_normal, refract_koef);
        vec4 refracted_color = textureCube(iChannel2, refracted_ray);
        gl_FragColor = refracted_color;
    } else {
        gl_FragColor = textureCube(iChannel2, ray_dir);
    }
}

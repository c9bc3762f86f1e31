uniform vec3 iResolution;
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

    vec3 up = vec3(0.0, 1.0, 0.0);
    vec3 forward = vec3(0.0, 0.0, 1.0);
    vec3 right = cross(up, forward);
    vec3 ray_dir = normalize(up * uv.y + right *uv.x + forward);

    float dist = raymarch(ray_dir);
    if (dist < max_distance) {
        vec3 point_normal = normalize(ray_dir * dist - sphere_center);
        vec3 etaRatioRGB = vec3(1.03, 1.06, 1.09);

        vec3 TRed = refract(ray_dir, -point_normal, etaRatioRGB.r);
        vec3 TGreen = refract(ray_dir, -point_normal, etaRatioRGB.g);
        vec3 TBlue = refract(ray_dir, -point_normal, etaRatioRGB.b);

        vec4 refracted_color;
        refracted_color.r = textureCube(iChannel2, TRed).r;
        refracted_color.g = textureCube(iChannel2, TGreen).g;
        refracted_color.b = textureCube(iChannel2, TBlue).b;
        vec3 reflected_ray = reflect(ray_dir, point_normal);
        vec4 reflected_color = textureCube(iChannel2, reflected_ray);
        float fresnelBias = 0.00;
        float fresnelScale = 0.25;
        float fresnelPower = 1.97;
        float mix_coef = fresnelBias + fresnelScale*pow(1.0 + dot(ray_dir, point_normal), fresnelPower);
        vec4 mixed = mix(reflected_color, refracted_color, mix_coef);
        gl_FragColor = mixed;
    } else {
        gl_FragColor = textureCube(iChannel2, ray_dir);
    }
}

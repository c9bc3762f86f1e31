uniform samplerCube mycube0;

varying vec3 myvert;
varying vec3 mynorm;

void main()
{
    float index_r = 1.097;  // Index of refraction for red light
    float index_g = 1.1;    // For green light
    float index_b = 1.103;  // For blue light

    vec3 viewdir = normalize(myvert);   // Viewing direction
    vec4 texcolor = vec4(0.,0.,0.,1.);  // Will hold texture color

    // Red refraction computation
    vec3 refractview_r = refract(viewdir, mynorm, 1./index_r);
    texcolor.r = textureCube(mycube0, refractview_r).r;

    // Green refraction computation
    vec3 refractview_g = refract(viewdir, mynorm, 1./index_g);
    texcolor.g = textureCube(mycube0, refractview_g).g;

    // Blue refraction computation
    vec3 refractview_b = refract(viewdir, mynorm, 1./index_b);
    texcolor.b = textureCube(mycube0, refractview_b).b;

    vec3 reflectview = reflect(viewdir, mynorm);
    gl_FragColor = mix(texcolor, textureCube(mycube0, reflectview), 0.1);
}

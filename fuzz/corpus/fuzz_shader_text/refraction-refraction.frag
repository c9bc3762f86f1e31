Quniform samplerCube mycube0;

varying vec3 myvert;
varying vec3 mynorm;

void main()
{
    float index = 1.1;                 // Index of refraction for object
    vec3 viewdir = normalize(myvert);  // Viewing direction
    vec3 refractview = refract(viewdir, mynorm, 1./index);
        // Refracted viewing direction
    vec4 texcolor = textureCube(mycube0, refractview);

    gl_FragColor = texcolor;
}

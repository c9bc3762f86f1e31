uniform mat4 modelViewMatrix;
uniform mat4 modelViewProjectionMatrix;
uniform mat3 normalMatrix;

attribute vec4 vertex;
attribute vec3 normal;

varying vec3 myvert;
varying vec3 mynorm;

void main()
{
    myvert = vec3(modelViewMatrix * vertex);
    mynorm = normalize(normalMatrix * normal);
    gl_Position = modelViewProjectionMatrix * vertex;
}

#version 140

in vec4 MCvertex;
uniform mat4 MVPMatrix;
out float Steps;

void main()
{
    Steps = 0.0;
    while (Steps < 4.0)
        Steps += 1.0;
    gl_Position = MVPMatrix * MCvertex;
}

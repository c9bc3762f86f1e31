#version 140

in vec4 Color;
out vec4 FragColor;

void main(void)
{
    FragColor = Color;
}

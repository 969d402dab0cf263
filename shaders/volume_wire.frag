#version 330 core
// volume_wire.frag - the volumes view's lines, in their light's colour (display values as they are).

flat in vec3 v_color;

out vec4 o_color;

void main()
{
    o_color = vec4(v_color, 1.0);
}

#version 330 core
// overlay.frag - the overlay's box and glyphs, blended over the picture.
in vec4 v_color;
out vec4 o_color;

void main() { o_color = v_color; }

#version 330 core
// Overlay marks: flat colour, already sRGB (no lighting, no tone mapping), with the alpha that
// blends faint lines.

in vec4 v_colour;
out vec4 frag_colour;

void main() {
  frag_colour = v_colour;
}

#version 330 core
// Overlay marks: flat colour, already sRGB (no lighting, no tone mapping).

in vec3 v_colour;
out vec4 frag_colour;

void main() {
  frag_colour = vec4(v_colour, 1.0);
}

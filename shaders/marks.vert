#version 330 core
// Overlay marks: triangles already placed in normalised device coordinates on the CPU
// (render/marks_pass.cpp), so widths are exact pixels; colour sRGB as written to the frame, and
// alpha, below 1 for the faint lines that blend over it.

layout(location = 0) in vec2 a_ndc;
layout(location = 1) in vec4 a_colour;

out vec4 v_colour;

void main() {
  v_colour = a_colour;
  gl_Position = vec4(a_ndc, 0.0, 1.0);
}

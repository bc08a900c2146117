#version 330 core
// Shadow pass: depth only; the framebuffer has no colour attachment.

void main() {}

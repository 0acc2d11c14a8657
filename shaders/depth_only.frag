#version 330 core
// Depth (and stencil) only: the light's first layer and the shadow volume write no colour.
void main() {}

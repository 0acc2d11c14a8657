#version 330 core
// One point per quad kept by volume_keep.geom (its captured indices, read as an integer vertex
// attribute); volume_gpu.geom expands it.
layout(location = 0) in int quad;
flat out int vQuad;
void main() {
  vQuad = quad;
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}

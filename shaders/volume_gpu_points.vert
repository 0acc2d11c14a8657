#version 330 core
// One point per quad of the GPU volume; volume_gpu.geom expands it (no vertex buffer).
uniform int firstQuad;  // quad index of gl_VertexID 0 in this draw call
flat out int vQuad;
void main() {
  vQuad = firstQuad + gl_VertexID;
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}

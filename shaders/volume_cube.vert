// (version_330.glsl, light_window_depth.glsl, volume_common.glsl and cube_common.glsl come first.)
// One point per cell of the GPU cube volume's geometry-shader way (GpuVolumeDraw::AllQuads);
// volume_cube.geom expands it. The inner quads come from gl_VertexID; the cells across the cube's
// edges and corners from a vertex buffer of their texel ids (seamCells = 1), a corner triangle's
// unused corner C being -1.
layout(location = 0) in ivec4 seamCell;
uniform int seamCells;  // 1: this draw's points are the seam cells of the buffer
flat out ivec4 vCell;   // texel ids of corners A, B, C, D
void main() {
  vCell = seamCells != 0 ? seamCell : cubeInnerCell(gl_VertexID);
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}

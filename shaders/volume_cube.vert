// (version_330.glsl comes first.) One point per cell of the GPU cube volume (shadowvol/cube_grid.h);
// volume_cube.geom expands it. The inner quads come from gl_VertexID, face by face and row by row
// as cube::Grid lists them; the cells across the cube's edges and corners from a vertex buffer of
// their texel ids (seamCells = 1), a corner triangle's unused corner C being -1.
layout(location = 0) in ivec4 seamCell;
uniform int seamCells;  // 1: this draw's points are the seam cells of the buffer
uniform int cubeSize;   // N texels per face side
flat out ivec4 vCell;   // texel ids f N^2 + j N + i of corners A, B, C, D
void main() {
  if (seamCells != 0) {
    vCell = seamCell;
  } else {
    int q = cubeSize - 1;
    int face = gl_VertexID / (q * q), r = gl_VertexID - face * q * q;
    int j = r / q, i = r - j * q;
    int a = (face * cubeSize + j) * cubeSize + i;
    vCell = ivec4(a, a + 1, a + cubeSize + 1, a + cubeSize);
  }
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}

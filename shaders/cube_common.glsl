// (volume_common.glsl comes first.) The GPU cube volume's texels and cells (cube_gpu_volume.h),
// shared by volume_cube.vert, volume_cube.geom, volume_cube_list.comp and
// volume_cube_indexed.vert: texel id f N^2 + j N + i of cube::Grid (shadowvol/cube_grid.h), the
// direction of its texel centre's ray (cubeTexelDirection of cube_map.h: D + x R + y U, x and y
// the centre's NDC, the faces' D, R, U set from the C++ table), its sheet depth
// (sheetDepthOfTexel: the cube has no border ring), and the inner quads' corners.
uniform sampler2DArray cubeDepth;  // layer f: face f's light-view depth (R32F; blurred with blur)
uniform int cubeSize;              // N texels per face side
uniform vec3 faceDirection[6];     // D of cube_map.h's table, face by face
uniform vec3 faceRight[6];         // R = D x U
uniform vec3 faceUp[6];            // U

ivec3 cubeTexel(int id) {
  int nn = cubeSize * cubeSize;
  int face = id / nn, r = id - face * nn;
  int j = r / cubeSize;
  return ivec3(r - j * cubeSize, j, face);
}

vec3 cubeDirection(ivec3 t) {
  vec2 ndc = (vec2(t.xy) + 0.5) / float(cubeSize) * 2.0 - 1.0;
  return faceDirection[t.z] + ndc.x * faceRight[t.z] + ndc.y * faceUp[t.z];
}

float cubeSheetDepth(ivec3 t) { return sheetDepthOfTexel(texelFetch(cubeDepth, t, 0).r); }

// The corners A, B, C, D of face f's inner quad (i, j).
ivec4 cubeQuadAt(int face, int i, int j) {
  int a = (face * cubeSize + j) * cubeSize + i;
  return ivec4(a, a + 1, a + cubeSize + 1, a + cubeSize);
}

// The inner quads come first in cube::Grid, face by face and row by row.
int cubeInnerCells() { return 6 * (cubeSize - 1) * (cubeSize - 1); }
ivec4 cubeInnerCell(int c) {
  int q = cubeSize - 1;
  int face = c / (q * q), r = c - face * q * q;
  int j = r / q;
  return cubeQuadAt(face, r - j * q, j);
}

// (version_430.glsl and volume_common.glsl come first.) The GPU volume with the exact cap built as
// a triangle list in a buffer, for GL 4.3+: one invocation per quad; a quad that is not all on the
// far plane appends its 4 triangles (12 light-view vertices) at an atomically taken offset: the
// two sheet triangles and their reversed copies on the far plane, exactly those volume_gpu.geom
// emits (fixed B-D: ABD, BCD, ADB, BDC; flipped A-C: ABC, ACD, ACB, ADC). A plain vertex shader
// then draws the list (volume_mesh.vert). The triangles' order varies from frame to frame; the
// z-fail stencil (increments and decrements that wrap) does not depend on it. Past `capacity`
// vertices nothing is written but the count still grows, so the renderer can grow the buffer and
// run the pass again.
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Count { uint vertexCount; };
layout(std430, binding = 1) writeonly buffer Vertices { float xyz[]; };
uniform int capacity;  // vertices the buffer holds

void put(uint v, vec3 p) {
  xyz[3u * v] = p.x;
  xyz[3u * v + 1u] = p.y;
  xyz[3u * v + 2u] = p.z;
}

void main() {
  int quads = (size.x - 1) * (size.y - 1);
  // Groups of 64 quads in rows of at most 65535 groups (renderer_gpu_volume.cpp's dispatch).
  int q = int((gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u + gl_LocalInvocationID.x);
  if (q >= quads) return;
  ivec2 t0 = quadCorner(q);
  if (quadAllFar(t0)) return;
  vec3 p[4], f[4];
  for (int k = 0; k < 4; ++k) {
    float d = sheetDepth(t0 + kCornerOffset[k]);
    p[k] = lightViewPoint(t0 + kCornerOffset[k], d);
    // A far sheet vertex and its cap copy must be bit-identical: reuse the sheet point.
    f[k] = d < farPlane ? lightViewPoint(t0 + kCornerOffset[k], farPlane) : p[k];
  }
  uint n = drawCap != 0 ? 12u : 6u;  // drawCap = 0 (z-pass): the sheet triangles alone
  uint v = atomicAdd(vertexCount, n);
  if (v + n > uint(capacity)) return;
  if (perfect == 0 || !flipDiagonal(p[0], p[1], p[2], p[3])) {
    put(v, p[0]); put(v + 1u, p[1]); put(v + 2u, p[3]);
    put(v + 3u, p[1]); put(v + 4u, p[2]); put(v + 5u, p[3]);
    if (drawCap == 0) return;
    put(v + 6u, f[0]); put(v + 7u, f[3]); put(v + 8u, f[1]);
    put(v + 9u, f[1]); put(v + 10u, f[3]); put(v + 11u, f[2]);
  } else {
    put(v, p[0]); put(v + 1u, p[1]); put(v + 2u, p[2]);
    put(v + 3u, p[0]); put(v + 4u, p[2]); put(v + 5u, p[3]);
    if (drawCap == 0) return;
    put(v + 6u, f[0]); put(v + 7u, f[2]); put(v + 8u, f[1]);
    put(v + 9u, f[0]); put(v + 10u, f[3]); put(v + 11u, f[2]);
  }
}

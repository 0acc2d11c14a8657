// (volume_common.glsl comes first.) Compaction pass of the GPU volume (exact cap only): point p
// stands for the kQuadsPerKeepPoint quads from p * kQuadsPerKeepPoint on (fewer for the last),
// and emits, in quad order, the index of each of them that volume_gpu.geom would expand, i.e.
// unless all four corners lie on the far plane. Transform feedback captures keptQuad with the
// rasteriser discarded; the volume pass then draws one point per kept quad (volume_gpu_kept.vert).
// Several quads per invocation because a geometry-shader invocation costs far more than its four
// texel fetches on a CPU rasteriser (llvmpipe); keep kQuadsPerKeepPoint in step with renderer_gpu_volume.cpp.
const int kQuadsPerKeepPoint = 32;
layout(points) in;
layout(points, max_vertices = 32) out;
flat in int vQuad[];  // the point's index (volume_gpu_points.vert with firstQuad = 0)
flat out int keptQuad;

void main() {
  int quads = (size.x - 1) * (size.y - 1);
  int first = vQuad[0] * kQuadsPerKeepPoint;
  for (int q = first; q < min(first + kQuadsPerKeepPoint, quads); ++q) {
    if (quadAllFar(quadCorner(q))) continue;
    keptQuad = q;
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    EmitVertex();
    EndPrimitive();
  }
}

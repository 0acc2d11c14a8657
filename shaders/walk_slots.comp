// (version_430.glsl, light_window_depth.glsl, volume_common.glsl and refine_common.glsl come
// first.) The refined GPU volume's work lists, after the unfolding (refined_gpu_volume.h):
//   phase 0, one invocation per texel t = (i, j): appends to `walkSlots` the slot 3 t + k of its
//     boundary edges (k = axis) and, for a quad with 3 or 4 boundary sides, of its centre (k = 2),
//     and to `refinedQuads` the index j (W - 1) + i of a quad with a boundary side;
//   phase 1, one invocation: the indirect dispatch sizes of the walk (64 slots per group) and of
//     the refined cells (64 quads per group), in rows of at most 65535 groups.
// Counters (binding 6): [4..6] the walk's dispatch, [7..9] the cells', [10] slots, [11] quads
// (both counts cleared before phase 0).
layout(local_size_x = 16, local_size_y = 16) in;
layout(std430, binding = 5) readonly buffer Flags { uint flags[]; };
layout(std430, binding = 6) buffer Counters { uint counters[]; };
layout(std430, binding = 7) writeonly buffer WalkSlots { uint walkSlots[]; };
layout(std430, binding = 4) writeonly buffer RefinedQuads { uint refinedQuads[]; };
uniform int phase;

void setDispatch(uint at, uint items) {
  uint groups = (items + 63u) / 64u, row = min(groups, 65535u);
  counters[at] = row;
  counters[at + 1u] = row == 0u ? 0u : (groups + row - 1u) / row;
  counters[at + 2u] = 1u;
}

void main() {
  if (phase == 1) {
    setDispatch(4u, counters[10]);
    setDispatch(7u, counters[11]);
    return;
  }
  ivec2 P = ivec2(gl_GlobalInvocationID.xy);
  if (!inGrid(P)) return;
  uint f = flags[texelIndex(P)];
  for (int k = 0; k < 2; ++k)
    if (((f >> uint(k)) & kBoundaryBit) != 0u) walkSlots[atomicAdd(counters[10], 1u)] = 3u * texelIndex(P) + uint(k);
  if (P.x + 1 >= size.x || P.y + 1 >= size.y) return;
  int sides = 0;
  for (int m = 0; m < 4; ++m)
    if (((flags[texelIndex(sideTexel(P, m))] >> uint(sideAxis(m))) & kBoundaryBit) != 0u) ++sides;
  if (sides == 0) return;
  refinedQuads[atomicAdd(counters[11], 1u)] = uint(P.y * (size.x - 1) + P.x);
  if (sides >= 3) walkSlots[atomicAdd(counters[10], 1u)] = 3u * texelIndex(P) + 2u;
}

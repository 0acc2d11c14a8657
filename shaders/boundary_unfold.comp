// (version_430.glsl, light_window_depth.glsl, volume_common.glsl and refine_common.glsl come
// first.) One round of boundary_edges.h's unfolding (keepWallsUnfolded), in two dispatches:
//   phase 0, one invocation per quad: a quad with exactly two boundary sides, both surface edges,
//     whose near components disagree (the near side at one crossing is the far side at the other)
//     marks both edges dying (atomicOr), reading only the flags the round started with;
//   phase 1, one invocation per texel: dying edges lose their boundary bits; if any did, the
//     next round's indirect dispatch gets its work groups (nextRound: its x count, else 0).
// Rounds beyond kMaxUnfoldRounds are not run, as on the CPU.
layout(local_size_x = 8, local_size_y = 8) in;
layout(std430, binding = 5) coherent buffer Flags { uint flags[]; };
layout(std430, binding = 7) buffer Rounds { uint rounds[]; };  // per round: x, y, z work groups
uniform int phase;
uniform int nextRound;   // the round whose x count phase 1 sets; < 0: none (the last round)
uniform int groupsX;     // the x count of a full dispatch

// Side k of quad q0: its flags, shifted to axis 0.
uint side(ivec2 q0, int k) { return flags[texelIndex(sideTexel(q0, k))] >> uint(sideAxis(k)); }

void foldCheck(ivec2 q0) {
  int split[2];
  int n = 0;
  for (int k = 0; k < 4; ++k)
    if ((side(q0, k) & kBoundaryBit) != 0u) {
      if (n < 2) split[n] = k;
      ++n;
    }
  if (n != 2) return;
  uint s0 = side(q0, split[0]), s1 = side(q0, split[1]);
  if ((s0 & kSurfaceBit) == 0u || (s1 & kSurfaceBit) == 0u) return;
  bool near0 = ((s0 & kNearAtPBit) != 0u) == (split[0] < 2);  // near at the side's start
  bool near1 = ((s1 & kNearAtPBit) != 0u) == (split[1] < 2);
  if (near0 != near1) return;  // one component near at both
  for (int m = 0; m < 2; ++m) {
    int k = split[m];
    atomicOr(flags[texelIndex(sideTexel(q0, k))], kDyingBit << uint(sideAxis(k)));
  }
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (phase == 0) {
    if (p.x + 1 < size.x && p.y + 1 < size.y) foldCheck(p);
    return;
  }
  if (!inGrid(p)) return;
  uint f = flags[texelIndex(p)];
  uint dying = (f >> 6) & 3u;
  if (dying == 0u) return;
  flags[texelIndex(p)] = f & ~(dying | (dying << 2) | (dying << 4) | (dying << 6));
  if (nextRound >= 0) rounds[3 * nextRound] = uint(groupsX);
}

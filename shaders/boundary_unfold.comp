// (version_430.glsl, light_window_depth.glsl, volume_common.glsl and refine_common.glsl come
// first.) boundary_edges.h's unfolding (keepWallsUnfolded) in rounds, without a read-back:
//   phase 0, round r, one invocation per quad: a quad with exactly two boundary sides, both
//     surface edges, whose near components disagree (the near side at one crossing is the far side
//     at the other) marks both edges made continuous in round r (bit 6 + 2 r + axis, atomicOr),
//     reading only the edges left by the rounds before (so every quad of a round sees the same
//     state, in any order); if it marks one, round r + 1 gets its work groups;
//   phase 1, one invocation per texel: the marked edges lose their boundary, near-end and surface
//     bits, and the round bits are cleared.
// Every dispatch is indirect from `rounds` (x, y, z work groups per entry: rounds 0 ..
// kMaxUnfoldRounds - 1, then phase 1); boundary_edges.comp gives round 0 and phase 1 their work
// groups only when it found a surface edge, a round gives the next one its own only when it marked
// an edge, so a map without folds runs no work group at all.
layout(local_size_x = 16, local_size_y = 16) in;
layout(std430, binding = 5) coherent buffer Flags { uint flags[]; };
layout(std430, binding = 7) buffer Rounds { uint rounds[]; };
uniform int phase;
uniform int round;      // phase 0: r
uniform int roundCount; // kMaxUnfoldRounds
uniform int groupsX;    // the x count of a full dispatch

// The edges left before round r of texel t's flags: the boundary, near-end and surface bits of
// those not made continuous in an earlier round.
uint edgesBefore(uint f, int r) {
  uint dead = 0u;
  for (int k = 0; k < r; ++k) dead |= (f >> uint(6 + 2 * k)) & 3u;
  return f & ~(dead | (dead << 2) | (dead << 4)) & 63u;
}

// Side k of quad q0 as the round finds it: its flags, shifted to axis 0.
uint side(ivec2 q0, int k) {
  return edgesBefore(flags[texelIndex(sideTexel(q0, k))], round) >> uint(sideAxis(k));
}

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
    atomicOr(flags[texelIndex(sideTexel(q0, k))], 1u << uint(6 + 2 * round + sideAxis(k)));
  }
  if (round + 1 < roundCount) rounds[3 * (round + 1)] = uint(groupsX);
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (phase == 0) {
    if (p.x + 1 < size.x && p.y + 1 < size.y) foldCheck(p);
    return;
  }
  if (inGrid(p)) flags[texelIndex(p)] = edgesBefore(flags[texelIndex(p)], roundCount);
}

// (version_430.glsl, light_window_depth.glsl, volume_common.glsl and refine_common.glsl come
// first.) The refined GPU volume's boundary edges (boundary_edges.h's findBoundaryEdges, rule for
// rule): one invocation per texel P, for its edges along +i and +j, writes P's boundary flags
// (refine_common.glsl). Far edge: exactly one end's sheet depth is the far plane. Surface edge:
// both ends hit and, with u the depth without the blur's averaging, J = |u(Q) - u(P)| >
// max(kJumpFootprints F(min(u(P), u(Q))), kJumpSlope min(gP, gQ)) over the steps beyond the ends
// that exist (0 when none does). boundary_unfold.comp then removes the folds.
layout(local_size_x = 8, local_size_y = 8) in;
layout(std430, binding = 5) writeonly buffer Flags { uint flags[]; };
uniform vec2 footprint;         // TexelFootprint a, b: F(d) = a + b d
uniform float jumpFootprints;   // kJumpFootprints
uniform float jumpSlope;        // kJumpSlope

bool farAt(ivec2 t) { return !inGrid(t) || sheetDepth(t) == farPlane; }

// The step beyond an end: |u(end) - u(t)|, or -1 when t is far or off the grid.
float stepBeyond(float uEnd, ivec2 t) {
  if (farAt(t)) return -1.0;
  float u = unblurredDepth(t);
  return u == farPlane ? -1.0 : abs(uEnd - u);
}

// The flags of the edge P -> Q = P + d (0 when it is not a boundary edge), shifted to axis 0.
uint edgeFlags(ivec2 P, ivec2 d) {
  ivec2 Q = P + d;
  bool farP = farAt(P), farQ = farAt(Q);
  if (farP && farQ) return 0u;
  if (farP != farQ) return kBoundaryBit | (farP ? 0u : kNearAtPBit);
  float uP = unblurredDepth(P), uQ = unblurredDepth(Q);
  if (uP == farPlane || uQ == farPlane) return 0u;
  float jump = abs(uQ - uP);
  float gP = stepBeyond(uP, P - d), gQ = stepBeyond(uQ, Q + d);
  float slope = gP >= 0.0 && gQ >= 0.0 ? min(gP, gQ) : (gP >= 0.0 ? gP : (gQ >= 0.0 ? gQ : 0.0));
  if (!(jump > max(jumpFootprints * (footprint.x + footprint.y * min(uP, uQ)), jumpSlope * slope))) return 0u;
  return kBoundaryBit | kSurfaceBit | (uP < uQ ? kNearAtPBit : 0u);
}

void main() {
  ivec2 P = ivec2(gl_GlobalInvocationID.xy);
  if (!inGrid(P)) return;
  uint f = 0u;
  if (P.x + 1 < size.x) f |= edgeFlags(P, ivec2(1, 0));
  if (P.y + 1 < size.y) f |= edgeFlags(P, ivec2(0, 1)) << 1;
  flags[texelIndex(P)] = f;
}

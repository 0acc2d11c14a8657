// (version_430.glsl, light_window_depth.glsl, volume_common.glsl and refine_common.glsl come
// first.) The refined GPU volume's boundary edges (boundary_edges.h's findBoundaryEdges, rule for
// rule): one invocation per texel P, for its edges along +i and +j, writes P's boundary flags
// (refine_common.glsl), and where it finds a surface edge switches boundary_unfold.comp on. Far edge: exactly one end's sheet depth is the far plane. Surface edge:
// both ends hit and, with u the depth without the blur's averaging, J = |u(Q) - u(P)| >
// max(kJumpFootprints F(min(u(P), u(Q))), kJumpSlope min(gP, gQ)) over the steps beyond the ends
// that exist (0 when none does). boundary_unfold.comp then removes the folds.
layout(local_size_x = 16, local_size_y = 16) in;
layout(std430, binding = 5) writeonly buffer Flags { uint flags[]; };
layout(std430, binding = 7) buffer Rounds { uint rounds[]; };  // boundary_unfold.comp's dispatches
uniform int unfoldRounds;       // kMaxUnfoldRounds
uniform int groupsX;            // the x count of a full unfold dispatch
uniform vec2 footprint;         // TexelFootprint a, b: F(d) = a + b d
uniform float jumpFootprints;   // kJumpFootprints
uniform float jumpSlope;        // kJumpSlope

// The work group's texels and their neighbours (one before, two after, along both axes: the
// steps beyond an edge's ends), read once into shared memory: sheet depths, and the depths
// without the blur's averaging; texels off the grid hold the far plane (farAt's rule).
const int kTile = 16 + 3;
shared float tileSheet[kTile * kTile];
shared float tileRaw[kTile * kTile];

int tileIndex(ivec2 t) {
  ivec2 l = t - (ivec2(gl_WorkGroupID.xy) * 16 - 1);
  return l.y * kTile + l.x;
}
float sheetAt(ivec2 t) { return tileSheet[tileIndex(t)]; }
float rawAt(ivec2 t) { return tileRaw[tileIndex(t)]; }

void loadTile() {
  ivec2 origin = ivec2(gl_WorkGroupID.xy) * 16 - 1;
  for (uint k = gl_LocalInvocationIndex; k < uint(kTile * kTile); k += 256u) {
    ivec2 t = origin + ivec2(int(k) % kTile, int(k) / kTile);
    float sd = inGrid(t) ? sheetDepth(t) : farPlane;
    tileSheet[k] = sd;
    tileRaw[k] = inGrid(t) && blurOn != 0 ? unblurredDepth(t) : sd;
  }
  barrier();
}

bool farAt(ivec2 t) { return sheetAt(t) == farPlane; }

// The step beyond an end: |u(end) - u(t)|, or -1 when t is far or off the grid.
float stepBeyond(float uEnd, ivec2 t) {
  if (farAt(t)) return -1.0;
  float u = rawAt(t);
  return u == farPlane ? -1.0 : abs(uEnd - u);
}

// The flags of the edge P -> Q = P + d (0 when it is not a boundary edge), shifted to axis 0, from
// P's sheet depth sP and depth without the blur's averaging uP.
uint edgeFlags(ivec2 P, ivec2 d, float sP, float uP) {
  ivec2 Q = P + d;
  float sQ = sheetAt(Q);
  bool farP = sP == farPlane, farQ = sQ == farPlane;
  if (farP && farQ) return 0u;
  if (farP != farQ) return kBoundaryBit | (farP ? 0u : kNearAtPBit);
  float uQ = rawAt(Q);
  if (uP == farPlane || uQ == farPlane) return 0u;
  float jump = abs(uQ - uP), least = jumpFootprints * (footprint.x + footprint.y * min(uP, uQ));
  if (!(jump > least)) return 0u;  // the rule's quick reject, before the steps beyond the ends
  float gP = stepBeyond(uP, P - d), gQ = stepBeyond(uQ, Q + d);
  float slope = gP >= 0.0 && gQ >= 0.0 ? min(gP, gQ) : (gP >= 0.0 ? gP : (gQ >= 0.0 ? gQ : 0.0));
  if (!(jump > max(least, jumpSlope * slope))) return 0u;
  return kBoundaryBit | kSurfaceBit | (uP < uQ ? kNearAtPBit : 0u);
}

void main() {
  loadTile();  // every invocation of the group, before any returns
  ivec2 P = ivec2(gl_GlobalInvocationID.xy);
  if (!inGrid(P)) return;
  float sP = sheetAt(P), uP = rawAt(P);
  uint f = 0u;
  if (P.x + 1 < size.x) f |= edgeFlags(P, ivec2(1, 0), sP, uP);
  if (P.y + 1 < size.y) f |= edgeFlags(P, ivec2(0, 1), sP, uP) << 1;
  flags[texelIndex(P)] = f;
  if ((f & (kSurfaceBit | (kSurfaceBit << 1))) != 0u) {  // a surface edge: the unfolding has work
    rounds[0] = uint(groupsX);
    rounds[3 * unfoldRounds] = uint(groupsX);
  }
}

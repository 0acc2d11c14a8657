// (volume_common.glsl comes first.) Shared by the refined GPU volume's passes (boundary_edges.comp,
// boundary_unfold.comp, walk_slots.comp, silhouette_walk.comp's grid queries, silhouette_rays.comp,
// volume_refined.comp
// and volume_refined.vert): the sheet-depth rule for one sample of the surface (sheet_depth.h's
// SheetDepthRule::ofSample), the boundary flags of a texel and the sides of a quad.
//
// Boundary flags, one word per texel t = j W + i (boundary_edges.h; P = t, Q = P + (1, 0) for
// axis 0, P + (0, 1) for axis 1):
//   bit axis      the edge from t along axis is a boundary edge
//   bit 2 + axis  its near end is P (nearAtP)
//   bit 4 + axis  it is a surface edge (both ends hit)
//   bit 6 + 2 r + axis  boundary_unfold.comp: made continuous in round r (cleared by its last phase)
// Quad (i, j)'s sides (cell_triangulator.h's sideEdge): 0 = the axis-0 edge of (i, j), 1 = the
// axis-1 edge of (i + 1, j), 2 = the axis-0 edge of (i, j + 1), 3 = the axis-1 edge of (i, j);
// sides 0 and 1 run from their edge's P end, 2 and 3 towards it.
// A crossing's record: layer `axis` of crossingRecords at texel t; a quad's centre depth: layer 2
// at its corner A. Work slots (walk_slots.comp): 3 t + k, k = axis or 2 for the centre.
uniform sampler2D rawDepth;  // with blur: the unblurred light-view depth (lightDepth holds the blurred)
uniform int blurOn;          // 1: lightDepth is blurred (the blur offset included)
uniform float blurOffset;    // world units, VolumeBuildOptions::blurOffset

const uint kBoundaryBit = 1u, kNearAtPBit = 4u, kSurfaceBit = 16u;

// SheetDepthRule::ofSample of a light-view depth d (a texel's stored depth or a walk's): the far
// plane when invalid (d >= farSnap, or not a finite depth >= 0), else clamp(d (+ the blur
// offset with blur) + bias, near, far), the far plane when that is >= farSnap.
float ofSample(float d) {
  if (!(d >= 0.0 && d < farSnap)) return farPlane;
  float c = clamp(d + (blurOn != 0 ? blurOffset : 0.0) + bias, nearPlane, farPlane);
  return c < farSnap ? c : farPlane;
}

// u of boundary_edges.h: the sheet depth of texel t without the blur's averaging (the ring on the
// far plane). Without blur the sheet depth itself.
float unblurredDepth(ivec2 t) {
  if (blurOn == 0) return sheetDepth(t);
  if (onRing(t)) return farPlane;
  return ofSample(texelFetch(rawDepth, t, 0).r);
}

bool inGrid(ivec2 t) { return all(greaterThanEqual(t, ivec2(0))) && all(lessThan(t, size)); }
uint texelIndex(ivec2 t) { return uint(t.y * size.x + t.x); }

// Side k of quad q0 (its corner A): the texel P of its edge and the edge's axis.
ivec2 sideTexel(ivec2 q0, int k) { return q0 + (k == 1 ? ivec2(1, 0) : (k == 2 ? ivec2(0, 1) : ivec2(0))); }
int sideAxis(int k) { return (k == 1 || k == 3) ? 1 : 0; }

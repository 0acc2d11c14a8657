// (version_430.glsl, light_window_depth.glsl, volume_common.glsl and refine_common.glsl come
// first.) The refined GPU volume's cells (--volume gpu --refine K): one invocation per quad of
// walk_slots.comp's list of refined quads (those with a boundary side; volume_index.frag lists the
// others into the same buffer) appends its triangles as vertex indices (volume_refined.vert places
// them, for both) at an atomically taken offset: exactly the triangles of the CPU builder with the
// mirrored cap (volume_builder.h with flattenCap = false) from the same boundary edges and
// crossings. That is cell_triangulator.h's CellTriangulator without chord points, rule for rule:
// its loop of corners with each boundary side's wall edge (the crossing's near and far vertex)
// between the side's corners, components closed by chords, the taper (one side), the wall (two),
// the middle polygon by the centre's depth (three or four); triangles with three far vertices
// dropped; every kept triangle that is not a wall mirrored on the far plane, reversed, unless
// drawCap = 0 (z-pass).
// Vertex indices (W H = texels): t = j W + i the sheet vertex of texel (i, j); W H + t its point on
// the far plane (a far texel is its own); 2 W H + 3 (2 t + axis) + k for the crossing of the edge
// from texel t along axis: k = 0 its near vertex, 1 its far vertex, 2 its point on the far plane
// (a far edge's far vertex is its own).
// Past `capacity` indices nothing is written but the count still grows (the renderer grows the
// buffer and lists again).
layout(local_size_x = 64) in;
layout(std430, binding = 5) readonly buffer Flags { uint flags[]; };
layout(std430, binding = 0) buffer Count { uint indexCount; uint quadCount; };  // shared with volume_index.frag
layout(std430, binding = 1) writeonly buffer Indices { uint indices[]; };
layout(std430, binding = 6) readonly buffer Counters { uint counters[]; };  // [11] refined quads (walk_slots.comp)
layout(std430, binding = 4) readonly buffer RefinedQuads { uint refinedQuads[]; };
uniform sampler2DArray crossingRecords;  // silhouette_rays.comp's or silhouette_walk.comp's records
uniform int capacity;

struct CellVertex {
  uint id;
  bool far;      // on the far plane
  vec3 lv;       // light-view point (the diagonal rule)
  float depth;   // light-view depth
  uint cap;      // its point on the far plane (the mirrored cap)
};
// The quad's loop: corners A B C D = 0..3, side k's crossing vertices on corner k's side (a[k]) at
// 4 + k and on corner k + 1's side (b[k]) at 8 + k.
CellVertex cell[12];
const int kMaxCellTriangles = 16;
ivec3 tri[kMaxCellTriangles];
bool footprint[kMaxCellTriangles];  // not a wall
int triCount;

int A(int k) { return 4 + k; }
int B(int k) { return 8 + k; }
void add(int p, int q, int r, bool notWall) {
  tri[triCount] = ivec3(p, q, r);
  footprint[triCount] = notWall;
  ++triCount;
}
// A vertical quad p q r s (wall edges p-q and r-s on light rays): diagonal p-r.
void wall(int p, int q, int r, int s) {
  add(p, q, r, false);
  add(p, r, s, false);
}
// A component polygon [crossing, 1..3 corners, crossing], counter-clockwise, convex.
void component(int poly[5], int count) {
  if (count == 3) {
    add(poly[0], poly[1], poly[2], true);
  } else if (count == 4) {  // a quad A B C D of triangulation.h
    if (perfect != 0 && flipDiagonal(cell[poly[0]].lv, cell[poly[1]].lv, cell[poly[2]].lv, cell[poly[3]].lv)) {
      add(poly[0], poly[1], poly[2], true);
      add(poly[0], poly[2], poly[3], true);
    } else {
      add(poly[0], poly[1], poly[3], true);
      add(poly[1], poly[2], poly[3], true);
    }
  } else {  // 5: a fan from the middle corner
    add(poly[2], poly[3], poly[4], true);
    add(poly[2], poly[4], poly[0], true);
    add(poly[2], poly[0], poly[1], true);
  }
}
// One boundary side k (a surface edge whose jump fades inside the quad): the wall tapers from the
// crossing to the corner diagonally opposite corner k + 1.
void taper(int k) {
  int c1 = (k + 1) % 4, c2 = (k + 2) % 4, c3 = (k + 3) % 4, c4 = k;
  add(B(k), c1, c2, true);
  add(B(k), c2, c3, true);
  add(B(k), c3, A(k), false);
  add(A(k), c3, c4, true);
}
// The middle polygon's vertex of one crossing (its vertices p, q on its two sides).
int pick(int p, int q, float centre) {
  int nearV = cell[p].depth < cell[q].depth ? p : q;
  int farV = cell[p].depth < cell[q].depth ? q : p;
  if (cell[farV].far) return centre != farPlane ? nearV : farV;  // a far edge: does the centre ray hit?
  return abs(cell[farV].depth - centre) < abs(cell[nearV].depth - centre) ? farV : nearV;
}

void triangulate(int split[4], int n, float centre) {
  triCount = 0;
  if (n == 1) {
    taper(split[0]);
    return;
  }
  for (int m = 0; m < n; ++m) {  // the components: corners s + 1 .. s2 between sides s and s2
    int s = split[m], s2 = split[(m + 1) % n];
    int poly[5];
    int count = 0;
    poly[count++] = B(s);
    for (int c = (s + 1) % 4, guard = 0; guard < 4; c = (c + 1) % 4, ++guard) {
      poly[count++] = c;
      if (c == s2) break;
    }
    poly[count++] = A(s2);
    component(poly, count);
  }
  if (n == 2) {
    wall(A(split[0]), B(split[0]), A(split[1]), B(split[1]));
    return;
  }
  // The middle polygon: one vertex per crossing by the centre's depth; where that would fold a
  // wall piece onto itself, the vertex on each crossing's second side.
  int mid[4];
  for (int m = 0; m < n; ++m) mid[m] = pick(A(split[m]), B(split[m]), centre);
  for (int m = 0; m < n; ++m) {
    int s = split[m], s2 = split[(m + 1) % n];
    bool quadPiece = mid[m] == A(s) && mid[(m + 1) % n] == B(s2);
    if (quadPiece && (cell[B(s)].depth - cell[A(s)].depth) * (cell[A(s2)].depth - cell[B(s2)].depth) < 0.0) {
      for (int k = 0; k < n; ++k) mid[k] = B(split[k]);
      break;
    }
  }
  for (int m = 1; m + 1 < n; ++m) add(mid[0], mid[m], mid[m + 1], true);
  for (int m = 0; m < n; ++m) {  // a wall piece under each side of the middle polygon
    int s = split[m], s2 = split[(m + 1) % n];
    int path[4];
    int count = 0;
    if (mid[m] == A(s)) path[count++] = A(s);
    path[count++] = B(s);
    path[count++] = A(s2);
    if (mid[(m + 1) % n] == B(s2)) path[count++] = B(s2);
    if (count == 3) add(path[0], path[1], path[2], false);
    if (count == 4) wall(path[0], path[1], path[2], path[3]);
  }
}

uint texelCount() { return uint(size.x * size.y); }
uint crossingId(ivec2 P, int axis, uint k) { return 2u * texelCount() + 3u * (2u * texelIndex(P) + uint(axis)) + k; }

// The loop of quad q0: its corners and, for each boundary side, the crossing's two vertices.
void assemble(ivec2 q0, uint sides[4]) {
  for (int k = 0; k < 4; ++k) {
    ivec2 c = q0 + kCornerOffset[k];
    float d = sheetDepth(c);
    bool far = d == farPlane;
    cell[k] = CellVertex(texelIndex(c), far, lightViewPoint(c, d), d, far ? texelIndex(c) : texelCount() + texelIndex(c));
    if ((sides[k] & kBoundaryBit) == 0u) continue;
    ivec2 P = sideTexel(q0, k);
    int axis = sideAxis(k);
    vec4 record = texelFetch(crossingRecords, ivec3(P, axis), 0);
    bool surface = (sides[k] & kSurfaceBit) != 0u;
    uint cap = surface ? crossingId(P, axis, 2u) : crossingId(P, axis, 1u);
    CellVertex nearV = CellVertex(crossingId(P, axis, 0u), false, lightViewPointAt(record.xy, record.z), record.z, cap);
    CellVertex farV = CellVertex(crossingId(P, axis, 1u), !surface, lightViewPointAt(record.xy, record.w), record.w, cap);
    bool cornerIsNear = (k < 2) == ((sides[k] & kNearAtPBit) != 0u);  // corner k is the edge's near end
    cell[A(k)] = cornerIsNear ? nearV : farV;
    cell[B(k)] = cornerIsNear ? farV : nearV;
  }
}

void main() {
  uint id = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u + gl_LocalInvocationID.x;
  if (id >= counters[11]) return;
  ivec2 q0 = quadCorner(int(refinedQuads[id]));
  uint sides[4];
  int split[4];
  int n = 0;
  for (int k = 0; k < 4; ++k) {
    sides[k] = flags[texelIndex(sideTexel(q0, k))] >> uint(sideAxis(k));
    if ((sides[k] & kBoundaryBit) != 0u) split[n++] = k;
  }
  assemble(q0, sides);
  float centre = n >= 3 ? texelFetch(crossingRecords, ivec3(q0, 2), 0).x : farPlane;
  triangulate(split, n, centre);
  // The exact cap's rule: a triangle with three far vertices is dropped.
  uint n3 = 0u;
  for (int k = 0; k < triCount; ++k) {
    ivec3 v = tri[k];
    if (cell[v.x].far && cell[v.y].far && cell[v.z].far) continue;
    n3 += (footprint[k] && drawCap != 0) ? 6u : 3u;
  }
  if (n3 == 0u) return;
  uint at = atomicAdd(indexCount, n3);
  atomicAdd(quadCount, 1u);
  if (at + n3 > uint(capacity)) return;
  for (int k = 0; k < triCount; ++k) {
    ivec3 v = tri[k];
    if (cell[v.x].far && cell[v.y].far && cell[v.z].far) continue;
    indices[at] = cell[v.x].id;
    indices[at + 1u] = cell[v.y].id;
    indices[at + 2u] = cell[v.z].id;
    at += 3u;
    if (!footprint[k] || drawCap == 0) continue;
    indices[at] = cell[v.x].cap;
    indices[at + 1u] = cell[v.z].cap;
    indices[at + 2u] = cell[v.y].cap;
    at += 3u;
  }
}

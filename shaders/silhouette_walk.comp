// (version_430.glsl, light_window_depth.glsl, volume_common.glsl and refine_common.glsl come
// first.) The silhouette
// walk (RefineCrossings::GpuWalk, docs/gpu.md "Crossings from a triangle walk"): where along a
// boundary edge the near surface ends, exactly, from the scene's triangles instead of rays.
//
// The light pass recorded at each texel the triangle it kept (light_triangle.frag: index + 1, 0 =
// none). A walk goes from a texel centre A towards a point B of the image plane, starting in the
// triangle A recorded: in the current triangle (projected to texel coordinates) it finds the edge
// through which the segment leaves, and steps to the triangle across it (triangle_adjacency.h)
// when that one turns the same way as the first as the light sees it (the sign of its projected
// area: front or back facing, the distinction the light pass's culling makes; the other sign
// across a link to a triangle wound the other way). It stops
//   - where it leaves through an edge with no neighbour, or into a triangle that turns the other
//     way or is edge-on (a silhouette edge of the surface A sees): status kCrossed, at that point
//     (but see the fold rule below);
//   - where it reaches B inside a triangle of the surface: status kReached, at B;
//   - after kMaxWalkTriangles triangles, at a triangle with a vertex behind a spot light's apex
//     plane, where A recorded no triangle or A's triangle is edge-on: status kFailed.
// The depth it reports is the light-view depth (world units) of the last triangle's plane on the
// light ray through the stopping point; the caller applies the sheet-depth rule.
// A surface edge's walk also stops (kDeeper) where the surface's depth reaches the middle of the
// jump between the two ends (as bisection's first step does; its later steps move the middle with
// their bracket, silhouette_refinement.h), a far edge's where it reaches the depth the sheet-depth
// rule puts on the far plane (hitLimit: beyond it a bisection ray's sample counts as no hit).
// One invocation per query:
//   edge (boundary edge P-Q, texel P = (i, j), Q one step along `axis`): a walk from the near end
//     N towards the far end R. kCrossed gives the crossing's edge parameter s (from N) and near
//     depth; a surface edge then walks back from R towards the crossing point X, stopping there (or
//     where R's surface ends first): the far depth, that of the surface seen past the outline at X.
//     kDeeper (a steep surface split where it goes on, or one passing the far plane): the crossing
//     there, its wall from the depth kWallHalfWidth before it to the depth kWallHalfWidth after it.
//     kReached on a far edge
//     (the near surface spans the edge; its far end is far only as the map's border ring): s = 1
//     at R's depth. Answered kCrossed in these three cases; kReached on a surface edge (a jump
//     that never reaches its middle) and kFailed are left to the caller's fallback.
//   centre (quad (i, j), its centre (i + 0.5, j + 0.5)): a walk from each corner that recorded a
//     triangle, nearest corner first (its triangle's depth at the corner); the first that reaches
//     the centre gives its depth, none: kNoHit.
// Folds: where an edge's walk stops at a silhouette edge, the surface it walked may only fold away
// while another goes on behind it (a bump of a real mesh seen edge-on), which bisection's rays
// would follow. So the walk looks for a surface just past the stop (kRestartStep further along the
// edge): from the triangle recorded at each of N, R and their neighbours across the edge it walks
// to that point, and of those that reach it with a depth below the edge's threshold (what the rays
// would count as the near side) the nearest is where the walk resumes, at most maxRestarts (4) times.
// Only surfaces recorded at those six texels are found; one that covers the segment in its middle
// and none of them is missed (as bisection's rays may miss it too).
// One layer only: midpoint capture (the mean of two) is refused by the renderer. Keep the result
// layout in step with walk_crossings.h's WalkResult.
// Queries come from a list (gridQueries = 0: the explicit volume's, walk_crossings.h) or from the
// boundary flags (gridQueries = 1: the refined GPU volume, refine_common.glsl): one invocation per
// slot of walk_slots.comp's list, slot 3 t + k for texel t = (i, j) (k = 0, 1: its boundary edge
// along axis k; 2: the centre of quad (i, j), which has 3 or 4 boundary sides), dispatched
// indirectly in rows of work groups.
// Their answers become the wall's crossing as walk_crossings.h's refinementFromWalks makes it
// (gridCrossing, rule for rule) and go to crossingRecords, layer k at (i, j): (texel coordinates
// of the crossing, near depth, far depth); a centre's: (its sheet depth, 0, 0, 0).
layout(local_size_x = 64) in;

const uint kEdgeQuery = 0u, kCentreQuery = 1u;
const uint kCrossed = 0u, kReached = 1u, kFailed = 2u, kDeeper = 3u;
const int kMaxWalkTriangles = 1024;
const int kFlippedNeighbour = 1 << 30;  // triangle_adjacency.h
const float kRestartStep = 1.0 / 1024.0;   // how far past the fold (edge parameter) the resumed walk starts
const float kWallHalfWidth = 1.0 / 256.0;  // kDeeper: the wall's ends this far either side (edge parameter)
const float kNoHitDepth = uintBitsToFloat(0x7f800000u);  // +infinity, DepthMap::kNoHit

struct WalkQuery { uint kind; int i; int j; uint flags; };  // flags: bit 0 axis, 1 nearAtP, 2 surface
struct WalkResult { float s; float nearDepth; float farDepth; uint status; };

layout(std430, binding = 0) readonly buffer Queries { WalkQuery queries[]; };
layout(std430, binding = 1) writeonly buffer Results { WalkResult results[]; };
layout(std430, binding = 2) readonly buffer SceneVertices { float sceneVertices[]; };  // renderer's VBO
layout(std430, binding = 3) readonly buffer SceneIndices { uint sceneIndices[]; };
layout(std430, binding = 4) readonly buffer Neighbours { int neighbours[]; };
layout(std430, binding = 5) readonly buffer Flags { uint flags[]; };   // gridQueries = 1
layout(std430, binding = 6) buffer Counters { uint counters[]; };      // [2] edges walked, [3] fallbacks, [10] slots
layout(std430, binding = 7) readonly buffer WalkSlots { uint walkSlots[]; };  // walk_slots.comp's list
layout(rgba32f, binding = 0) writeonly uniform image2DArray crossingRecords;
uniform int gridQueries;          // 1: the queries are the boundary flags' (see the header comment)
uniform usampler2D triangleIds;   // light_triangle.frag's record
uniform int queryCount;
uniform int vertexStride;         // floats per scene vertex (position first)
uniform mat4 worldToLightView;    // V_light, composed in double
// Loop bounds as uniforms (16, kMaxRestarts = 4 and 6, set by silhouette_walk.cpp), so that the compiler
// does not unroll the loops around a walk into many copies of it (seconds of JIT on llvmpipe).
uniform int depthHalvings;        // where a walk's depth reaches its threshold, found to 2^-16 of the stretch
uniform int maxRestarts;          // walks resumed past a fold, per edge
uniform int candidateTexels;      // texels whose triangles may go on past a fold: N, R and their neighbours across
uniform float hitLimit;           // the largest depth the sheet-depth rule takes as a hit (farSnap less
                                  // the bias and, with blur, the blur offset)

// One scene triangle as the light sees it: light-view vertices, their texel coordinates, and the
// sign of its projected area (+1, -1; 0 when edge-on or behind a spot light's apex plane).
struct LightTriangle { vec3 lv[3]; vec2 p[3]; float turn; bool behind; };

float cross2(vec2 u, vec2 v) { return u.x * v.y - u.y * v.x; }

LightTriangle lightTriangle(int t) {
  LightTriangle T;
  bool behind = false;
  for (int k = 0; k < 3; ++k) {
    uint v = sceneIndices[3 * t + k] * uint(vertexStride);
    vec3 world = vec3(sceneVertices[v], sceneVertices[v + 1u], sceneVertices[v + 2u]);
    T.lv[k] = (worldToLightView * vec4(world, 1.0)).xyz;
    behind = behind || !(lightClipW(T.lv[k]) > 0.0);
    T.p[k] = behind ? vec2(0.0) : texelOf(T.lv[k]);
  }
  float area = cross2(T.p[1] - T.p[0], T.p[2] - T.p[0]);
  T.turn = behind ? 0.0 : sign(area);
  T.behind = behind;
  return T;
}

// Light-view depth of triangle T's plane on the light ray through texel coordinates u.
float depthOn(LightTriangle T, vec2 u) {
  vec3 p0 = lightViewPointAt(u, 0.0), dir = lightViewPointAt(u, 1.0) - p0;
  vec3 n = cross(T.lv[1] - T.lv[0], T.lv[2] - T.lv[0]);
  float den = dot(n, dir);
  if (abs(den) <= 1e-30 * length(n) * length(dir))  // edge-on: the nearest vertex's depth
    return min(-T.lv[0].z, min(-T.lv[1].z, -T.lv[2].z));
  return dot(n, T.lv[0] - p0) / den;
}

// Where, between parameters t0 and t1 of the segment a -> b inside triangle T, its depth reaches
// `threshold` (it is below it at t0 and not at t1): depthHalvings (16) halvings.
float depthCrossing(LightTriangle T, vec2 a, vec2 b, float t0, float t1, float threshold) {
  for (int k = 0; k < depthHalvings; ++k) {
    float m = 0.5 * (t0 + t1);
    if (depthOn(T, mix(a, b, m)) < threshold) t0 = m; else t1 = m;
  }
  return 0.5 * (t0 + t1);
}

// Walks along the segment a -> b from parameter tStart (a point inside triangle t) up to tEnd.
// With a finite `threshold` it also stops (kDeeper) where the surface's depth reaches it.
// Returns the status; tOut is where it stopped, depth the depth there, last the triangle there
// (see the header comment).
uint walk(int t, vec2 a, vec2 b, float tStart, float tEnd, float threshold, out float tOut, out float depth,
          out int last) {
  tOut = tStart;
  depth = kNoHitDepth;
  last = t;
  LightTriangle T = lightTriangle(t);
  float turn = T.turn;
  if (turn == 0.0) return kFailed;
  int entered = -1;  // the current triangle's edge the walk came in through
  float tc = tStart;
  for (int step = 0; step < kMaxWalkTriangles; ++step) {
    float tExit = 1e30;
    int exitEdge = -1;
    for (int k = 0; k < 3; ++k) {
      if (k == entered) continue;
      vec2 p = T.p[k], q = T.p[(k + 1) % 3];
      float ea = turn * cross2(q - p, a - p), eb = turn * cross2(q - p, b - p);
      if (eb < ea) {  // the segment runs out through this edge's line
        float tk = ea / (ea - eb);
        if (tk < tExit) { tExit = tk; exitEdge = k; }
      }
    }
    tExit = max(tExit, tc);
    bool reached = exitEdge < 0 || tExit >= tEnd;
    float tStop = reached ? tEnd : tExit;
    last = t;
    if (depthOn(T, mix(a, b, tStop)) >= threshold) {
      tOut = depthCrossing(T, a, b, tc, tStop, threshold);
      depth = depthOn(T, mix(a, b, tOut));
      return kDeeper;
    }
    if (reached) {
      tOut = tEnd;
      depth = depthOn(T, mix(a, b, tEnd));
      return kReached;
    }
    int link = neighbours[3 * t + exitEdge];
    int next = link < 0 ? -1 : link & ~kFlippedNeighbour;
    // A neighbour wound the other way (kFlippedNeighbour) faces as this one does when its sign is
    // the opposite: from there on the walk compares with the flipped sign.
    float expected = (link & kFlippedNeighbour) != 0 ? -turn : turn;
    LightTriangle N;
    if (next >= 0) N = lightTriangle(next);
    if (next >= 0 && N.behind) return kFailed;  // no projection to compare: not a silhouette
    if (next < 0 || N.turn != expected) {
      tOut = tExit;
      depth = depthOn(T, mix(a, b, tExit));
      return kCrossed;
    }
    turn = expected;
    entered = (neighbours[3 * next] & ~kFlippedNeighbour) == t ? 0 : ((neighbours[3 * next + 1] & ~kFlippedNeighbour) == t ? 1 : 2);
    t = next;
    T = N;
    tc = tExit;
  }
  return kFailed;
}

int recorded(ivec2 texel) { return int(texelFetch(triangleIds, texel, 0).r) - 1; }

// After a walk stopped at a silhouette edge at parameter s of N -> R: a surface that goes on just
// past it, below `threshold` (what bisection's rays would still count as the near side), found by
// walking from the triangles recorded at N, R and their neighbours across the edge to that point.
// Returns the triangle there (the nearest such surface), or -1.
int surfaceGoingOn(ivec2 N, ivec2 R, float s, float threshold) {
  vec2 y = mix(vec2(N), vec2(R), s + kRestartStep);
  ivec2 across = N.x == R.x ? ivec2(1, 0) : ivec2(0, 1);
  ivec2 from[6] = ivec2[6](N, R, N + across, N - across, R + across, R - across);
  int best = -1;
  float bestDepth = threshold;
  for (int k = 0; k < candidateTexels; ++k) {
    if (any(lessThan(from[k], ivec2(0))) || any(greaterThanEqual(from[k], size))) continue;
    int t = recorded(from[k]);
    if (t < 0) continue;
    float tOut, d;
    int last;
    if (walk(t, vec2(from[k]), y, 0.0, 1.0, kNoHitDepth, tOut, d, last) == kReached && d < bestDepth) {
      best = last;
      bestDepth = d;
    }
  }
  return best;
}

WalkResult edgeQuery(WalkQuery q) {
  WalkResult r = WalkResult(0.5, kNoHitDepth, kNoHitDepth, kFailed);
  ivec2 P = ivec2(q.i, q.j), Q = P + ((q.flags & 1u) == 0u ? ivec2(1, 0) : ivec2(0, 1));
  bool nearAtP = (q.flags & 2u) != 0u, surface = (q.flags & 4u) != 0u;
  ivec2 N = nearAtP ? P : Q, R = nearAtP ? Q : P;
  int t = recorded(N), tr = recorded(R);
  if (t < 0 || (surface && tr < 0)) return r;
  // A surface edge: the middle of the jump, the ends' depths as their triangles give them; a far
  // edge: where depth + bias passes the far plane.
  float threshold = surface ? 0.5 * (depthOn(lightTriangle(t), vec2(N)) + depthOn(lightTriangle(tr), vec2(R)))
                            : hitLimit;
  float s = 0.0, d;
  int last = t;
  uint status = kFailed;
  for (int restart = 0; restart <= maxRestarts; ++restart) {
    status = walk(t, vec2(N), vec2(R), s, 1.0, threshold, s, d, last);
    if (status != kCrossed || restart == maxRestarts || s + kRestartStep >= 1.0) break;
    int goingOn = surfaceGoingOn(N, R, s, threshold);  // a fold: something behind goes on
    if (goingOn < 0) break;
    t = goingOn;
    s += kRestartStep;
  }
  if (status == kFailed || (status == kReached && surface)) return r;
  r.status = kCrossed;
  r.s = status == kReached ? 1.0 : s;  // reached: a far edge whose near surface spans it (its far end is the ring)
  r.nearDepth = d;
  if (status == kDeeper) {  // the surface goes on (steeply, or past the far plane): a wall where it crosses
    // The wall's ends on the last triangle's plane, 1/256 either side (a plane nearly along the
    // light's rays can put them off the surface; refinementFromWalks then falls back to the ends').
    LightTriangle T = lightTriangle(last);
    r.nearDepth = depthOn(T, mix(vec2(N), vec2(R), max(s - kWallHalfWidth, 0.0)));
    r.farDepth = depthOn(T, mix(vec2(N), vec2(R), min(s + kWallHalfWidth, 1.0)));
    return r;
  }
  if (!surface || status == kReached) return r;
  float back, df;
  int lastBack;
  if (walk(tr, vec2(R), vec2(N), 0.0, 1.0 - s, kNoHitDepth, back, df, lastBack) != kFailed) r.farDepth = df;
  return r;
}

WalkResult centreQuery(WalkQuery q) {
  WalkResult r = WalkResult(0.5, kNoHitDepth, kNoHitDepth, kReached);
  vec2 c = vec2(q.i, q.j) + 0.5;
  int tri[4];
  float dist[4];
  for (int k = 0; k < 4; ++k) {
    ivec2 corner = ivec2(q.i, q.j) + kCornerOffset[k];
    tri[k] = recorded(corner);
    dist[k] = tri[k] < 0 ? kNoHitDepth : depthOn(lightTriangle(tri[k]), vec2(corner));
  }
  for (int n = 0; n < 4; ++n) {  // nearest corner first; ties by corner order
    int best = -1;
    for (int k = 0; k < 4; ++k)
      if (tri[k] >= 0 && (best < 0 || dist[k] < dist[best])) best = k;
    if (best < 0) break;
    float s, d;
    int last;
    if (walk(tri[best], vec2(ivec2(q.i, q.j) + kCornerOffset[best]), c, 0.0, 1.0, kNoHitDepth, s, d, last) == kReached) {
      r.nearDepth = d;
      return r;
    }
    tri[best] = -1;
  }
  r.status = kCrossed;  // every walk left its surface before the centre
  return r;
}

const float kWalkEdgeMargin = 1.0 / 256.0;  // walk_crossings.h

// walk_crossings.h's refinementFromWalks for one edge (P, axis; flags e shifted to axis 0):
// (crossing's texel coordinates, near depth, far depth); counts a fallback.
vec4 gridCrossing(ivec2 P, int axis, uint e, WalkResult w) {
  bool nearAtP = (e & kNearAtPBit) != 0u, surface = (e & kSurfaceBit) != 0u;
  ivec2 Q = P + (axis == 0 ? ivec2(1, 0) : ivec2(0, 1));
  ivec2 N = nearAtP ? P : Q, R = nearAtP ? Q : P;
  float uN = unblurredDepth(N);
  float nearEnd = uN != farPlane ? uN : sheetDepth(N);  // edgeSegment's nearFallback
  float farEnd = surface ? unblurredDepth(R) : farPlane;
  float s = 0.5, nearDepth = nearEnd, farDepth = farEnd;
  bool found = w.status == kCrossed && !isnan(w.s) && !isinf(w.s);
  if (found) {
    s = clamp(w.s, kWalkEdgeMargin, 1.0 - kWalkEdgeMargin);
    float nearAt = ofSample(w.nearDepth);
    if (nearAt != farPlane) nearDepth = nearAt;
    if (surface) {
      float farAt = ofSample(w.farDepth);
      farDepth = farAt != farPlane && farAt > nearDepth ? farAt : farEnd;
      if (!(farDepth > nearDepth)) {  // the near vertex came out beyond the far end's depth
        found = false;
        s = 0.5;
        nearDepth = nearEnd;
        farDepth = farEnd;
      }
    }
  }
  if (!found) atomicAdd(counters[3], 1u);
  return vec4(mix(vec2(N), vec2(R), s), nearDepth, farDepth);
}

void gridMain() {
  uint id = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u + gl_LocalInvocationID.x;
  if (id >= counters[10]) return;
  uint slot = walkSlots[id], t = slot / 3u;
  int k = int(slot % 3u), i = int(t % uint(size.x)), j = int(t / uint(size.x));
  ivec2 P = ivec2(i, j);
  if (k < 2) {
    uint e = flags[texelIndex(P)] >> uint(k);
    if ((e & kBoundaryBit) == 0u) return;
    uint queryFlags = uint(k) | ((e & kNearAtPBit) != 0u ? 2u : 0u) | ((e & kSurfaceBit) != 0u ? 4u : 0u);
    WalkResult r = edgeQuery(WalkQuery(kEdgeQuery, i, j, queryFlags));
    imageStore(crossingRecords, ivec3(P, k), gridCrossing(P, k, e, r));
    atomicAdd(counters[2], 1u);
    return;
  }
  WalkResult r = centreQuery(WalkQuery(kCentreQuery, i, j, 0u));
  imageStore(crossingRecords, ivec3(P, 2), vec4(ofSample(r.nearDepth), 0.0, 0.0, 0.0));
}

void main() {
  if (gridQueries != 0) {
    gridMain();
    return;
  }
  int k = int(gl_GlobalInvocationID.x);
  if (k >= queryCount) return;
  WalkQuery q = queries[k];
  results[k] = q.kind == kEdgeQuery ? edgeQuery(q) : centreQuery(q);
}

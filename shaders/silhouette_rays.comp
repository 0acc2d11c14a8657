// (version_430.glsl, light_window_depth.glsl, volume_common.glsl and refine_common.glsl come
// first.) The refined GPU volume's crossings by bisection rays (RefineCrossings::Rays with
// --volume gpu, docs/gpu.md "Crossings from GPU rays"): the CPU builder's refinement
// (silhouette_refinement.h's bisectWith and edgeSegment, rule for rule) with each ray cast here,
// through triangle_bvh.h's hierarchy of the scene's triangles, by the capture rule of the light
// pass (depth_capture.h's captureRay): the nearest hit in [near, far] for front capture, the
// nearest back face (its counter-clockwise normal along the ray) for back capture, and for entry
// capture the nearest face up to the nearest back face that is not lit nearly edge-on (the back
// face itself where there is none; nothing without a back face).
// One invocation per slot of walk_slots.comp's list, dispatched indirectly in rows of work groups:
//   slot 3 t + k, k = axis (0, 1): texel t's boundary edge along k: refineSteps halvings of the
//     bracket from the near end N to the far end R, then, with snapCrossings, crossing_snap.h's
//     snap (the triangle each round's ray records at lo, where the edge leaves its image:
//     triangle_exit.h's rule in float; a probe just beyond); its record (layer k at t): the
//     crossing's texel coordinates (the middle of the last bracket, or where it snapped), near
//     depth, far depth;
//   k = 2: the centre of quad t (3 or 4 boundary sides): one ray; its record (sheet depth, 0, 0, 0).
layout(local_size_x = 64) in;

struct BvhNode { float lo[3]; uint first; float hi[3]; uint count; };  // triangle_bvh.h

layout(std430, binding = 3) readonly buffer BvhTriangles { vec4 bvhCorners[]; };  // 3 corners each (xyz), leaf order
layout(std430, binding = 4) readonly buffer BvhNodes { BvhNode nodes[]; };
layout(std430, binding = 5) readonly buffer Flags { uint flags[]; };
layout(std430, binding = 6) buffer Counters { uint counters[]; };  // [2] edges refined, [3] fallbacks, [10] slots
layout(std430, binding = 7) readonly buffer WalkSlots { uint walkSlots[]; };
layout(rgba32f, binding = 0) writeonly uniform image2DArray crossingRecords;
uniform mat4 lightViewToWorld;   // inverse of V_light, composed in double
uniform int refineSteps;         // K: rays per boundary edge
uniform int captureRule;         // kFrontRule, kBackRule or kEntryRule
uniform float grazingCos;        // entry: kEntryGrazingCos (depth_map.h)
uniform int nodeCount;           // 0: no triangles
uniform int snapCrossings;       // 1: crossing_snap.h's snap after bisection (VolumeBuildOptions::refineSnap)
uniform mat4 worldToLightView;   // V_light, composed in double (the snap's triangle images)

const int kStack = 64;                    // kBvhMaxDepth (silhouette_rays.cpp asserts they agree): never full
const float kNoHitDepth = uintBitsToFloat(0x7f800000u);  // +infinity, DepthMap::kNoHit
const float kBarycentricSlack = 1e-6;     // a ray through a shared edge hits both triangles
const uint kNoTriangle = 0xffffffffu;
const int kFrontRule = 0, kBackRule = 1, kEntryRule = 2;  // silhouette_rays.cpp sets captureRule
const int kSnapRounds = 3;                // crossing_snap.h (SnapConstantsMatchTheShader keeps them in step)
const float kSnapProbeTexels = 1.0 / 4096.0;
const float kSnapEndSlack = 1e-9;

// The entry parameter of the ray o + t d (1 / d = inv, safeInverse) into node n's box within
// [t0, t1], or +infinity when it misses.
float boxEntry(uint n, vec3 o, vec3 inv, float t0, float t1) {
  vec3 lo = vec3(nodes[n].lo[0], nodes[n].lo[1], nodes[n].lo[2]);
  vec3 hi = vec3(nodes[n].hi[0], nodes[n].hi[1], nodes[n].hi[2]);
  vec3 a = (lo - o) * inv, b = (hi - o) * inv;
  vec3 tmin = min(a, b), tmax = max(a, b);
  float enter = max(max(tmin.x, tmin.y), max(tmin.z, t0));
  float leave = min(min(tmax.x, tmax.y), min(tmax.z, t1));
  return enter <= leave + 1e-6 * abs(leave) ? enter : kNoHitDepth;  // slack: flat boxes, rounding
}

// Triangle k (leaf order) against the ray: its parameter when hit within [t0, tBest) and
// accepted by the capture rule (kBackRule: back faces only), else tBest. `back`: whether it is a
// back face; `grazing` (kEntryRule only): a face that is not, lit nearly edge-on (cosine below
// grazingCos).
float hitTriangle(uint k, vec3 o, vec3 d, float t0, float tBest, out bool back, out bool grazing) {
  vec3 v0 = bvhCorners[3u * k].xyz, v1 = bvhCorners[3u * k + 1u].xyz, v2 = bvhCorners[3u * k + 2u].xyz;
  vec3 e1 = v1 - v0, e2 = v2 - v0;
  vec3 normal = cross(e1, e2);
  float along = dot(normal, d);
  back = along > 0.0;
  grazing = captureRule == kEntryRule && !back && -along < grazingCos * length(normal) * length(d);
  if (captureRule == kBackRule && !back) return tBest;
  vec3 p = cross(d, e2);
  float det = dot(e1, p);
  if (det == 0.0) return tBest;
  float invDet = 1.0 / det;
  vec3 s = o - v0;
  float u = dot(s, p) * invDet;
  if (u < -kBarycentricSlack || u > 1.0 + kBarycentricSlack) return tBest;
  vec3 q = cross(s, e1);
  float v = dot(d, q) * invDet;
  if (v < -kBarycentricSlack || u + v > 1.0 + kBarycentricSlack) return tBest;
  float t = dot(e2, q) * invDet;
  return t >= t0 && t < tBest ? t : tBest;
}

// The next float above x (x finite and >= 0): hitTriangle's bound that lets t == x through.
float nextFloat(float x) { return uintBitsToFloat(floatBitsToUint(x) + 1u); }

// 1 / d, finite: a component of magnitude below 1e-30 counts as +-1e-30 (+ for 0), as Embree's
// traversal takes it. So a ray that does not move along an axis and lies exactly on a box's
// upper face along it misses the box, on its lower face enters it: asymmetric, but Embree's
// rule, which the explicit volume's rays follow (RefinedGpuVolumeByRaysIsTheExplicitVolumesBisection:
// 12 vertices apart with this rule, 204 with such faces counted on both sides or on neither, on
// the axis-aligned scenes whose bisection samples land on box faces).
vec3 safeInverse(vec3 d) {
  vec3 s = mix(vec3(1.0), sign(d), notEqual(d, vec3(0.0)));
  return 1.0 / mix(d, s * 1e-30, lessThan(abs(d), vec3(1e-30)));
}

// The light-view depth the capture rule records along the light ray through texel coordinates
// u (lightViewPointAt's), within [nearPlane, farPlane); kNoHitDepth when nothing is recorded
// (a hit at the far plane itself would be the far plane to the sheet-depth rule anyway).
float castRayHit(vec2 u, out uint triangle) {
  triangle = kNoTriangle;
  if (nodeCount == 0) return kNoHitDepth;
  // Light view: the point at depth t is a + t b (linear in t, -b.z = 1); the ray starts at the
  // near plane, so its parameter is the depth less nearPlane.
  vec3 a = lightViewPointAt(u, 0.0), b = lightViewPointAt(u, 1.0) - a;
  vec3 o = (lightViewToWorld * vec4(a + nearPlane * b, 1.0)).xyz;
  vec3 d = (lightViewToWorld * vec4(b, 0.0)).xyz;
  vec3 inv = safeInverse(d);
  float range = farPlane - nearPlane, best = range;
  float bestFront = kNoHitDepth;  // entry: the nearest face seen that is neither a back face nor grazing
  uint frontTriangle = kNoTriangle;
  uint stack[kStack];
  float entries[kStack];  // each stacked node's entry parameter: skipped once a hit lies before it
  int top = 0;
  float rootEntry = boxEntry(0u, o, inv, 0.0, range);
  if (rootEntry != kNoHitDepth) {
    stack[0] = 0u;
    entries[0] = rootEntry;
    top = 1;
  }
  while (top > 0) {
    --top;
    uint n = stack[top];
    if (entries[top] > best) continue;
    if (nodes[n].count > 0u) {
      for (uint k = nodes[n].first; k < nodes[n].first + nodes[n].count; ++k) {
        bool back, grazing;
        // Entry: any face up to the nearest back face so far (included) is a candidate.
        float t = hitTriangle(k, o, d, 0.0, captureRule == kEntryRule ? nextFloat(best) : best, back, grazing);
        if (captureRule == kEntryRule && !back) {
          if (!grazing && t <= best && (t < bestFront || (t == bestFront && k < frontTriangle))) {
            bestFront = t;
            frontTriangle = k;
          }
          continue;
        }
        if (t < best) {
          best = t;
          triangle = k;
        }
      }
      continue;
    }
    uint c0 = nodes[n].first, c1 = c0 + 1u;
    float e0 = boxEntry(c0, o, inv, 0.0, best), e1 = boxEntry(c1, o, inv, 0.0, best);
    if (e0 > e1) {  // the nearer child on top of the stack
      uint c = c0;
      c0 = c1;
      c1 = c;
      float e = e0;
      e0 = e1;
      e1 = e;
    }
    if (e1 != kNoHitDepth && top < kStack) {
      stack[top] = c1;
      entries[top++] = e1;
    }
    if (e0 != kNoHitDepth && top < kStack) {
      stack[top] = c0;
      entries[top++] = e0;
    }
  }
  if (!(best < range)) triangle = kNoTriangle;
  if (captureRule == kEntryRule && best < range && bestFront <= best) {  // (entry: no back face, no record)
    best = bestFront;
    triangle = frontTriangle;
  }
  return best < range ? nearPlane + best : kNoHitDepth;
}
float castRay(vec2 u) {
  uint triangle;
  return castRayHit(u, triangle);
}

// triangle_exit.h's triangleExit in float: the fraction of the way from -> to (texel coordinates)
// at which the path leaves triangle k's image (>= 0, may exceed 1), or -1 where it has none.
float triangleExit(uint k, vec2 from, vec2 to) {
  vec2 dir = to - from;
  if (dir == vec2(0.0)) return -1.0;
  vec2 image[3];
  for (int c = 0; c < 3; ++c) {
    vec3 p = (worldToLightView * vec4(bvhCorners[3u * k + uint(c)].xyz, 1.0)).xyz;
    if (projZW.z != 0.0 && !(-p.z > 1e-9 * farPlane)) return -1.0;  // at or behind a spot light's apex plane
    image[c] = texelOf(p);
  }
  vec2 ab = image[1] - image[0], ac = image[2] - image[0];
  float area2 = ab.x * ac.y - ab.y * ac.x;
  float longest = 0.0;
  for (int c = 0; c < 3; ++c) longest = max(longest, dot(image[(c + 1) % 3] - image[c], image[(c + 1) % 3] - image[c]));
  if (!(abs(area2) > 1e-12 * longest)) return -1.0;
  float t = kNoHitDepth;
  for (int c = 0; c < 3; ++c) {
    vec2 a = image[c], e = image[(c + 1) % 3] - a;
    vec2 n = area2 > 0.0 ? vec2(e.y, -e.x) : vec2(-e.y, e.x);
    float rate = dot(n, dir);
    if (rate > 0.0) t = min(t, dot(n, a - from) / rate);
  }
  return t == kNoHitDepth ? -1.0 : max(t, 0.0);
}

void refineEdge(ivec2 P, int axis, uint e) {
  bool nearAtP = (e & kNearAtPBit) != 0u, surface = (e & kSurfaceBit) != 0u;
  ivec2 Q = P + (axis == 0 ? ivec2(1, 0) : ivec2(0, 1));
  ivec2 N = nearAtP ? P : Q, R = nearAtP ? Q : P;
  // edgeSegment: the ends' depths by the rule for one sample (the ring is the far plane).
  float dLo = unblurredDepth(N), dHi = surface ? unblurredDepth(R) : farPlane;
  float lo = 0.0, hi = 1.0;
  uint triangleLo = kNoTriangle;  // the triangle recorded at lo, once a ray has been cast there
  for (int step = 0; step < refineSteps; ++step) {
    float m = 0.5 * (lo + hi);
    uint triangle;
    float d = ofSample(castRayHit(mix(vec2(N), vec2(R), m), triangle));
    bool hit = d != farPlane;
    if (hit && (!surface || d < 0.5 * (dLo + dHi))) {
      lo = m;
      dLo = d;
      triangleLo = triangle;
    } else {
      hi = m;
      if (hit && surface) dHi = d;
    }
  }
  // bisectWith's crossing: the bracket's middle; a near depth on the far plane (blur) falls back
  // to the near end's final sheet depth. The snap (crossing_snap.h) moves s and the far depth.
  float s = -1.0, probeFar = farPlane;
  if (snapCrossings != 0) {
    for (int round = 0; round < kSnapRounds; ++round) {
      // The triangle at lo: the ray that put lo there recorded it (the same ray, the same answer
      // as crossing_snap.h's surface-end ray); at the near end itself one ray finds it.
      vec2 from = mix(vec2(N), vec2(R), lo);
      if (triangleLo == kNoTriangle) castRayHit(from, triangleLo);
      if (triangleLo == kNoTriangle) break;
      float t = triangleExit(triangleLo, from, mix(vec2(N), vec2(R), hi));
      if (!(t >= 0.0 && t <= 1.0 + kSnapEndSlack)) break;
      float se = min(lo + t * (hi - lo), hi);
      if (se == hi) {
        s = se;
        break;
      }
      float sp = se + min(kSnapProbeTexels, 0.5 * (hi - se));  // an edge is one texel long
      if (!(sp > se && sp < hi)) break;
      uint triangle;
      float d = ofSample(castRayHit(mix(vec2(N), vec2(R), sp), triangle));
      if (d != farPlane && (!surface || d < 0.5 * (dLo + dHi))) {  // the surface goes on
        lo = sp;
        dLo = d;
        triangleLo = triangle;
        continue;
      }
      s = se;
      probeFar = d;
      break;
    }
  }
  // Snapped or not, 2^-(K+2) from the edge's ends (crossing_snap.cpp's margin): a bracket walked
  // on past probes can shrink onto hi, and a crossing on an end is a degenerate wall.
  float margin = exp2(float(-(refineSteps + 2)));
  s = clamp(s >= 0.0 ? s : 0.5 * (lo + hi), margin, 1.0 - margin);
  float nearDepth = dLo != farPlane ? dLo : sheetDepth(N);
  float farDepth = surface ? (probeFar != farPlane && probeFar > nearDepth ? probeFar : dHi) : farPlane;
  // In float the bracket's depths can meet (their middle rounds to the near one: a steep surface
  // at large K), which double never lets happen: the edge's fallback then, as the walk's
  // (gridCrossing), counted.
  if (!(farDepth > nearDepth)) {
    s = 0.5;
    nearDepth = unblurredDepth(N) != farPlane ? unblurredDepth(N) : sheetDepth(N);
    farDepth = surface ? unblurredDepth(R) : farPlane;
    atomicAdd(counters[3], 1u);
  }
  imageStore(crossingRecords, ivec3(P, axis), vec4(mix(vec2(N), vec2(R), s), nearDepth, farDepth));
  atomicAdd(counters[2], 1u);
}

void main() {
  uint id = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u + gl_LocalInvocationID.x;
  if (id >= counters[10]) return;
  uint slot = walkSlots[id], t = slot / 3u;
  int k = int(slot % 3u);
  ivec2 P = ivec2(int(t % uint(size.x)), int(t / uint(size.x)));
  if (k < 2) {
    uint e = flags[texelIndex(P)] >> uint(k);
    if ((e & kBoundaryBit) != 0u) refineEdge(P, k, e);
    return;
  }
  imageStore(crossingRecords, ivec3(P, 2), vec4(ofSample(castRay(vec2(P) + 0.5)), 0.0, 0.0, 0.0));
}

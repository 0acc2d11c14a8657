#include "shadowvol/embree/depth_capture.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <span>
#include <vector>

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadowvol/check.h"
#include "shadowvol/depth_map.h"
#include "shadowvol/embree/capture_ray.h"
#include "shadowvol/embree/embree_scene.h"
#include "shadowvol/error.h"

namespace shadowvol {
namespace {

// Extended intersect context: Embree hands the RTCIntersectContext* to the filter, and it is the
// first member here, so the filter can reach the per-ray state (style of Embree's tutorials).
struct CaptureContext {
  RTCIntersectContext ctx;
  float t1 = INFINITY;  // midpoint: nearest distinct hit distance
  float t2 = INFINITY;  // midpoint: second nearest distinct hit distance
};

// Two hits within this relative distance are the same surface (a ray through a shared edge or
// vertex reports each adjacent triangle).
constexpr float kSameSurface = 1e-5f;

// Rays per packet (rtcIntersect8, captureRays).
constexpr unsigned kPacket = 8;

// Back capture: accept only hits on back faces (geometric normal along the ray). Embree's Ng for a
// counter-clockwise triangle points to its front side, the same convention as OpenGL. Every filter
// here reads lane k of a packet of N rays (N = 1 for rtcIntersect1, 8 for rtcIntersect8: Embree
// hands the query's own packet, lane k being its ray k, with only the lanes to filter valid).
void backFaceFilter(const RTCFilterFunctionNArguments* args) {
  for (unsigned k = 0; k < args->N; ++k) {
    if (args->valid[k] == 0) continue;
    const float dx = RTCRayN_dir_x(args->ray, args->N, k), dy = RTCRayN_dir_y(args->ray, args->N, k),
                dz = RTCRayN_dir_z(args->ray, args->N, k);
    const float nx = RTCHitN_Ng_x(args->hit, args->N, k), ny = RTCHitN_Ng_y(args->hit, args->N, k),
                nz = RTCHitN_Ng_z(args->hit, args->N, k);
    if (!(dx * nx + dy * ny + dz * nz > 0.0f)) args->valid[k] = 0;
  }
}

// Entry capture in one traversal: back faces are accepted (Embree then narrows the ray to each,
// ending at the first), every other face is rejected, and the nearest of them that is not lit
// nearly edge-on (cosine with the ray below kEntryGrazingCos, in double so that the rule does not
// depend on the order of the products) is kept here. Any face before the first back face is seen,
// as the ray reaches at least that far.
struct EntryContext {
  RTCIntersectContext ctx;
  // Per lane of the packet: the nearest entering face's distance and ids.
  float t[kPacket] = {INFINITY, INFINITY, INFINITY, INFINITY, INFINITY, INFINITY, INFINITY, INFINITY};
  unsigned geomID[kPacket], primID[kPacket];
  EntryContext() {
    std::fill(std::begin(geomID), std::end(geomID), RTC_INVALID_GEOMETRY_ID);
    std::fill(std::begin(primID), std::end(primID), RTC_INVALID_GEOMETRY_ID);
  }
};

void entryFilter(const RTCFilterFunctionNArguments* args) {
  auto* c = reinterpret_cast<EntryContext*>(const_cast<RTCIntersectContext*>(args->context));
  for (unsigned k = 0; k < args->N; ++k) {
    if (args->valid[k] == 0) continue;
    const glm::dvec3 d(RTCRayN_dir_x(args->ray, args->N, k), RTCRayN_dir_y(args->ray, args->N, k),
                       RTCRayN_dir_z(args->ray, args->N, k));
    const glm::dvec3 n(RTCHitN_Ng_x(args->hit, args->N, k), RTCHitN_Ng_y(args->hit, args->N, k),
                       RTCHitN_Ng_z(args->hit, args->N, k));
    const double along = glm::dot(d, n);
    if (along > 0.0) continue;  // a back face: accepted
    args->valid[k] = 0;
    if (-along < kEntryGrazingCos * glm::length(d) * glm::length(n)) continue;  // lit nearly edge-on
    const float t = RTCRayN_tfar(args->ray, args->N, k);
    const unsigned g = RTCHitN_geomID(args->hit, args->N, k), p = RTCHitN_primID(args->hit, args->N, k);
    // The nearest; among equally near faces the lowest ids, whatever the traversal's order.
    if (t < c->t[k] || (t == c->t[k] && (g < c->geomID[k] || (g == c->geomID[k] && p < c->primID[k])))) {
      c->t[k] = t;
      c->geomID[k] = g;
      c->primID[k] = p;
    }
  }
}

// Midpoint capture: reject every hit (so traversal sees all of them) and keep the two nearest
// distinct distances.
void twoLayerFilter(const RTCFilterFunctionNArguments* args) {
  if (args->valid[0] == 0) return;
  auto* c = reinterpret_cast<CaptureContext*>(const_cast<RTCIntersectContext*>(args->context));
  const float t = RTCRayN_tfar(args->ray, args->N, 0);
  args->valid[0] = 0;
  // Not the same as an empty slot (b = +inf): |t - inf| <= 1e-5 * inf would hold, and a hit
  // arriving after a farther one then took the empty slot out of order (regression: the room's
  // crate in front of the floor gave the floor as the second surface, hits in BVH order).
  auto same = [](float a, float b) { return std::isfinite(b) && std::abs(a - b) <= kSameSurface * std::max(a, b); };
  if (same(t, c->t1) || same(t, c->t2)) {
    // a duplicate of a known surface: keep the smaller distance for determinism
    if (same(t, c->t1)) c->t1 = std::min(c->t1, t);
    else c->t2 = std::min(c->t2, t);
    return;
  }
  if (t < c->t1) {
    c->t2 = c->t1;
    c->t1 = t;
  } else if (t < c->t2) {
    c->t2 = t;
  }
}

}  // namespace

namespace {

// One ray: the first hit in [tNear, tFar], on back faces only with `backOnly`.
CapturedHit firstHit(RTCScene scene, const TexelUnprojector::Ray& ray, float tNear, float tFar, bool backOnly) {
  RTCRayHit rh = makeRayHit(ray.origin, ray.direction, tNear, tFar);
  CaptureContext c;
  rtcInitIntersectContext(&c.ctx);
  if (backOnly) c.ctx.filter = backFaceFilter;
  rtcIntersect1(scene, &c.ctx, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {};
  return {rh.ray.tfar, rh.hit.geomID, rh.hit.primID};
}

// Entry capture's ray (entryFilter): the first back face, and the first face up to it that is not
// lit nearly edge-on where there is one (the back face itself where not).
CapturedHit entryHit(RTCScene scene, const TexelUnprojector::Ray& ray, float tNear, float tFar) {
  RTCRayHit rh = makeRayHit(ray.origin, ray.direction, tNear, tFar);
  EntryContext c;
  rtcInitIntersectContext(&c.ctx);
  c.ctx.filter = entryFilter;
  rtcIntersect1(scene, &c.ctx, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {};
  if (c.t[0] <= rh.ray.tfar) return {c.t[0], c.geomID[0], c.primID[0]};
  return {rh.ray.tfar, rh.hit.geomID, rh.hit.primID};
}

}  // namespace

CapturedHit captureHit(RTCScene scene, const TexelUnprojector::Ray& ray, float tNear, float tFar, CaptureMode mode) {
  switch (mode) {
    case CaptureMode::Front: return firstHit(scene, ray, tNear, tFar, false);
    case CaptureMode::Back: return firstHit(scene, ray, tNear, tFar, true);
    case CaptureMode::Entry: return entryHit(scene, ray, tNear, tFar);
    case CaptureMode::Midpoint: break;
  }
  return {};
}

float captureRay(RTCScene scene, const TexelUnprojector::Ray& ray, float tNear, float tFar, CaptureMode mode) {
  if (mode != CaptureMode::Midpoint) return captureHit(scene, ray, tNear, tFar, mode).depth;
  RTCRayHit rh = makeRayHit(ray.origin, ray.direction, tNear, tFar);
  CaptureContext c;
  rtcInitIntersectContext(&c.ctx);
  c.ctx.filter = twoLayerFilter;
  rtcIntersect1(scene, &c.ctx, &rh);
  return std::isfinite(c.t1) ? 0.5f * (c.t1 + (std::isfinite(c.t2) ? c.t2 : tFar)) : DepthMap::kNoHit;
}

namespace {

// Up to kPacket rays in one rtcIntersect8 for front, back and entry capture, each lane read as
// firstHit and entryHit read their one ray (the same filters; lanes past `count` are masked off).
void capturePacket(RTCScene scene, const TexelUnprojector::Ray* rays, std::size_t count, float tNear, float tFar,
                   CaptureMode mode, float* depth) {
  alignas(32) int valid[kPacket];
  RTCRayHit8 rh{};
  for (std::size_t k = 0; k < kPacket; ++k) {
    valid[k] = k < count ? -1 : 0;
    const RTCRayHit one = makeRayHit(rays[k < count ? k : 0].origin, rays[k < count ? k : 0].direction, tNear, tFar);
    rh.ray.org_x[k] = one.ray.org_x;
    rh.ray.org_y[k] = one.ray.org_y;
    rh.ray.org_z[k] = one.ray.org_z;
    rh.ray.dir_x[k] = one.ray.dir_x;
    rh.ray.dir_y[k] = one.ray.dir_y;
    rh.ray.dir_z[k] = one.ray.dir_z;
    rh.ray.tnear[k] = one.ray.tnear;
    rh.ray.tfar[k] = one.ray.tfar;
    rh.ray.mask[k] = one.ray.mask;
    rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
  }
  EntryContext c;
  rtcInitIntersectContext(&c.ctx);
  if (mode == CaptureMode::Entry) c.ctx.filter = entryFilter;
  if (mode == CaptureMode::Back) c.ctx.filter = backFaceFilter;
  rtcIntersect8(valid, scene, &c.ctx, &rh);
  for (std::size_t k = 0; k < count; ++k) {
    if (rh.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID)
      depth[k] = DepthMap::kNoHit;
    else if (mode == CaptureMode::Entry && c.t[k] <= rh.ray.tfar[k])
      depth[k] = c.t[k];
    else
      depth[k] = rh.ray.tfar[k];
  }
}

}  // namespace

void captureRays(RTCScene scene, std::span<const TexelUnprojector::Ray> rays, float tNear, float tFar, CaptureMode mode,
                 std::span<float> depth) {
  SV_CHECK_EQ(rays.size(), depth.size());
  if (mode == CaptureMode::Midpoint) {
    for (std::size_t k = 0; k < rays.size(); ++k) depth[k] = captureRay(scene, rays[k], tNear, tFar, mode);
    return;
  }
  for (std::size_t k = 0; k < rays.size(); k += kPacket)
    capturePacket(scene, rays.data() + k, std::min<std::size_t>(kPacket, rays.size() - k), tNear, tFar, mode,
                  depth.data() + k);
}

namespace {

void fillDepthMap(const EmbreeScene& rtScene, DepthMap& map) {
  const TexelUnprojector unproject(map);
  const float tNear = float(map.nearPlane), tFar = float(map.farPlane);
  tbb::parallel_for(tbb::blocked_range<int>(0, map.height), [&](const tbb::blocked_range<int>& rows) {
    std::vector<TexelUnprojector::Ray> rays(std::size_t(map.width));
    for (int j = rows.begin(); j != rows.end(); ++j) {
      for (int i = 0; i < map.width; ++i) rays[std::size_t(i)] = unproject.ray(i, j);
      captureRays(rtScene.get(), rays, tNear, tFar, map.capture,
                  std::span<float>(map.depth).subspan(map.index(0, j), std::size_t(map.width)));
    }
  });
}

std::vector<const TriangleMesh*> meshesOf(const Scene& scene) {
  std::vector<const TriangleMesh*> meshes;
  for (const auto& o : scene.objects) meshes.push_back(&o.mesh);
  return meshes;
}

}  // namespace

DepthMap captureDepthEmbree(const Scene& scene, int width, int height, CaptureMode mode, int guard) {
  if (scene.light.type == LightType::Point)
    throw InputError(scene.source, "/light/type", "point",
                     "a point light has six depth maps, one per cube face: capture them with captureCubeEmbree");
  checkDepthMapSize(width, height, "captureDepthEmbree", "width x height", DepthMapUse::MapOnly);
  checkGuardTexels(guard, "captureDepthEmbree", "guard");
  checkGuardedDepthMapSize(width, height, guard, "captureDepthEmbree", "width x height", DepthMapUse::MapOnly);
  DepthMap map = guard == 0 ? makeDepthMap(scene.light, width, height, mode)
                            : makeDepthMap(guardedLight(scene.light, width, height, guard), width + 2 * guard,
                                           height + 2 * guard, mode);
  map.origin = scene.origin;
  map.guard = guard;
  const EmbreeDevice device;
  const EmbreeScene rtScene(device, meshesOf(scene));
  fillDepthMap(rtScene, map);
  device.throwIfError();
  return map;
}

CubeDepthMap captureCubeEmbree(const Scene& scene, int n, CaptureMode mode) {
  if (scene.light.type != LightType::Point)
    throw InputError(scene.source, "/light/type", toString(scene.light.type),
                     "a cube map is a point light's: capture a spot or directional light with captureDepthEmbree");
  CubeDepthMap cube = makeCubeDepthMap(scene.light, n, mode);
  const EmbreeDevice device;
  const EmbreeScene rtScene(device, meshesOf(scene));
  for (DepthMap& face : cube.faces) {
    face.origin = scene.origin;
    fillDepthMap(rtScene, face);
  }
  device.throwIfError();
  return cube;
}

}  // namespace shadowvol

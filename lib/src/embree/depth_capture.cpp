#include "shadowvol/embree/depth_capture.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

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

// Back capture: accept only hits on back faces (geometric normal along the ray). Embree's Ng for a
// counter-clockwise triangle points to its front side, the same convention as OpenGL.
void backFaceFilter(const RTCFilterFunctionNArguments* args) {
  if (args->valid[0] == 0) return;
  const float dx = RTCRayN_dir_x(args->ray, args->N, 0), dy = RTCRayN_dir_y(args->ray, args->N, 0),
              dz = RTCRayN_dir_z(args->ray, args->N, 0);
  const float nx = RTCHitN_Ng_x(args->hit, args->N, 0), ny = RTCHitN_Ng_y(args->hit, args->N, 0),
              nz = RTCHitN_Ng_z(args->hit, args->N, 0);
  if (!(dx * nx + dy * ny + dz * nz > 0.0f)) args->valid[0] = 0;
}

// Entry capture's first surface: reject a face that is not a back face and meets the ray at a
// cosine below kEntryGrazingCos (lit nearly edge-on, or edge-on), so the ray goes on to the back
// face behind it. In double, so the rule does not depend on the order of the products.
void enteringFaceFilter(const RTCFilterFunctionNArguments* args) {
  if (args->valid[0] == 0) return;
  const glm::dvec3 d(RTCRayN_dir_x(args->ray, args->N, 0), RTCRayN_dir_y(args->ray, args->N, 0),
                     RTCRayN_dir_z(args->ray, args->N, 0));
  const glm::dvec3 n(RTCHitN_Ng_x(args->hit, args->N, 0), RTCHitN_Ng_y(args->hit, args->N, 0),
                     RTCHitN_Ng_z(args->hit, args->N, 0));
  const double along = glm::dot(d, n);
  if (along <= 0.0 && -along < kEntryGrazingCos * glm::length(d) * glm::length(n)) args->valid[0] = 0;
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

// Which faces a ray of firstHit may stop at.
enum class Faces { Any, Back, Entering };

// One ray: the first hit in [tNear, tFar] on the faces `faces` admits.
CapturedHit firstHit(RTCScene scene, const TexelUnprojector::Ray& ray, float tNear, float tFar, Faces faces) {
  RTCRayHit rh = makeRayHit(ray.origin, ray.direction, tNear, tFar);
  CaptureContext c;
  rtcInitIntersectContext(&c.ctx);
  if (faces == Faces::Back) c.ctx.filter = backFaceFilter;
  if (faces == Faces::Entering) c.ctx.filter = enteringFaceFilter;
  rtcIntersect1(scene, &c.ctx, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {};
  return {rh.ray.tfar, rh.hit.geomID, rh.hit.primID};
}

}  // namespace

CapturedHit captureHit(RTCScene scene, const TexelUnprojector::Ray& ray, float tNear, float tFar, CaptureMode mode) {
  switch (mode) {
    case CaptureMode::Front: return firstHit(scene, ray, tNear, tFar, Faces::Any);
    case CaptureMode::Back: return firstHit(scene, ray, tNear, tFar, Faces::Back);
    case CaptureMode::Entry: {
      // The first back face, then the first surface up to it that is not lit nearly edge-on
      // (itself where nothing lies before it).
      const CapturedHit back = firstHit(scene, ray, tNear, tFar, Faces::Back);
      if (back.geomID == RTC_INVALID_GEOMETRY_ID) return {};
      const CapturedHit first = firstHit(scene, ray, tNear, back.depth, Faces::Entering);
      return first.geomID == RTC_INVALID_GEOMETRY_ID ? back : first;
    }
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

void fillDepthMap(const EmbreeScene& rtScene, DepthMap& map) {
  const TexelUnprojector unproject(map);
  const float tNear = float(map.nearPlane), tFar = float(map.farPlane);
  tbb::parallel_for(tbb::blocked_range<int>(0, map.height), [&](const tbb::blocked_range<int>& rows) {
    for (int j = rows.begin(); j != rows.end(); ++j)
      for (int i = 0; i < map.width; ++i)
        map.depth[map.index(i, j)] = captureRay(rtScene.get(), unproject.ray(i, j), tNear, tFar, map.capture);
  });
}

std::vector<const TriangleMesh*> meshesOf(const Scene& scene) {
  std::vector<const TriangleMesh*> meshes;
  for (const auto& o : scene.objects) meshes.push_back(&o.mesh);
  return meshes;
}

}  // namespace

DepthMap captureDepthEmbree(const Scene& scene, int width, int height, CaptureMode mode) {
  if (scene.light.type == LightType::Point)
    throw InputError(scene.source, "/light/type", "point",
                     "a point light has six depth maps, one per cube face: capture them with captureCubeEmbree");
  checkDepthMapSize(width, height, "captureDepthEmbree", "width x height", DepthMapUse::MapOnly);
  DepthMap map = makeDepthMap(scene.light, width, height, mode);
  map.origin = scene.origin;
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

#include "shadowvol/embree/ray_queries.h"

#include <algorithm>
#include <span>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "shadowvol/check.h"
#include "shadowvol/cube_map.h"
#include "shadowvol/depth_map.h"

namespace shadowvol {
namespace {

// The ray of pixel (x, image row r): origin at the eye, the ray parameter is the camera view depth.
TexelUnprojector::Ray pixelRay(const TexelUnprojector& u, int x, int r, int height) {
  return u.ray(x, height - 1 - r);  // GL rows count from the bottom
}

struct CollectContext {
  RTCIntersectContext ctx;
  std::vector<VolumeCrossing>* hits;
  const std::vector<const unsigned*>* indices;  // each geometry's index buffer, by geometry ID
  const std::vector<const float*>* vertices;    // and vertex buffer
};

void collectAll(const RTCFilterFunctionNArguments* args) {
  if (args->valid[0] == 0) return;
  auto* c = reinterpret_cast<CollectContext*>(const_cast<RTCIntersectContext*>(args->context));
  const float dx = RTCRayN_dir_x(args->ray, args->N, 0), dy = RTCRayN_dir_y(args->ray, args->N, 0),
              dz = RTCRayN_dir_z(args->ray, args->N, 0);
  const float nx = RTCHitN_Ng_x(args->hit, args->N, 0), ny = RTCHitN_Ng_y(args->hit, args->N, 0),
              nz = RTCHitN_Ng_z(args->hit, args->N, 0);
  const double d = double(dx) * nx + double(dy) * ny + double(dz) * nz;
  const unsigned geom = RTCHitN_geomID(args->hit, args->N, 0), prim = RTCHitN_primID(args->hit, args->N, 0);
  const unsigned* index = (*c->indices)[geom] + 3 * std::size_t(prim);
  const double u = RTCHitN_u(args->hit, args->N, 0), v = RTCHitN_v(args->hit, args->N, 0);
  const double t = RTCRayN_tfar(args->ray, args->N, 0);
  const float* xyz = (*c->vertices)[geom];
  const auto corner = [&](int k) {
    const float* p = xyz + 3 * std::size_t(index[k]);
    return glm::dvec3(p[0], p[1], p[2]);
  };
  c->hits->push_back({t, d > 0 ? 1 : (d < 0 ? -1 : 0), {index[0], index[1], index[2]},
                      onTriangleBorder(corner(0), corner(1), corner(2), u, v, t)});
  args->valid[0] = 0;  // reject: traversal goes on and reports every hit
}

// A shadow ray's context: the triangle its visible point lies on, which the ray passes through.
struct SkipContext {
  RTCIntersectContext ctx;
  unsigned geomID, primID;
};

void skipOwnTriangle(const RTCFilterFunctionNArguments* args) {
  if (args->valid[0] == 0) return;
  const auto* c = reinterpret_cast<const SkipContext*>(args->context);
  if (RTCHitN_geomID(args->hit, args->N, 0) == c->geomID && RTCHitN_primID(args->hit, args->N, 0) == c->primID)
    args->valid[0] = 0;
}

}  // namespace

CameraHits castPrimaryRays(const EmbreeScene& scene, const Camera& camera) {
  CameraHits h;
  h.width = camera.width;
  h.height = camera.height;
  const std::size_t n = std::size_t(h.width) * std::size_t(h.height);
  h.depth.assign(n, INFINITY);
  h.point.assign(n, glm::dvec3(0.0));
  h.normal.assign(n, glm::vec3(0.0f));
  h.triangle.assign(n, {RTC_INVALID_GEOMETRY_ID, RTC_INVALID_GEOMETRY_ID});
  const TexelUnprojector u(cameraView(camera), cameraProjection(camera), camera.width, camera.height);
  tbb::parallel_for(tbb::blocked_range<int>(0, h.height), [&](const tbb::blocked_range<int>& rows) {
    for (int r = rows.begin(); r != rows.end(); ++r)
      for (int x = 0; x < h.width; ++x) {
        const TexelUnprojector::Ray pr = pixelRay(u, x, r, h.height);
        RTCRayHit rh = makeRayHit(pr.origin, pr.direction, float(camera.nearPlane), float(camera.farPlane));
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        rtcIntersect1(scene.get(), &ctx, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
        const std::size_t k = std::size_t(r) * std::size_t(h.width) + std::size_t(x);
        h.depth[k] = rh.ray.tfar;
        h.point[k] = pr.origin + double(rh.ray.tfar) * pr.direction;
        h.triangle[k] = {rh.hit.geomID, rh.hit.primID};
        glm::vec3 ng(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
        const float len = glm::length(ng);
        ng = len > 0.0f ? ng / len : glm::vec3(0.0f);
        if (glm::dot(glm::dvec3(ng), pr.direction) > 0.0) ng = -ng;  // face the camera
        h.normal[k] = ng;
      }
  });
  return h;
}

std::vector<double> visibleDepths(const EmbreeScene& scene, const Camera& camera,
                                  const std::vector<std::size_t>& pixels, const std::vector<glm::dvec2>& offsets) {
  const PrimaryRays rays(camera);
  std::vector<double> out(pixels.size() * offsets.size(), INFINITY);
  for (std::size_t p = 0; p < pixels.size(); ++p) {
    const int x = int(pixels[p] % std::size_t(camera.width)), row = int(pixels[p] / std::size_t(camera.width));
    for (std::size_t o = 0; o < offsets.size(); ++o) {
      const TexelUnprojector::Ray pr = rays.ray(x, row, offsets[o].x, offsets[o].y);
      RTCRayHit rh = makeRayHit(pr.origin, pr.direction, float(camera.nearPlane), float(camera.farPlane));
      RTCIntersectContext ctx;
      rtcInitIntersectContext(&ctx);
      rtcIntersect1(scene.get(), &ctx, &rh);
      if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) out[p * offsets.size() + o] = rh.ray.tfar;
    }
  }
  return out;
}

double shadowRayOffset(const Scene& scene) { return 1e-4 * std::max(scene.bounds().radius(), 1e-9); }

double shadowRayOffsetAt(double sceneOffset, const glm::dvec3& p, double localScale) {
  const double size = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return std::max(std::min(sceneOffset, 1e-3 * localScale), std::ldexp(size + localScale, -21));
}

std::vector<PixelClass> exactShadows(const EmbreeScene& scene, const Scene& description, const CameraHits& hits,
                                     double sceneOffset, std::vector<std::uint32_t>* occluders) {
  SV_CHECK_EQ(hits.triangle.size(), hits.depth.size());  // hits from castPrimaryRays
  const Light& light = description.light;
  const bool point = light.type == LightType::Point;
  const glm::dmat4 lv = lightView(light), lp = point ? glm::dmat4(1.0) : lightProjection(light);
  const glm::dvec3 towardsLight = -glm::normalize(light.direction);
  std::vector<PixelClass> out(hits.depth.size(), PixelClass::Background);
  if (occluders) occluders->assign(out.size(), kNoOccluder);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, out.size(), 256), [&](const tbb::blocked_range<std::size_t>& b) {
    for (std::size_t k = b.begin(); k != b.end(); ++k) {
      if (hits.isBackground(k)) continue;
      const glm::dvec3 p = hits.point[k], n(hits.normal[k]);
      // Inside the light's frustum and depth range? (A point light's: between its near and far
      // cubes, cube_map.h.)
      const glm::dvec4 v = lv * glm::dvec4(p, 1.0);
      const glm::dvec4 c = lp * v;
      const double depth = point ? cubeDepth(glm::dvec3(v)) : -v.z;
      const bool inWindow = point || (c.w > 0.0 && std::abs(c.x / c.w) <= 1.0 && std::abs(c.y / c.w) <= 1.0);
      if (!inWindow || depth < light.nearPlane || depth > light.farPlane) {
        out[k] = PixelClass::OutsideLight;
        continue;
      }
      glm::dvec3 l;
      double tfar = INFINITY;
      if (light.type != LightType::Directional) {
        l = light.position - p;
        tfar = glm::length(l);
        l /= tfar;
      } else {
        l = towardsLight;
      }
      if (!(glm::dot(n, l) > 0.0)) {
        out[k] = PixelClass::FacingAway;
        continue;
      }
      const double local = std::min(glm::length(p - description.camera.eye), tfar);
      const double off = shadowRayOffsetAt(sceneOffset, p, local);
      const glm::dvec3 org = p + n * off;
      const RTCRayHit shadowRay = makeRayHit(org, l, 0.0f, float(std::isfinite(tfar) ? tfar - off : INFINITY));
      RTCRay ray = shadowRay.ray;
      SkipContext ctx{{}, hits.triangle[k].geomID, hits.triangle[k].primID};
      rtcInitIntersectContext(&ctx.ctx);
      ctx.ctx.filter = skipOwnTriangle;
      rtcOccluded1(scene.get(), &ctx.ctx, &ray);
      out[k] = ray.tfar < 0.0f ? PixelClass::Shadowed : PixelClass::Lit;  // Embree sets tfar = -inf on a hit
      if (occluders && out[k] == PixelClass::Shadowed) {  // the same ray, its nearest hit
        RTCRayHit nearest = shadowRay;
        rtcIntersect1(scene.get(), &ctx.ctx, &nearest);
        (*occluders)[k] = nearest.hit.geomID == RTC_INVALID_GEOMETRY_ID ? kNoOccluder : nearest.hit.geomID;
      }
    }
  });
  return out;
}

double tieTolerance(const Camera& camera, double d) {
  const double n = camera.nearPlane, f = camera.farPlane;
  return std::max(1e-4, 16.0 * std::ldexp(1.0, -24) * d * (f - n) / (f * n));
}

bool onTriangleBorder(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, double u, double v, double t) {
  const double area2 = glm::length(glm::cross(b - a, c - a));  // twice the area
  const double tol = kCrossingMergeTolerance * std::abs(t);
  // The distance to the edge opposite a corner: its weight times the height over that edge.
  const auto near = [&](double weight, const glm::dvec3& p, const glm::dvec3& q) {
    return weight * area2 <= tol * glm::length(q - p);
  };
  return near(1.0 - u - v, b, c) || near(u, c, a) || near(v, a, b);
}

bool VolumeCrossing::touches(const VolumeCrossing& o) const {
  if (corners == kUnknownCorners || o.corners == kUnknownCorners) return true;
  int shared = 0;
  for (const std::uint32_t a : corners)
    for (const std::uint32_t b : o.corners) shared += a == b;
  // Both on their borders: two faces that share an edge but meet the ray apart (a near cap and the
  // wall on its edge at a sharp fold, hit within the distance tolerance) are two crossings.
  return shared >= 1 && onBorder && o.onBorder;
}

namespace {

// The summed signs of a group of hits at one distance, one sum per set of hits whose triangles
// touch (VolumeCrossing::touches, joined transitively), in order of their first hit. `stack` and
// `cluster` are scratch.
void mergedSigns(std::span<const VolumeCrossing> group, std::vector<std::size_t>& stack, std::vector<int>& cluster,
                 std::vector<int>& sums) {
  const std::size_t n = group.size();
  cluster.assign(n, -1);
  sums.clear();
  for (std::size_t i = 0; i < n; ++i) {
    if (cluster[i] >= 0) continue;
    const int id = int(sums.size());
    sums.push_back(0);
    cluster[i] = id;
    stack.assign(1, i);
    while (!stack.empty()) {  // every hit that touches one of the set joins it
      const std::size_t k = stack.back();
      stack.pop_back();
      sums.back() += group[k].sign;
      for (std::size_t m = i + 1; m < n; ++m)
        if (cluster[m] < 0 && group[k].touches(group[m])) {
          cluster[m] = id;
          stack.push_back(m);
        }
    }
  }
}

}  // namespace

PixelCounts countPixel(std::vector<VolumeCrossing>& crossings, double tVisible, double band) {
  std::sort(crossings.begin(), crossings.end(), [](const VolumeCrossing& a, const VolumeCrossing& b) {
    return a.t < b.t || (a.t == b.t && a.sign < b.sign);
  });
  int zfail = 0, zpass = 0;
  std::vector<int> tieSigns;
  thread_local std::vector<std::size_t> stack;  // scratch of mergedSigns, kept between pixels
  thread_local std::vector<int> cluster, sums;
  for (std::size_t g = 0; g < crossings.size();) {
    // The hits within the tolerance of the group's first hit; each set of touching triangles among
    // them is one event (mergedSigns).
    const double t0 = crossings[g].t, tol = kCrossingMergeTolerance * std::max(t0, 1e-30);
    std::size_t e = g + 1;  // the first always (an infinite t0 compares false below)
    while (e < crossings.size() && crossings[e].t - t0 <= tol) ++e;
    mergedSigns(std::span<const VolumeCrossing>(crossings).subspan(g, e - g), stack, cluster, sums);
    for (const int sum : sums) {
      const int sign = (sum > 0) - (sum < 0);
      if (std::abs(t0 - tVisible) <= band) {
        zfail += sign;  // nominal: behind (reversed-Z GL_GREATER fails on equal depths)
        if (sign != 0) tieSigns.push_back(sign);
      } else if (t0 > tVisible) {
        zfail += sign;
      } else {
        zpass -= sign;
      }
    }
    g = e;
  }
  // Splits of the band: the first m tie events in front of the point, the rest behind.
  int tieSuffix = 0, tieMin = 0, tieMax = 0;  // suffix sums of the band's events, last to first
  for (auto it = tieSigns.rbegin(); it != tieSigns.rend(); ++it) {
    tieSuffix += *it;
    tieMin = std::min(tieMin, tieSuffix);
    tieMax = std::max(tieMax, tieSuffix);
  }
  const int base = zfail - tieSuffix;  // z-fail with every tie event in front
  return {zfail, zpass, base + tieMin, base + tieMax};
}

PrimaryRays::PrimaryRays(const Camera& camera)
    : unproject_(cameraView(camera), cameraProjection(camera), camera.width, camera.height), height_(camera.height) {}

TexelUnprojector::Ray PrimaryRays::ray(int x, int row) const { return pixelRay(unproject_, x, row, height_); }

TexelUnprojector::Ray PrimaryRays::ray(int x, int row, double dx, double dy) const {
  return unproject_.ray(double(x) + dx, double(height_ - 1 - row) + dy);  // GL rows count from the bottom
}

CrossingCounts countCrossings(const EmbreeScene& volume, const Camera& camera, const CameraHits& hits) {
  CrossingCounts out;
  out.width = hits.width;
  out.height = hits.height;
  out.zfail.assign(hits.depth.size(), 0);
  out.zpass.assign(hits.depth.size(), 0);
  out.zfailMin.assign(hits.depth.size(), 0);
  out.zfailMax.assign(hits.depth.size(), 0);
  const TexelUnprojector u(cameraView(camera), cameraProjection(camera), camera.width, camera.height);
  // The merge rule's vertex indices: a volume is one mesh (indices of two meshes would not compare).
  SV_CHECK_LE(volume.geometryCount(), 1u);
  std::vector<const unsigned*> indices;
  std::vector<const float*> vertices;
  for (unsigned g = 0; g < volume.geometryCount(); ++g) {
    RTCGeometry geom = rtcGetGeometry(volume.get(), g);
    indices.push_back(static_cast<const unsigned*>(rtcGetGeometryBufferData(geom, RTC_BUFFER_TYPE_INDEX, 0)));
    vertices.push_back(static_cast<const float*>(rtcGetGeometryBufferData(geom, RTC_BUFFER_TYPE_VERTEX, 0)));
  }
  tbb::enumerable_thread_specific<std::vector<VolumeCrossing>> buffers;
  tbb::parallel_for(tbb::blocked_range<int>(0, hits.height), [&](const tbb::blocked_range<int>& rows) {
    std::vector<VolumeCrossing>& buf = buffers.local();
    for (int r = rows.begin(); r != rows.end(); ++r)
      for (int x = 0; x < hits.width; ++x) {
        const std::size_t k = std::size_t(r) * std::size_t(hits.width) + std::size_t(x);
        if (hits.isBackground(k)) continue;
        const TexelUnprojector::Ray pr = pixelRay(u, x, r, hits.height);
        buf.clear();
        RTCRayHit rh = makeRayHit(pr.origin, pr.direction, 0.0f, INFINITY);
        CollectContext c;
        rtcInitIntersectContext(&c.ctx);
        c.ctx.filter = collectAll;
        c.hits = &buf;
        c.indices = &indices;
        c.vertices = &vertices;
        rtcIntersect1(volume.get(), &c.ctx, &rh);
        const PixelCounts pc = countPixel(buf, hits.depth[k], tieTolerance(camera, hits.depth[k]) * hits.depth[k]);
        out.zfail[k] = pc.zfail;
        out.zpass[k] = pc.zpass;
        out.zfailMin[k] = pc.zfailMin;
        out.zfailMax[k] = pc.zfailMax;
      }
  });
  return out;
}

}  // namespace shadowvol

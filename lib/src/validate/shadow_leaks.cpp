#include "shadowvol/validate/shadow_leaks.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "shadowvol/boundary_edges.h"
#include "shadowvol/check.h"
#include "shadowvol/cube_map.h"
#include "shadowvol/distance_transform.h"

namespace shadowvol {
namespace {

// The pixels that count as a shadow's outline (see the header): not exactly shadowed, on the
// image's border, or beside a jump in the camera's view.
std::vector<std::uint8_t> outlineSites(const CameraHits& hits, const std::vector<PixelClass>& exact) {
  const int w = hits.width, h = hits.height;
  std::vector<std::uint8_t> site(exact.size(), 0);
  const auto jump = [&](std::size_t a, std::size_t b) {
    if (hits.isBackground(a) || hits.isBackground(b)) return true;
    if (hits.triangle[a].geomID != hits.triangle[b].geomID) return true;
    const double da = hits.depth[a], db = hits.depth[b];
    return std::abs(da - db) > kLeakDepthJump * std::min(da, db);
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t k = std::size_t(y) * std::size_t(w) + std::size_t(x);
      if (exact[k] != PixelClass::Shadowed || x == 0 || y == 0 || x == w - 1 || y == h - 1) {
        site[k] = 1;
        continue;
      }
      site[k] = jump(k, k - 1) || jump(k, k + 1) || jump(k, k - std::size_t(w)) || jump(k, k + std::size_t(w));
    }
  return site;
}

// The light's texel width at surface point p (world units, across the light's rays), 0 for an
// exact method.
double texelWidthAt(const Light& light, const LeakTexels& texels, const TexelFootprint& footprint,
                    const glm::dvec3& p) {
  if (texels.map) return footprint.at(texels.map->viewDepthOf(p));
  if (texels.cubeSide > 0) return 2.0 * cubeDepth(p - light.position) / double(texels.cubeSide);
  return 0.0;
}

// How far along the surface at p (unit normal n) the method's shadow may stray from the exact one:
// its texels' reach plus its depth offset's (see the header).
double alongSurfaceReach(const Light& light, const LeakTexels& texels, const TexelFootprint& footprint,
                         const glm::dvec3& p, const glm::dvec3& n) {
  const double width = texelWidthAt(light, texels, footprint, p);
  const glm::dvec3 toLight = light.type == LightType::Directional ? -light.direction : light.position - p;
  const double toLightLength = glm::length(toLight);
  const double cosine = toLightLength > 0.0 ? std::abs(glm::dot(n, toLight / toLightLength)) : 1.0;
  // The light's view axis: a spot or directional light's direction, a point light's cube face.
  const glm::dvec3 axis = light.type == LightType::Point
                             ? cubeFaceDirection(cubeLookup(p - light.position, std::max(texels.cubeSide, 1)).face)
                             : light.direction;
  const double cosAxis = std::min(std::abs(glm::dot(n, glm::normalize(axis))), 1.0);
  const double sinAxis = std::sqrt(1.0 - cosAxis * cosAxis);
  const double tanAxis = std::min(sinAxis / std::max(cosAxis, 1e-4), 10.0);  // scene.frag's clamp
  const double offset = texels.offset + texels.slope * width * tanAxis;
  return kLeakTexels * width / std::max(cosine, kLeakMinCos) + offset / std::max(sinAxis, kLeakMinCos);
}

}  // namespace

ShadowLeaks findShadowLeaks(const Scene& scene, const LeakTexels& texels, const CameraHits& hits,
                            const std::vector<PixelClass>& exact, const std::vector<std::uint8_t>& methodShadowed) {
  const std::size_t n = std::size_t(hits.width) * std::size_t(hits.height);
  SV_CHECK_EQ(exact.size(), n);
  SV_CHECK_EQ(methodShadowed.size(), n);
  ShadowLeaks leaks;
  std::vector<std::size_t> missed;
  for (std::size_t k = 0; k < n; ++k)
    if (exact[k] == PixelClass::Shadowed && !methodShadowed[k]) missed.push_back(k);
  if (missed.empty()) return leaks;
  const std::vector<double> toOutline = squaredDistanceTransform(hits.width, hits.height, outlineSites(hits, exact));
  const Light& light = scene.light;
  const TexelFootprint footprint = texels.map ? TexelFootprint::of(*texels.map) : TexelFootprint{};
  // An image pixel's width per unit of camera depth, on the image's axis.
  const double pixelPerDepth = 2.0 * std::tan(0.5 * glm::radians(scene.camera.fovYDegrees)) / scene.camera.height;
  for (std::size_t k : missed) {
    const glm::dvec3 p = hits.point[k], n = glm::dvec3(hits.normal[k]);
    const double along = alongSurfaceReach(light, texels, footprint, p, n);
    // The width of an image pixel at p, across the ray: off the image's axis the ray meets the
    // image plane obliquely and a pixel covers less (z / r of it, at distance r).
    const double z = double(hits.depth[k]), r = glm::length(p - scene.camera.eye);
    const double allowance = along / (pixelPerDepth * z * z / r) + kLeakPixels;
    const double distance = std::sqrt(toOutline[k]) - 0.5;  // from the outline pixel's edge
    if (!(distance > allowance)) continue;
    ++leaks.deep;
    if (leaks.firstDeep.size() < 16) leaks.firstDeep.push_back(k);
  }
  return leaks;
}

}  // namespace shadowvol

#include "shadowvol/validate/image_plane_surfaces.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "shadowvol/embree/ray_queries.h"

namespace shadowvol {
namespace {

// Distance in the image plane from point p to triangle (a, b, c): 0 inside (either winding).
double distanceToTriangle(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
  const auto cross = [](glm::dvec2 u, glm::dvec2 v) { return u.x * v.y - u.y * v.x; };
  const double d0 = cross(b - a, p - a), d1 = cross(c - b, p - b), d2 = cross(a - c, p - c);
  if ((d0 >= 0.0 && d1 >= 0.0 && d2 >= 0.0) || (d0 <= 0.0 && d1 <= 0.0 && d2 <= 0.0)) return 0.0;
  const auto segment = [&](glm::dvec2 u, glm::dvec2 v) {
    const glm::dvec2 e = v - u;
    const double len2 = glm::dot(e, e);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - u, e) / len2, 0.0, 1.0) : 0.0;
    return glm::length(u + t * e - p);
  };
  return std::min({segment(a, b), segment(b, c), segment(c, a)});
}

}  // namespace

std::vector<std::vector<double>> surfaceDepthsNearPixels(const std::vector<const TriangleMesh*>& meshes,
                                                         const Camera& camera, const std::vector<std::size_t>& pixels,
                                                         double radius) {
  std::vector<std::vector<double>> out(pixels.size());
  if (pixels.empty()) return out;
  const int w = camera.width, h = camera.height;
  std::unordered_map<std::size_t, std::size_t> slot;  // pixel index -> its place in `pixels`
  for (std::size_t p = 0; p < pixels.size(); ++p) slot.emplace(pixels[p], p);
  const glm::dmat4 toClip = cameraProjection(camera) * cameraView(camera);
  const PrimaryRays rays(camera);
  for (const TriangleMesh* mesh : meshes) {
    for (const auto& t : mesh->triangles) {
      glm::dvec3 world[3];
      glm::dvec2 image[3];
      bool behind = false;
      for (int v = 0; v < 3; ++v) {
        world[v] = glm::dvec3(mesh->positions[t[v]]);
        const glm::dvec4 c = toClip * glm::dvec4(world[v], 1.0);
        if (!(c.w > 0.0)) behind = true;
        image[v] = {(c.x / c.w + 1.0) * 0.5 * w, (1.0 - c.y / c.w) * 0.5 * h};  // rows from the top
      }
      if (behind) continue;
      const glm::dvec2 lo = glm::min(glm::min(image[0], image[1]), image[2]) - radius,
                       hi = glm::max(glm::max(image[0], image[1]), image[2]) + radius;
      // Pixel centres (x + 0.5, row + 0.5) inside [lo, hi]; a large triangle visits the listed
      // pixels instead of its box.
      const int x0 = int(std::max(0.0, std::ceil(lo.x - 0.5))), x1 = int(std::min(w - 1.0, std::floor(hi.x - 0.5)));
      const int r0 = int(std::max(0.0, std::ceil(lo.y - 0.5))), r1 = int(std::min(h - 1.0, std::floor(hi.y - 0.5)));
      if (x0 > x1 || r0 > r1) continue;
      const glm::dvec3 n = glm::cross(world[1] - world[0], world[2] - world[0]);
      auto visit = [&](std::size_t k, std::size_t p) {
        const int x = int(k % std::size_t(w)), row = int(k / std::size_t(w));
        if (x < x0 || x > x1 || row < r0 || row > r1) return;
        if (distanceToTriangle({x + 0.5, row + 0.5}, image[0], image[1], image[2]) > radius) return;
        const TexelUnprojector::Ray ray = rays.ray(x, row);
        const double along = glm::dot(n, ray.direction);
        if (along == 0.0) return;  // edge-on: no depth on this ray
        const double depth = glm::dot(n, world[0] - ray.origin) / along;
        if (depth > 0.0) out[p].push_back(depth);
      };
      if (std::size_t(x1 - x0 + 1) * std::size_t(r1 - r0 + 1) <= pixels.size()) {
        for (int row = r0; row <= r1; ++row)
          for (int x = x0; x <= x1; ++x)
            if (const auto it = slot.find(std::size_t(row) * std::size_t(w) + std::size_t(x)); it != slot.end())
              visit(it->first, it->second);
      } else {
        for (std::size_t p = 0; p < pixels.size(); ++p) visit(pixels[p], p);
      }
    }
  }
  return out;
}

}  // namespace shadowvol

#include "shadowvol/validate/double_recount.h"

#include <cmath>
#include <iterator>
#include <vector>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <glm/geometric.hpp>

namespace shadowvol {
namespace {

using K = CGAL::Simple_cartesian<double>;
using Triangles = std::vector<K::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

glm::dvec3 toGlm(const K::Point_3& p) { return {p.x(), p.y(), p.z()}; }

// Ray parameter and sign of the ray's crossing with triangle t (double Moeller-Trumbore, edges
// included). The AABB tree reported an intersection, so only the parameter is computed here.
bool crossing(const K::Triangle_3& t, const glm::dvec3& o, const glm::dvec3& d, VolumeCrossing& out) {
  const glm::dvec3 a = toGlm(t[0]), e1 = toGlm(t[1]) - a, e2 = toGlm(t[2]) - a;
  const glm::dvec3 n = glm::cross(e1, e2);
  const double denom = glm::dot(n, d);
  if (denom == 0.0) return false;  // edge-on: counts 0, as in countCrossings
  out.t = glm::dot(n, a - o) / denom;
  out.sign = denom > 0.0 ? 1 : -1;
  return out.t >= 0.0;
}

}  // namespace

std::size_t recountInconsistentPixels(const VolumeMesh& volume, const Camera& camera, const CameraHits& hits,
                                      int expectedNet, CrossingCounts& counts) {
  std::vector<std::size_t> pixels;
  for (std::size_t k = 0; k < hits.depth.size(); ++k)
    if (!hits.isBackground(k) && counts.zfail[k] - counts.zpass[k] != expectedNet) pixels.push_back(k);
  if (pixels.empty() || volume.triangleCount() == 0) return 0;

  Triangles triangles;
  triangles.reserve(volume.triangleCount());
  auto point = [&](std::uint32_t i) {
    const glm::dvec3& p = volume.positions[i];
    return K::Point_3(p.x, p.y, p.z);
  };
  for (const auto& t : volume.triangles) triangles.emplace_back(point(t[0]), point(t[1]), point(t[2]));
  const Tree tree(triangles.begin(), triangles.end());
  std::vector<Primitive::Id> hit;
  std::vector<VolumeCrossing> crossings;
  const PrimaryRays rays(camera);
  for (std::size_t k : pixels) {
    const int x = int(k % std::size_t(hits.width)), row = int(k / std::size_t(hits.width));
    const TexelUnprojector::Ray r = rays.ray(x, row);
    const K::Ray_3 ray(K::Point_3(r.origin.x, r.origin.y, r.origin.z),
                       K::Vector_3(r.direction.x, r.direction.y, r.direction.z));
    hit.clear();
    tree.all_intersected_primitives(ray, std::back_inserter(hit));
    crossings.clear();
    VolumeCrossing c;
    for (const auto& id : hit)
      if (!triangles.empty() && crossing(*id, r.origin, r.direction, c)) crossings.push_back(c);
    const double tVisible = hits.depth[k];
    const PixelCounts pc = countPixel(crossings, tVisible, tieTolerance(camera, tVisible) * tVisible);
    counts.zfail[k] = pc.zfail;
    counts.zpass[k] = pc.zpass;
    counts.zfailMin[k] = pc.zfailMin;
    counts.zfailMax[k] = pc.zfailMax;
  }
  return pixels.size();
}

}  // namespace shadowvol

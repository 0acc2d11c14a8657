#include "shadowvol/validate/double_recount.h"

#include <algorithm>
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

// The volume's triangles in double in an AABB tree, counting any camera ray by countPixel.
class DoubleCounter {
 public:
  explicit DoubleCounter(const VolumeMesh& volume) {
    triangles_.reserve(volume.triangleCount());
    auto point = [&](std::uint32_t i) {
      const glm::dvec3& p = volume.positions[i];
      return K::Point_3(p.x, p.y, p.z);
    };
    for (const auto& t : volume.triangles) triangles_.emplace_back(point(t[0]), point(t[1]), point(t[2]));
    tree_.insert(triangles_.begin(), triangles_.end());
    tree_.build();
  }

  PixelCounts count(const TexelUnprojector::Ray& r, const Camera& camera, double tVisible) {
    const K::Ray_3 ray(K::Point_3(r.origin.x, r.origin.y, r.origin.z),
                       K::Vector_3(r.direction.x, r.direction.y, r.direction.z));
    hit_.clear();
    tree_.all_intersected_primitives(ray, std::back_inserter(hit_));
    crossings_.clear();
    VolumeCrossing c;
    for (const auto& id : hit_)
      if (crossing(*id, r.origin, r.direction, c)) crossings_.push_back(c);
    return countPixel(crossings_, tVisible, tieTolerance(camera, tVisible) * tVisible);
  }

 private:
  Triangles triangles_;
  Tree tree_;
  std::vector<Primitive::Id> hit_;
  std::vector<VolumeCrossing> crossings_;
};

}  // namespace

std::size_t recountInconsistentPixels(const VolumeMesh& volume, const Camera& camera, const CameraHits& hits,
                                      int expectedNet, CrossingCounts& counts) {
  std::vector<std::size_t> pixels;
  for (std::size_t k = 0; k < hits.depth.size(); ++k)
    if (!hits.isBackground(k) && counts.zfail[k] - counts.zpass[k] != expectedNet) pixels.push_back(k);
  if (pixels.empty() || volume.triangleCount() == 0) return 0;

  DoubleCounter counter(volume);
  const PrimaryRays rays(camera);
  for (std::size_t k : pixels) {
    const int x = int(k % std::size_t(hits.width)), row = int(k / std::size_t(hits.width));
    const PixelCounts pc = counter.count(rays.ray(x, row), camera, hits.depth[k]);
    counts.zfail[k] = pc.zfail;
    counts.zpass[k] = pc.zpass;
    counts.zfailMin[k] = pc.zfailMin;
    counts.zfailMax[k] = pc.zfailMax;
  }
  return pixels.size();
}

std::size_t widenImagePlaneTies(const VolumeMesh& volume, const Camera& camera, const CameraHits& hits,
                                const std::vector<std::size_t>& pixels, CrossingCounts& counts) {
  if (pixels.empty() || volume.triangleCount() == 0) return 0;
  DoubleCounter counter(volume);
  const PrimaryRays rays(camera);
  std::size_t widened = 0;
  for (std::size_t k : pixels) {
    if (hits.isBackground(k)) continue;
    const int x = int(k % std::size_t(hits.width)), row = int(k / std::size_t(hits.width));
    int lo = counts.zfailMin[k], hi = counts.zfailMax[k];
    for (double dx : {-kImagePlaneTie, kImagePlaneTie})
      for (double dy : {-kImagePlaneTie, kImagePlaneTie}) {
        const PixelCounts pc = counter.count(rays.ray(x, row, dx, dy), camera, hits.depth[k]);
        lo = std::min(lo, pc.zfailMin);
        hi = std::max(hi, pc.zfailMax);
      }
    widened += lo < counts.zfailMin[k] || hi > counts.zfailMax[k];
    counts.zfailMin[k] = lo;
    counts.zfailMax[k] = hi;
  }
  return widened;
}

}  // namespace shadowvol

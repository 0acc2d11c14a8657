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

#include "shadowvol/check.h"

namespace shadowvol {
namespace {

using K = CGAL::Simple_cartesian<double>;
using Triangles = std::vector<K::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

glm::dvec3 toGlm(const K::Point_3& p) { return {p.x(), p.y(), p.z()}; }

// Ray parameter and sign of the ray's crossing with the plane of triangle t (the AABB tree
// reported that the ray meets the triangle, edges included, so only the parameter is computed
// here). The ray (o, d) may be another than the one that met the triangle: the pixel centre's,
// where a rasteriser interpolates the depth of a triangle it covers from a nearby edge.
bool crossing(const K::Triangle_3& t, const glm::dvec3& o, const glm::dvec3& d, VolumeCrossing& out) {
  const glm::dvec3 a = toGlm(t[0]), e1 = toGlm(t[1]) - a, e2 = toGlm(t[2]) - a;
  const glm::dvec3 n = glm::cross(e1, e2);
  const double denom = glm::dot(n, d);
  if (denom == 0.0) return false;  // edge-on: counts 0, as in countCrossings
  out.t = glm::dot(n, a - o) / denom;
  out.sign = denom > 0.0 ? 1 : -1;
  return out.t >= 0.0;
}

// The triangles of `volume` whose projection may cover one of `pixels` (rows top first) of the
// camera's image: each triangle's pixel bounding box, grown by two pixels, against a summed-area
// table of the pixels; a triangle with a vertex at or behind the eye plane is always kept. So the
// tree below holds what a few pixels' rays can meet, not a whole 2048^2 volume.
std::vector<std::size_t> trianglesNear(const VolumeMesh& volume, const Camera& camera,
                                       const std::vector<std::size_t>& pixels) {
  const int w = camera.width, h = camera.height;
  std::vector<std::uint32_t> sat(std::size_t(w + 1) * std::size_t(h + 1), 0);  // sat[(r + 1)(w + 1) + c + 1]
  auto at = [w](int row, int col) { return std::size_t(row) * std::size_t(w + 1) + std::size_t(col); };
  for (std::size_t k : pixels) sat[at(int(k / std::size_t(w)) + 1, int(k % std::size_t(w)) + 1)] = 1;
  for (int r = 1; r <= h; ++r)
    for (int c = 1; c <= w; ++c) sat[at(r, c)] += sat[at(r - 1, c)] + sat[at(r, c - 1)] - sat[at(r - 1, c - 1)];
  const glm::dmat4 toClip = cameraProjection(camera) * cameraView(camera);
  std::vector<std::size_t> out;
  for (std::size_t t = 0; t < volume.triangles.size(); ++t) {
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    bool behind = false;
    for (std::uint32_t i : volume.triangles[t]) {
      const glm::dvec4 c = toClip * glm::dvec4(volume.positions[i], 1.0);
      if (!(c.w > 0.0)) {
        behind = true;
        break;
      }
      const double x = (c.x / c.w + 1.0) * 0.5 * w, y = (1.0 - c.y / c.w) * 0.5 * h;  // y: rows from the top
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    if (!behind) {
      // The box's pixels [c0, c1) x [r0, r1), grown by two pixels each way, clamped to the image.
      auto grown = [](double v, double by, int size) { return int(std::clamp(std::floor(v) + by, 0.0, double(size))); };
      const int c0 = grown(x0, -2.0, w), c1 = grown(x1, 3.0, w), r0 = grown(y0, -2.0, h), r1 = grown(y1, 3.0, h);
      if (c0 >= c1 || r0 >= r1 || sat[at(r1, c1)] - sat[at(r0, c1)] - sat[at(r1, c0)] + sat[at(r0, c0)] == 0) continue;
    }
    out.push_back(t);
  }
  return out;
}

// Triangles of the volume in double in an AABB tree, counting any camera ray by countPixel.
class DoubleCounter {
 public:
  DoubleCounter(const VolumeMesh& volume, const std::vector<std::size_t>& which) {
    triangles_.reserve(which.size());
    auto point = [&](std::uint32_t i) {
      const glm::dvec3& p = volume.positions[i];
      return K::Point_3(p.x, p.y, p.z);
    };
    for (std::size_t k : which) {
      const auto& t = volume.triangles[k];
      triangles_.emplace_back(point(t[0]), point(t[1]), point(t[2]));
    }
    tree_.insert(triangles_.begin(), triangles_.end());
    tree_.build();
  }

  /// The counts of the triangles ray `r` meets, each at its depth along `depth` (its plane's
  /// crossing with that ray: the pixel centre's, for a ray beside it) or along `r` itself.
  PixelCounts count(const TexelUnprojector::Ray& r, const Camera& camera, double tVisible,
                    const TexelUnprojector::Ray* depth = nullptr) {
    crossings_.clear();
    const double band = tieTolerance(camera, tVisible) * tVisible;
    if (triangles_.empty()) return countPixel(crossings_, tVisible, band);  // no triangle near the pixels
    const K::Ray_3 ray(K::Point_3(r.origin.x, r.origin.y, r.origin.z),
                       K::Vector_3(r.direction.x, r.direction.y, r.direction.z));
    hit_.clear();
    tree_.all_intersected_primitives(ray, std::back_inserter(hit_));
    const TexelUnprojector::Ray& along = depth ? *depth : r;
    VolumeCrossing c;
    for (const auto& id : hit_)
      if (crossing(*id, along.origin, along.direction, c)) crossings_.push_back(c);
    return countPixel(crossings_, tVisible, band);
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

  DoubleCounter counter(volume, trianglesNear(volume, camera, pixels));
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

std::vector<glm::dvec2> imagePlaneTieCorners() {
  std::vector<glm::dvec2> corners;
  for (double dx : {-kImagePlaneTie, kImagePlaneTie})
    for (double dy : {-kImagePlaneTie, kImagePlaneTie}) corners.emplace_back(dx, dy);
  return corners;
}

std::size_t widenImagePlaneTies(const VolumeMesh& volume, const Camera& camera, const CameraHits& hits,
                                const std::vector<std::size_t>& pixels, CrossingCounts& counts,
                                const std::vector<double>& cornerDepths) {
  if (pixels.empty() || volume.triangleCount() == 0) return 0;
  const std::vector<glm::dvec2> corners = imagePlaneTieCorners();
  SV_CHECK(cornerDepths.empty() || cornerDepths.size() == corners.size() * pixels.size());
  DoubleCounter counter(volume, trianglesNear(volume, camera, pixels));
  const PrimaryRays rays(camera);
  std::size_t widened = 0;
  std::vector<double> depths;
  for (std::size_t p = 0; p < pixels.size(); ++p) {
    const std::size_t k = pixels[p];
    if (hits.isBackground(k)) continue;
    const int x = int(k % std::size_t(hits.width)), row = int(k / std::size_t(hits.width));
    // The depths to split at: the pixel's own, and each other surface a corner sees.
    const double own = hits.depth[k];
    depths.assign(1, own);
    for (std::size_t c = 0; c < (cornerDepths.empty() ? 0 : corners.size()); ++c) {
      const double d = cornerDepths[p * corners.size() + c];
      if (d < INFINITY && std::abs(d - own) > tieTolerance(camera, own) * own) depths.push_back(d);
    }
    int lo = counts.zfailMin[k], hi = counts.zfailMax[k];
    const TexelUnprojector::Ray centre = rays.ray(x, row);
    auto admit = [&](const TexelUnprojector::Ray& ray, double depth, const TexelUnprojector::Ray* along) {
      const PixelCounts pc = counter.count(ray, camera, depth, along);
      lo = std::min(lo, pc.zfailMin);
      hi = std::max(hi, pc.zfailMax);
    };
    // A corner's triangles at their depths along the corner's ray, and along the centre's: the
    // rasteriser that covers the pixel from a snapped edge takes the triangle's depth at the
    // centre (two triangles of a fold, tied in depth on their shared edge there, part a few
    // thousandths of a pixel inside it).
    for (const glm::dvec2& c : corners) {
      const TexelUnprojector::Ray corner = rays.ray(x, row, c.x, c.y);
      for (double d : depths) {
        admit(corner, d, nullptr);
        admit(corner, d, &centre);
      }
    }
    for (std::size_t d = 1; d < depths.size(); ++d) admit(centre, depths[d], nullptr);
    widened += lo < counts.zfailMin[k] || hi > counts.zfailMax[k];
    counts.zfailMin[k] = lo;
    counts.zfailMax[k] = hi;
  }
  return widened;
}

}  // namespace shadowvol

#include "shadowvol/validate/double_recount.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <tuple>
#include <unordered_map>
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
  // Barycentric coordinates of the plane's point, for the merge rule's border test.
  const glm::dvec3 p = o + out.t * d - a;
  const double n2 = glm::dot(n, n);
  const double u = glm::dot(glm::cross(p, e2), n) / n2, v = glm::dot(glm::cross(e1, p), n) / n2;
  out.onBorder = onTriangleBorder(a, a + e1, a + e2, u, v, out.t);
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
      corners_.push_back(t);
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
      if (crossing(*id, along.origin, along.direction, c)) {
        c.corners = corners_[std::size_t(id - triangles_.begin())];  // the merge rule's vertex indices
        crossings_.push_back(c);
      }
    return countPixel(crossings_, tVisible, band);
  }

 private:
  Triangles triangles_;
  std::vector<std::array<std::uint32_t, 3>> corners_;  // triangles_[k]'s vertex indices
  Tree tree_;
  std::vector<Primitive::Id> hit_;
  std::vector<VolumeCrossing> crossings_;
};

// A triangle's projection onto the camera's image (pixels, rows from the top): the part in front
// of the eye (clipped at a small positive clip w, as a rasteriser with depth clamp draws it), a
// convex polygon of up to four points; empty when the triangle lies wholly behind the eye.
struct ImagePolygon {
  glm::dvec2 p[4];
  double w[4] = {0.0, 0.0, 0.0, 0.0};  // clip w of each point: the camera view depth
  int n = 0;
  bool clipped = false;                                                 // a vertex lay behind the eye
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;  // its bounding box
};

ImagePolygon projectTriangle(const glm::dmat4& toClip, const VolumeMesh& volume, std::size_t t, int w, int h) {
  constexpr double kMinW = 1e-9;
  glm::dvec4 c[3];
  for (int k = 0; k < 3; ++k) c[k] = toClip * glm::dvec4(volume.positions[volume.triangles[t][std::size_t(k)]], 1.0);
  ImagePolygon out;
  auto add = [&](const glm::dvec4& v) {
    const glm::dvec2 q((v.x / v.w + 1.0) * 0.5 * w, (1.0 - v.y / v.w) * 0.5 * h);
    out.w[out.n] = v.w;
    out.p[out.n++] = q;
    out.x0 = std::min(out.x0, q.x), out.x1 = std::max(out.x1, q.x);
    out.y0 = std::min(out.y0, q.y), out.y1 = std::max(out.y1, q.y);
  };
  for (int k = 0; k < 3; ++k) {  // Sutherland-Hodgman against w = kMinW
    const glm::dvec4 &a = c[k], &b = c[(k + 1) % 3];
    const bool aIn = a.w > kMinW, bIn = b.w > kMinW;
    if (aIn) add(a);
    if (aIn != bIn) add(a + (b - a) * ((kMinW - a.w) / (b.w - a.w)));
    out.clipped = out.clipped || !aIn;
  }
  return out;
}

double cross2(const glm::dvec2& a, const glm::dvec2& b) {
  return a.x * b.y - a.y * b.x;
}

// How a projected polygon lies against the square of image-plane ties around `centre`: apart,
// overlapping it, or holding all of it (strictly; a polygon of no area never holds it).
enum class SquareCover { Apart, Overlaps, Holds };

SquareCover coverOfSquare(const ImagePolygon& poly, const glm::dvec2& centre) {
  const double r = kImagePlaneTie;
  if (poly.n < 3 || poly.x1 < centre.x - r || poly.x0 > centre.x + r || poly.y1 < centre.y - r ||
      poly.y0 > centre.y + r)
    return SquareCover::Apart;
  double area = 0.0;
  for (int k = 0; k < poly.n; ++k) area += cross2(poly.p[k], poly.p[(k + 1) % poly.n]);
  const double orient = area > 0.0 ? 1.0 : -1.0;
  bool holds = area != 0.0;
  for (int k = 0; k < poly.n; ++k) {  // separating axes: the polygon's edges (the box's are above)
    const glm::dvec2 a = poly.p[k], e = poly.p[(k + 1) % poly.n] - a;
    const double reach = r * (std::abs(e.x) + std::abs(e.y));  // the square's half-extent along e's normal
    const double side = orient * cross2(e, centre - a);        // > 0: the centre on the inner side
    if (side < -reach) return SquareCover::Apart;
    holds = holds && side > reach;
  }
  return holds ? SquareCover::Holds : SquareCover::Overlaps;
}

// Whether a rasteriser could turn the polygon over: its vertices snapped by up to a sub-pixel step
// (kImagePlaneTie covers two), a sliver whose height is within that could change its winding.
bool mayFlip(const ImagePolygon& poly) {
  double area2 = 0.0, longest = 0.0;
  for (int k = 0; k < poly.n; ++k) {
    area2 += cross2(poly.p[k], poly.p[(k + 1) % poly.n]);
    longest = std::max(longest, glm::length(poly.p[(k + 1) % poly.n] - poly.p[k]));
  }
  return std::abs(area2) <= 2.0 * kImagePlaneTie * longest;  // twice the area over the base: the height
}

// The view depths a rasteriser may give an unclipped projected triangle at image point q: 1 / depth
// is affine in the image, evaluated with each vertex moved by up to kImagePlaneTie pixels along
// each axis (its snap and the float transform), the extremes of 64 such moves. A sliver's depth
// gradient across it is ill-conditioned, so its range is wide where a small move tilts its plane.
// (kAnyDepth stands for "any depth behind", finite so that countPixel can sort and merge it.)
constexpr double kAnyDepth = std::numeric_limits<double>::max();

std::pair<double, double> depthRangeAt(const ImagePolygon& poly, const glm::dvec2& q) {
  double lo = INFINITY, hi = -INFINITY;
  const double r = kImagePlaneTie;
  for (int m = 0; m < 64; ++m) {
    glm::dvec2 v[3];
    for (int k = 0; k < 3; ++k)
      v[k] = poly.p[k] + glm::dvec2((m >> (2 * k) & 1) ? r : -r, (m >> (2 * k + 1) & 1) ? r : -r);
    const double area = cross2(v[1] - v[0], v[2] - v[0]);
    if (area == 0.0) continue;
    const double l1 = cross2(q - v[0], v[2] - v[0]) / area;
    const double l2 = cross2(v[1] - v[0], q - v[0]) / area;
    const double l0 = 1.0 - l1 - l2;
    const double inv = l0 / poly.w[0] + l1 / poly.w[1] + l2 / poly.w[2];
    if (!(inv > 0.0)) return {0.0, kAnyDepth};  // the plane passes the eye near q: any depth
    const double d = 1.0 / inv;
    lo = std::min(lo, d), hi = std::max(hi, d);
  }
  if (!(lo <= hi)) return {0.0, kAnyDepth};
  return {lo, hi};
}

// The admissible z-fail range of a pixel from every volume triangle whose projection meets the
// square of image-plane ties around its centre, however small: one that holds the whole square is
// drawn at the pixel, one that only overlaps it may be drawn or not, and a sliver may be drawn
// turned over; each is counted at any depth its snapped plane may have at the centre (where the
// rasteriser evaluates it: depthRangeAt; a clipped one at its plane's depth there), an edge-on one
// at the pixel's own depth (a tie). The corners' rays miss a triangle smaller than the square (a
// sub-grid's wall at a large map), which this does not.
struct SquareRange {
  int lo = 0, hi = 0;
};

SquareRange squareRange(const std::vector<const ImagePolygon*>& polys, const std::vector<std::size_t>& ids,
                        const VolumeMesh& volume, const TexelUnprojector::Ray& centreRay, const glm::dvec2& centre,
                        double tVisible, double band) {
  std::vector<VolumeCrossing> low, high;
  for (std::size_t k = 0; k < polys.size(); ++k) {
    const ImagePolygon& poly = *polys[k];
    const SquareCover cover = coverOfSquare(poly, centre);
    if (cover == SquareCover::Apart) continue;
    const auto& tri = volume.triangles[ids[k]];
    const glm::dvec3 a = volume.positions[tri[0]];
    const glm::dvec3 n = glm::cross(volume.positions[tri[1]] - a, volume.positions[tri[2]] - a);
    const double denom = glm::dot(n, centreRay.direction);
    // The depths it may have at the centre: its plane's there (a clipped one), else the range of
    // its snapped planes (depthRangeAt); an edge-on one: a tie with the pixel's own depth.
    double t0 = tVisible, t1 = tVisible;
    if (denom != 0.0 && poly.clipped)
      t0 = t1 = glm::dot(n, a - centreRay.origin) / denom;
    else if (denom != 0.0)
      std::tie(t0, t1) = depthRangeAt(poly, centre);
    if (!(t1 >= 0.0)) continue;  // behind the eye
    const int sign = denom > 0.0 ? 1 : -1;
    const bool flips = denom == 0.0 || mayFlip(poly);
    // Its contribution is lowest as a -1 at its farthest depth or a +1 at its nearest (or not
    // drawn, unless it holds the square), highest the other way round.
    if (cover == SquareCover::Holds && !flips) {
      low.push_back({sign < 0 ? t1 : t0, sign, tri});
      high.push_back({sign > 0 ? t1 : t0, sign, tri});
      continue;
    }
    if (sign < 0 || flips) low.push_back({t1, -1, tri});
    if (sign > 0 || flips) high.push_back({t1, 1, tri});
  }
  return {countPixel(low, tVisible, band).zfailMin, countPixel(high, tVisible, band).zfailMax};
}

// The projected polygons of the triangles near each of a few pixels (widenImagePlaneTies): each
// triangle of `near` projected once, listed for every pixel whose square of ties its bounding box
// reaches.
class PolygonsNear {
 public:
  PolygonsNear(const VolumeMesh& volume, const Camera& camera, const std::vector<std::size_t>& near,
               const std::vector<std::size_t>& pixels)
      : of_(pixels.size()), ids_(pixels.size()) {
    const int w = camera.width, h = camera.height;
    const glm::dmat4 toClip = cameraProjection(camera) * cameraView(camera);
    std::unordered_map<std::size_t, std::size_t> slot;  // pixel index -> position in `pixels`
    for (std::size_t p = 0; p < pixels.size(); ++p) slot.emplace(pixels[p], p);
    polygons_.reserve(near.size());
    for (std::size_t t : near) polygons_.push_back(projectTriangle(toClip, volume, t, w, h));
    const double r = kImagePlaneTie;
    for (std::size_t k = 0; k < near.size(); ++k) {
      const ImagePolygon& poly = polygons_[k];
      if (poly.n < 3) continue;
      auto list = [&](std::size_t p) {
        of_[p].push_back(&polygons_[k]);
        ids_[p].push_back(near[k]);
      };
      // Pixel centres (x + 0.5, row + 0.5) within r of the box.
      const double cx0 = std::max(0.0, std::ceil(poly.x0 - r - 0.5)),
                   cx1 = std::min(w - 1.0, std::floor(poly.x1 + r - 0.5));
      const double cy0 = std::max(0.0, std::ceil(poly.y0 - r - 0.5)),
                   cy1 = std::min(h - 1.0, std::floor(poly.y1 + r - 0.5));
      if (cx0 > cx1 || cy0 > cy1) continue;
      if ((cx1 - cx0 + 1.0) * (cy1 - cy0 + 1.0) <= double(pixels.size())) {
        for (int row = int(cy0); row <= int(cy1); ++row)
          for (int x = int(cx0); x <= int(cx1); ++x)
            if (auto it = slot.find(std::size_t(row) * std::size_t(w) + std::size_t(x)); it != slot.end())
              list(it->second);
      } else {
        for (std::size_t p = 0; p < pixels.size(); ++p) {
          const double x = double(pixels[p] % std::size_t(w)), row = double(pixels[p] / std::size_t(w));
          if (x >= cx0 && x <= cx1 && row >= cy0 && row <= cy1) list(p);
        }
      }
    }
  }
  const std::vector<const ImagePolygon*>& of(std::size_t p) const { return of_[p]; }
  const std::vector<std::size_t>& ids(std::size_t p) const { return ids_[p]; }

 private:
  std::vector<ImagePolygon> polygons_;
  std::vector<std::vector<const ImagePolygon*>> of_;
  std::vector<std::vector<std::size_t>> ids_;
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
                                const std::vector<double>& cornerDepths,
                                const std::vector<std::vector<double>>& nearDepths) {
  if (pixels.empty() || volume.triangleCount() == 0) return 0;
  const std::vector<glm::dvec2> corners = imagePlaneTieCorners();
  SV_CHECK(cornerDepths.empty() || cornerDepths.size() == corners.size() * pixels.size());
  SV_CHECK(nearDepths.empty() || nearDepths.size() == pixels.size());
  const std::vector<std::size_t> near = trianglesNear(volume, camera, pixels);
  DoubleCounter counter(volume, near);
  const PrimaryRays rays(camera);
  const PolygonsNear polygons(volume, camera, near, pixels);
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
    if (!nearDepths.empty())
      for (const double d : nearDepths[p])
        if (d < INFINITY && std::abs(d - own) > tieTolerance(camera, own) * own) depths.push_back(d);
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
    const glm::dvec2 centrePx(x + 0.5, row + 0.5);
    const SquareRange square =
        squareRange(polygons.of(p), polygons.ids(p), volume, centre, centrePx, own, tieTolerance(camera, own) * own);
    lo = std::min(lo, square.lo);
    hi = std::max(hi, square.hi);
    widened += lo < counts.zfailMin[k] || hi > counts.zfailMax[k];
    counts.zfailMin[k] = lo;
    counts.zfailMax[k] = hi;
  }
  return widened;
}

}  // namespace shadowvol

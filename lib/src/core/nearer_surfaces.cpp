#include "shadowvol/nearer_surfaces.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/ext/vector_int3_sized.hpp>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadowvol/check.h"
#include "shadowvol/triangle_adjacency.h"

namespace shadowvol {

TriangleSoup soupOf(const TriangleMesh& mesh) {
  static_assert(sizeof(glm::vec3) == 3 * sizeof(float) && sizeof(mesh.triangles[0]) == 3 * sizeof(std::uint32_t));
  return {std::span<const float>(reinterpret_cast<const float*>(mesh.positions.data()), 3 * mesh.positions.size()),
          std::span<const std::uint32_t>(reinterpret_cast<const std::uint32_t*>(mesh.triangles.data()),
                                         3 * mesh.triangles.size()),
          isClosedSurface(mesh), {}, {}};
}

int lightFacing(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, bool perspective) {
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const glm::dvec3 ray = perspective ? a : glm::dvec3(0.0, 0.0, -1.0);
  const double along = glm::dot(n, ray), edgeOn = 1e-9 * glm::length(n) * glm::length(ray);
  return along > edgeOn ? -1 : -along > edgeOn ? 1 : 0;
}

TriangleMesh meshOf(const TriangleSoup& soup) {
  TriangleMesh m;
  m.positions.resize(soup.xyz.size() / 3);
  for (std::size_t k = 0; k < m.positions.size(); ++k)
    m.positions[k] = {soup.xyz[3 * k], soup.xyz[3 * k + 1], soup.xyz[3 * k + 2]};
  m.triangles.resize(soup.indices.size() / 3);
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    m.triangles[t] = {soup.indices[3 * t], soup.indices[3 * t + 1], soup.indices[3 * t + 2]};
  return m;
}

namespace {

// A clipped triangle has at most 3 + 2 (depth planes) + 4 (quad sides) corners.
constexpr int kMaxCorners = 9;

// A polygon corner in the image: texel coordinates and an attribute that is linear along the
// image's straight lines (the depth for a directional light, its inverse for a spot light).
struct ImageCorner {
  double x, y, a;
};

ImageCorner lerpCorner(const ImageCorner& u, const ImageCorner& v, double t) {
  return {u.x + t * (v.x - u.x), u.y + t * (v.y - u.y), u.a + t * (v.a - u.a)};
}

// Sutherland-Hodgman: the part of the polygon `in` (n corners) where s(corner) >= 0, for an s that
// is linear along the polygon's sides.
template <typename Corner, typename Side, typename Lerp>
int clipPolygon(const Corner* in, int n, Corner* out, Side s, Lerp lerp) {
  int m = 0;
  for (int k = 0; k < n; ++k) {
    const Corner& p = in[k];
    const Corner& q = in[(k + 1) % n];
    const double sp = s(p), sq = s(q);
    if (sp >= 0.0) out[m++] = p;
    if ((sp >= 0.0) != (sq >= 0.0)) out[m++] = lerp(p, q, sp / (sp - sq));
  }
  return m;
}

struct Projection {
  glm::dmat4 view, projection;
  double width, height;
  bool perspective;
  double nearDepth, farDepth;

  explicit Projection(const DepthMap& map)
      : view(map.lightView), projection(map.lightProjection), width(map.width), height(map.height),
        perspective(map.lightType != LightType::Directional),
        // Never at a spot light's apex (triangle_exit.h's rule), where the image has no point.
        nearDepth(perspective ? std::max(map.nearPlane, 1e-9 * map.farPlane) : map.nearPlane),
        farDepth(map.farPlane) {}

  ImageCorner image(const glm::dvec3& v) const {
    const glm::dvec4 c = projection * glm::dvec4(v, 1.0);
    const double depth = -v.z;
    return {(c.x / c.w + 1.0) * 0.5 * width - 0.5, (c.y / c.w + 1.0) * 0.5 * height - 0.5,
            perspective ? 1.0 / depth : depth};
  }
  double depthOf(double a) const { return perspective ? 1.0 / a : a; }
};

// The polygon's nearest depth (from its corners' attributes).
double nearestDepth(const Projection& p, const ImageCorner* c, int n) {
  double a = c[0].a;
  for (int k = 1; k < n; ++k) a = p.perspective ? std::max(a, c[k].a) : std::min(a, c[k].a);
  return p.depthOf(a);
}

// Whether the polygon has a point in the square [qi, qi + 1] x [qj, qj + 1] nearer than `limit`.
bool nearerInQuad(const Projection& p, const ImageCorner* poly, int n, int qi, int qj, double limit) {
  std::array<ImageCorner, kMaxCorners> a, b;
  const auto lerp = lerpCorner;
  const double x0 = qi, x1 = qi + 1.0, y0 = qj, y1 = qj + 1.0;
  int m = clipPolygon(poly, n, a.data(), [&](const ImageCorner& c) { return c.x - x0; }, lerp);
  if (m) m = clipPolygon(a.data(), m, b.data(), [&](const ImageCorner& c) { return x1 - c.x; }, lerp);
  if (m) m = clipPolygon(b.data(), m, a.data(), [&](const ImageCorner& c) { return c.y - y0; }, lerp);
  if (m) m = clipPolygon(a.data(), m, b.data(), [&](const ImageCorner& c) { return y1 - c.y; }, lerp);
  return m > 0 && nearestDepth(p, b.data(), m) < limit;
}

// The plane of a polygon's attribute over the image (the attribute is affine in x and y on a planar
// polygon), from its corners 0, 1 and 2: a(x, y) = a0 + gx (x - x0) + gy (y - y0). Unset (`valid`
// false) for fewer than three corners or corners nearly on a line (the sine of their angle below
// 1e-4), whose plane rounding would make unreliable. Only a shortcut: where it is unset or says
// nothing, the polygon is clipped to the square as before.
struct AttributePlane {
  double x0 = 0.0, y0 = 0.0, a0 = 0.0, gx = 0.0, gy = 0.0;
  bool valid = false;

  AttributePlane(const ImageCorner* c, int n) {
    if (n < 3) return;
    const double dx1 = c[1].x - c[0].x, dy1 = c[1].y - c[0].y, dx2 = c[2].x - c[0].x, dy2 = c[2].y - c[0].y;
    const double det = dx1 * dy2 - dx2 * dy1;
    const double scale = (std::abs(dx1) + std::abs(dy1)) * (std::abs(dx2) + std::abs(dy2));
    if (!(std::abs(det) > 1e-4 * scale)) return;
    const double da1 = c[1].a - c[0].a, da2 = c[2].a - c[0].a;
    x0 = c[0].x, y0 = c[0].y, a0 = c[0].a;
    gx = (da1 * dy2 - da2 * dy1) / det;
    gy = (dx1 * da2 - dx2 * da1) / det;
    valid = std::isfinite(gx) && std::isfinite(gy);
  }

  // Whether the plane lies beyond `limit` (light-view depth) over the whole square [qi, qi + 1] x
  // [qj, qj + 1] by more than 1e-6 of it (far above the plane's rounding, and below what a float
  // limit means): then so does every part of the polygon inside that square (an affine attribute
  // is nearest at one of the square's corners), and clipping would not flag the quad.
  bool beyondOver(const Projection& p, int qi, int qj, double limit) const {
    const double a = a0 + gx * (qi + 0.5 - x0) + gy * (qj + 0.5 - y0);
    const double spread = 0.5 * (std::abs(gx) + std::abs(gy));
    const double nearest = p.perspective ? a + spread : a - spread;  // the nearest attribute over the square
    if (p.perspective && !(nearest > 0.0)) return false;
    return p.depthOf(nearest) - limit > 1e-6 * std::abs(limit);
  }
};

// The quad rows a polygon's image crosses (within `slack` texels), and in each the columns of the
// quads it overlaps: f(qj, i0, i1) for each row qj with a nonempty range [i0, i1]. A small image
// (most triangles) takes its bounding box's quads; a larger one row by row, so that a long thin
// triangle across the map visits the quads along it, not its bounding box.
template <typename Row>
void forEachQuadRow(const ImageCorner* poly, int n, int qw, int qh, double slack, Row f) {
  double minX = 1e300, maxX = -1e300, minY = 1e300, maxY = -1e300;
  for (int k = 0; k < n; ++k) {
    minX = std::min(minX, poly[k].x), maxX = std::max(maxX, poly[k].x);
    minY = std::min(minY, poly[k].y), maxY = std::max(maxY, poly[k].y);
  }
  if (!(maxX + slack >= 0.0 && maxY + slack >= 0.0 && minX - slack <= qw && minY - slack <= qh)) return;  // or NaN
  const int j0 = std::max(0, int(std::floor(minY - slack))), j1 = std::min(qh - 1, int(std::floor(maxY + slack)));
  const int b0 = std::max(0, int(std::floor(minX - slack))), b1 = std::min(qw - 1, int(std::floor(maxX + slack)));
  if ((j1 - j0 + 1) * (b1 - b0 + 1) <= 16) {
    for (int qj = j0; qj <= j1; ++qj) f(qj, b0, b1);
    return;
  }
  const auto lerp = lerpCorner;
  std::array<ImageCorner, kMaxCorners> a, b;
  for (int qj = j0; qj <= j1; ++qj) {
    const double y0 = qj - slack, y1 = qj + 1.0 + slack;
    int m = clipPolygon(poly, n, a.data(), [&](const ImageCorner& c) { return c.y - y0; }, lerp);
    if (m) m = clipPolygon(a.data(), m, b.data(), [&](const ImageCorner& c) { return y1 - c.y; }, lerp);
    if (!m) continue;
    double lo = 1e300, hi = -1e300;
    for (int k = 0; k < m; ++k) lo = std::min(lo, b[std::size_t(k)].x), hi = std::max(hi, b[std::size_t(k)].x);
    if (!(hi + slack >= 0.0 && lo - slack <= qw)) continue;
    const int i0 = std::max(0, int(std::floor(lo - slack))), i1 = std::min(qw - 1, int(std::floor(hi + slack)));
    if (i0 <= i1) f(qj, i0, i1);
  }
}

// A triangle or a rim segment (n = 3 or 2 light-view corners) against the quads its image overlaps:
// sets `bit` in the flag of each quad whose closed square holds a point of it nearer than its limit.
void flagPolygon(const Projection& p, const glm::dvec3* v, int n, int qw, int qh, std::span<const float> limit,
                 std::span<std::uint8_t> flags, std::uint8_t bit) {
  // Clipping a segment (a polygon of two corners) may repeat a corner: at most 4 of them.
  std::array<glm::dvec3, 5> a, b;
  const int minCorners = n;
  const auto lerp3 = [](const glm::dvec3& u, const glm::dvec3& w, double t) { return u + t * (w - u); };
  n = clipPolygon(v, n, a.data(), [&](const glm::dvec3& c) { return -c.z - p.nearDepth; }, lerp3);
  if (n) n = clipPolygon(a.data(), n, b.data(), [&](const glm::dvec3& c) { return p.farDepth + c.z; }, lerp3);
  if (n < minCorners) return;
  std::array<ImageCorner, kMaxCorners> poly;
  for (int k = 0; k < n; ++k) poly[std::size_t(k)] = p.image(b[std::size_t(k)]);
  const double nearest = nearestDepth(p, poly.data(), n);
  const AttributePlane plane(poly.data(), n);
  forEachQuadRow(poly.data(), n, qw, qh, 0.0, [&](int qj, int i0, int i1) {
    for (int qi = i0; qi <= i1; ++qi) {
      const std::size_t q = std::size_t(qj) * std::size_t(qw) + std::size_t(qi);
      std::atomic_ref<std::uint8_t> flag(flags[q]);
      if (!(nearest < limit[q]) || (flag.load(std::memory_order_relaxed) & bit)) continue;
      if (plane.valid && plane.beyondOver(p, qi, qj, limit[q])) continue;  // cheaper than clipping
      if (nearerInQuad(p, poly.data(), n, qi, qj, limit[q])) flag.fetch_or(bit, std::memory_order_relaxed);
    }
  });
}

// A vertex's image in float, for the quick test that rejects most triangles before the exact one:
// texel coordinates and light-view depth; x is NaN when the depth lies outside [near, far] (the
// triangle then needs clipping).
struct VertexImage {
  float x, y, depth;
};

VertexImage vertexImage(const Projection& p, const glm::dvec3& view) {
  const double depth = -view.z;
  if (!(depth >= p.nearDepth && depth <= p.farDepth)) return {std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f};
  const ImageCorner c = p.image(view);
  return {float(c.x), float(c.y), float(depth)};
}

// Whether a triangle within [near, far] (its vertices' images) may hold a point nearer than the limit
// of a quad its image overlaps: false only when it surely does not (its nearest vertex at or beyond
// every such limit, or, for back capture, its image clearly counter-clockwise: facing the light).
// The margins cover the float rounding of the images.
bool mayBeNearer(const VertexImage& a, const VertexImage& b, const VertexImage& c, bool backOnly, int qw, int qh,
                 std::span<const float> limit) {
  const float nearest = std::min({a.depth, b.depth, c.depth});
  const float minX = std::min({a.x, b.x, c.x}), maxX = std::max({a.x, b.x, c.x});
  const float minY = std::min({a.y, b.y, c.y}), maxY = std::max({a.y, b.y, c.y});
  const float slack = 1e-4f + 4e-7f * std::max({std::abs(minX), std::abs(maxX), std::abs(minY), std::abs(maxY)});
  if (backOnly) {
    const double area = (double(b.x) - a.x) * (double(c.y) - a.y) - (double(b.y) - a.y) * (double(c.x) - a.x);
    const double extent = double(maxX - minX) + double(maxY - minY) + slack;
    if (area > 1e-4 * extent * extent) return false;  // counter-clockwise in the image: facing the light
  }
  const float below = nearest * (1.0f - 1e-5f);
  const std::array<ImageCorner, 3> tri{ImageCorner{a.x, a.y, 0.0}, ImageCorner{b.x, b.y, 0.0}, ImageCorner{c.x, c.y, 0.0}};
  bool may = false;
  forEachQuadRow(tri.data(), 3, qw, qh, slack, [&](int qj, int i0, int i1) {
    // (Rows after the first quad that may hold it only cost their clipping.)
    for (int qi = i0; qi <= i1 && !may; ++qi) may = below < limit[std::size_t(qj) * std::size_t(qw) + std::size_t(qi)];
  });
  return may;
}

// What both searches check and read first: the quad grid's size (qw x qh) and the largest limit;
// `searching` false when no quad's limit lies beyond the near plane (nothing can be flagged).
struct SearchGrid {
  int qw = 0, qh = 0;
  float maxLimit = -1.0f;
  bool searching = false;
};

SearchGrid searchGrid(const DepthMap& map, const Projection& p, std::span<const float> limit,
                      std::span<const std::uint8_t> flags) {
  SearchGrid g{map.width - 1, map.height - 1};
  if (g.qw < 1 || g.qh < 1) return g;
  SV_CHECK_EQ(limit.size(), std::size_t(g.qw) * std::size_t(g.qh));
  SV_CHECK_EQ(flags.size(), limit.size());
  // The largest limit, NaN limits aside; in eight independent lanes, without a branch, so that the
  // loop vectorises (one pass over every quad of the map, each frame).
  std::array<float, 8> lane;
  lane.fill(g.maxLimit);
  const std::size_t n = limit.size(), blocks = n - n % lane.size();
  for (std::size_t k = 0; k < blocks; k += lane.size())
    for (std::size_t l = 0; l < lane.size(); ++l) lane[l] = limit[k + l] > lane[l] ? limit[k + l] : lane[l];
  for (std::size_t k = blocks; k < n; ++k) lane[0] = limit[k] > lane[0] ? limit[k] : lane[0];
  for (float l : lane) g.maxLimit = l > g.maxLimit ? l : g.maxLimit;
  g.searching = double(g.maxLimit) > p.nearDepth;
  return g;
}

// Vertex k of a soup in the light's view space (double).
glm::dvec3 viewPoint(const Projection& p, const TriangleSoup& mesh, std::size_t k) {
  return glm::dvec3(p.view * glm::dvec4(mesh.xyz[3 * k], mesh.xyz[3 * k + 1], mesh.xyz[3 * k + 2], 1.0));
}

// For each vertex v in `ids` (sorted, unique), rep[v] = the smallest of `ids` within `tol` of it
// (itself at least); other entries of rep are unset. A grid of cells 4 tol wide, its (cell, id)
// pairs sorted: a point looks in its own cell, and in a neighbour only when it lies within tol of
// the side between them. Parallel, deterministic.
std::vector<std::uint32_t> nearestSmallest(const std::vector<glm::vec3>& pos, const std::vector<std::uint32_t>& ids,
                                           double tol, const glm::dvec3& origin) {
  const double size = 4.0 * tol;
  const auto key = [](const glm::i64vec3& c) {
    return std::uint64_t(c.x & 0x1FFFFF) | std::uint64_t(c.y & 0x1FFFFF) << 21 | std::uint64_t(c.z & 0x1FFFFF) << 42;
  };
  std::vector<std::pair<std::uint64_t, std::uint32_t>> cells(ids.size());
  for (std::size_t k = 0; k < ids.size(); ++k)
    cells[k] = {key(glm::i64vec3(glm::floor((glm::dvec3(pos[ids[k]]) - origin) / size))), ids[k]};
  std::sort(cells.begin(), cells.end());
  std::vector<std::uint32_t> rep(pos.size(), 0);
  // In cell order: the lookups of neighbouring points stay near each other in `cells`.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cells.size(), 1024), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t k = r.begin(); k != r.end(); ++k) {
      const std::uint32_t v = cells[k].second;
      const glm::dvec3 t = (glm::dvec3(pos[v]) - origin) / size, f = t - glm::floor(t);
      const glm::i64vec3 c(glm::floor(t));
      const glm::ivec3 from(f.x < 0.25 ? -1 : 0, f.y < 0.25 ? -1 : 0, f.z < 0.25 ? -1 : 0);
      const glm::ivec3 to(f.x > 0.75 ? 1 : 0, f.y > 0.75 ? 1 : 0, f.z > 0.75 ? 1 : 0);
      std::uint32_t best = v;
      for (int dz = from.z; dz <= to.z; ++dz)
        for (int dy = from.y; dy <= to.y; ++dy)
          for (int dx = from.x; dx <= to.x; ++dx) {
            const std::uint64_t kc = key(c + glm::i64vec3(dx, dy, dz));
            auto it = std::lower_bound(cells.begin(), cells.end(), std::pair<std::uint64_t, std::uint32_t>(kc, 0));
            for (; it != cells.end() && it->first == kc && it->second < best; ++it)
              if (glm::length(glm::dvec3(pos[it->second]) - glm::dvec3(pos[v])) <= tol) best = it->second;
          }
      rep[v] = best;
    }
  });
  return rep;
}

// The rims less those that another rim seals (kRimSealShare): each end within the tolerance of
// the other's, either way round (a soup's seam), or an edge shorter than it.
std::vector<std::uint32_t> unsealedRims(const TriangleMesh& mesh, const std::vector<std::uint32_t>& rims) {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, glm::dvec3(p)), hi = glm::max(hi, glm::dvec3(p));
  const double tol = kRimSealShare * glm::length(hi - lo);
  if (!(tol > 0.0) || !std::isfinite(tol)) return rims;
  std::vector<std::uint32_t> ids(rims);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  const auto rep = nearestSmallest(mesh.positions, ids, tol, lo);
  std::vector<std::pair<std::uint64_t, std::size_t>> keys;  // (representatives' edge, rim index)
  for (std::size_t e = 0; e < rims.size() / 2; ++e) {
    const auto [a, b] = std::minmax(rep[rims[2 * e]], rep[rims[2 * e + 1]]);
    if (a != b) keys.push_back({std::uint64_t(a) << 32 | b, e});
  }
  std::sort(keys.begin(), keys.end());
  std::vector<std::uint32_t> open;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const bool alone = (k == 0 || keys[k - 1].first != keys[k].first) &&
                       (k + 1 == keys.size() || keys[k + 1].first != keys[k].first);
    if (alone) open.insert(open.end(), {rims[2 * keys[k].second], rims[2 * keys[k].second + 1]});
  }
  return open;
}

}  // namespace

std::vector<std::uint32_t> openRims(const TriangleMesh& mesh, bool* closed) {
  if (closed) *closed = true;
  if (closedAsStored(mesh)) return {};  // welding can join its parts, never open it
  const std::vector<std::int32_t> neighbours = triangleNeighbours(mesh);
  if (closed) *closed = closedByNeighbours(mesh, neighbours);
  std::vector<std::uint32_t> rims;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const auto& pos = mesh.positions;
    if (pos[tri[0]] == pos[tri[1]] || pos[tri[1]] == pos[tri[2]] || pos[tri[2]] == pos[tri[0]]) continue;
    for (std::size_t k = 0; k < 3; ++k)
      if (neighbours[3 * t + k] == kNoNeighbour) rims.insert(rims.end(), {tri[k], tri[(k + 1) % 3]});
  }
  return rims.empty() ? rims : unsealedRims(mesh, rims);
}

void findNearerSurfaces(const DepthMap& map, std::span<const TriangleSoup> meshes, std::span<const float> limit,
                        std::span<std::uint8_t> flags) {
  const Projection p(map);
  const SearchGrid g = searchGrid(map, p, limit, flags);
  if (!g.searching) return;
  const int qw = g.qw, qh = g.qh;
  const float maxLimit = g.maxLimit;
  for (const TriangleSoup& mesh : meshes) {
    const bool backOnly = map.capture == CaptureMode::Back || (map.capture == CaptureMode::Entry && !mesh.closed);
    SV_CHECK_EQ(mesh.xyz.size() % 3, 0u);
    SV_CHECK_EQ(mesh.indices.size() % 3, 0u);
    const std::size_t vertices = mesh.xyz.size() / 3;
    const auto viewOf = [&](std::size_t k) { return viewPoint(p, mesh, k); };
    // Each vertex's image once (most vertices serve six triangles), then the quick test per triangle.
    std::vector<VertexImage> image(vertices);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices, 8192), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t k = r.begin(); k != r.end(); ++k) image[k] = vertexImage(p, viewOf(k));
    });
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.indices.size() / 3, 4096),
                      [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t t = r.begin(); t != r.end(); ++t) {
        const std::size_t k0 = mesh.indices[3 * t], k1 = mesh.indices[3 * t + 1], k2 = mesh.indices[3 * t + 2];
        SV_CHECK_LT(std::max({k0, k1, k2}), vertices);
        const VertexImage &a = image[k0], &b = image[k1], &c = image[k2];
        const bool inRange = !std::isnan(a.x) && !std::isnan(b.x) && !std::isnan(c.x);
        if (inRange && !mayBeNearer(a, b, c, backOnly, qw, qh, limit)) continue;
        const std::array<glm::dvec3, 3> v{viewOf(k0), viewOf(k1), viewOf(k2)};
        // Nearest depth first: most triangles lie on or behind the sheet.
        const double nearest = -std::max({v[0].z, v[1].z, v[2].z});
        if (!(nearest < double(maxLimit)) || -std::min({v[0].z, v[1].z, v[2].z}) < p.nearDepth) continue;
        // The capture's facing rule: back capture records only triangles facing away from the light;
        // no capture records one edge-on to the light or without area.
        const int facing = lightFacing(v[0], v[1], v[2], p.perspective);
        if (backOnly ? facing != -1 : facing == 0) continue;
        flagPolygon(p, v.data(), 3, qw, qh, limit, flags, 1);
      }
    });
  }
}

void findOpenRims(const DepthMap& map, std::span<const TriangleSoup> meshes, std::span<const float> limit,
                  std::span<std::uint8_t> flags) {
  const Projection p(map);
  const SearchGrid g = searchGrid(map, p, limit, flags);
  if (!g.searching) return;
  for (const TriangleSoup& mesh : meshes) {
    SV_CHECK_EQ(mesh.rims.size() % 2, 0u);
    const std::size_t vertices = mesh.xyz.size() / 3;
    const auto viewOf = [&](std::size_t k) {
      SV_CHECK_LT(k, vertices);
      return viewPoint(p, mesh, k);
    };
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.rims.size() / 2, 1024),
                      [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t e = r.begin(); e != r.end(); ++e) {
        const std::array<glm::dvec3, 2> v{viewOf(mesh.rims[2 * e]), viewOf(mesh.rims[2 * e + 1])};
        if (!(-std::max(v[0].z, v[1].z) < double(g.maxLimit))) continue;  // behind every limit
        flagPolygon(p, v.data(), 2, g.qw, g.qh, limit, flags, kRimFlag);
      }
    });
  }
}

}  // namespace shadowvol

#include "shadowvol/caster_faces.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadowvol/check.h"
#include "shadowvol/triangle_adjacency.h"

namespace shadowvol {
namespace {

// Flagged quads in a rectangle of the quad grid, in O(1): a summed-area table of the flags.
class FlagSums {
 public:
  FlagSums(std::span<const std::uint8_t> flags, int qw, int qh)
      : qw_(qw), qh_(qh), sum_(std::size_t(qw + 1) * std::size_t(qh + 1), 0) {
    for (int j = 0; j < qh; ++j)
      for (int i = 0; i < qw; ++i)
        at(i + 1, j + 1) = at(i, j + 1) + at(i + 1, j) - at(i, j) + (flags[std::size_t(j) * qw + i] != 0);
  }
  bool any() const { return sum_.back() > 0; }
  /// Whether a quad whose closed square meets the box [x0, x1] x [y0, y1] (texel coordinates: quad
  /// (qi, qj) is [qi, qi + 1] x [qj, qj + 1]) is flagged.
  bool anyIn(double x0, double x1, double y0, double y1) const {
    if (!(x1 >= 0.0 && y1 >= 0.0 && x0 <= qw_ && y0 <= qh_)) return false;
    // Clamped in double before the conversion (a corner just past a small near plane lies far out).
    const auto index = [](double v, int n) { return int(std::clamp(v, 0.0, double(n - 1))); };
    const int i0 = index(std::ceil(x0) - 1.0, qw_), i1 = index(std::floor(x1), qw_);
    const int j0 = index(std::ceil(y0) - 1.0, qh_), j1 = index(std::floor(y1), qh_);
    return at(i1 + 1, j1 + 1) - at(i0, j1 + 1) - at(i1 + 1, j0) + at(i0, j0) > 0;
  }

 private:
  std::uint32_t& at(int i, int j) { return sum_[std::size_t(j) * std::size_t(qw_ + 1) + std::size_t(i)]; }
  std::uint32_t at(int i, int j) const { return sum_[std::size_t(j) * std::size_t(qw_ + 1) + std::size_t(i)]; }
  int qw_, qh_;
  std::vector<std::uint32_t> sum_;
};

// A vertex in light view and its image in texel coordinates; `inRange` when its light-view depth
// lies strictly between the near and far planes.
struct ViewVertex {
  glm::dvec3 view;
  double x = 0.0, y = 0.0;
  bool inRange = false;
};

// Each vertex of `mesh` in light view, with its image where it lies in range.
std::vector<ViewVertex> imageOf(const DepthMap& map, const TriangleSoup& mesh) {
  const glm::dmat4 view = map.lightView, projection = map.lightProjection;
  std::vector<ViewVertex> image(mesh.xyz.size() / 3);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, image.size(), 8192), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t k = r.begin(); k != r.end(); ++k) {
      ViewVertex& v = image[k];
      v.view = glm::dvec3(view * glm::dvec4(mesh.xyz[3 * k], mesh.xyz[3 * k + 1], mesh.xyz[3 * k + 2], 1.0));
      const double depth = -v.view.z;
      v.inRange = depth > map.nearPlane && depth < map.farPlane;
      if (!v.inRange) continue;
      const glm::dvec4 c = projection * glm::dvec4(v.view, 1.0);
      const glm::dvec2 t = map.texelOfNdc({c.x / c.w, c.y / c.w});
      v.x = t.x;
      v.y = t.y;
    }
  });
  return image;
}

// Inside the light's window, so that every prism stays in its frustum (zpass.h's rule).
bool insideWindow(const DepthMap& map, double x0, double x1, double y0, double y1) {
  return x0 >= -0.5 && y0 >= -0.5 && x1 <= map.width - 0.5 && y1 <= map.height - 0.5;
}

// A face's state in the selection.
constexpr std::uint8_t kNotTaken = 0, kEligible = 1, kTaken = 2;

// Takes every eligible face connected to a taken one across edges between eligible faces (a link
// of triangleNeighbours; one between faces wound against each other is not crossed): each region
// of light-facing faces that reaches a flagged quad, whole.
void growOverEdges(const TriangleSoup& mesh, std::vector<std::uint8_t>& take) {
  std::vector<std::uint32_t> stack;
  for (std::size_t t = 0; t < take.size(); ++t)
    if (take[t] == kTaken) stack.push_back(std::uint32_t(t));
  if (stack.empty()) return;
  std::vector<std::int32_t> own;
  std::span<const std::int32_t> neighbours = mesh.neighbours;
  if (neighbours.empty()) {
    own = triangleNeighbours(meshOf(mesh));
    neighbours = own;
  }
  SV_CHECK_EQ(neighbours.size(), 3 * take.size());
  while (!stack.empty()) {
    const std::uint32_t t = stack.back();
    stack.pop_back();
    for (std::size_t k = 0; k < 3; ++k) {
      const std::int32_t link = neighbours[3 * std::size_t(t) + k];
      if (link < 0 || (link & kFlippedNeighbour) != 0) continue;
      SV_CHECK_LT(std::size_t(link), take.size());  // neighbours of another mesh: a caller's logic error
      if (take[std::size_t(link)] != kEligible) continue;
      take[std::size_t(link)] = kTaken;
      stack.push_back(std::uint32_t(link));
    }
  }
}

}  // namespace

bool handedToPrisms(const DepthMap& map, const TriangleSoup& mesh) {
  if (!mesh.closed || mesh.xyz.empty()) return false;
  const std::vector<ViewVertex> image = imageOf(map, mesh);
  return std::all_of(image.begin(), image.end(),
                     [&map](const ViewVertex& v) { return v.inRange && insideWindow(map, v.x, v.x, v.y, v.y); });
}

std::vector<std::array<glm::dvec3, 3>> findCasterFaces(const DepthMap& map, std::span<const TriangleSoup> meshes,
                                                      std::span<const std::uint8_t> quads) {
  const int qw = map.width - 1, qh = map.height - 1;
  std::vector<std::array<glm::dvec3, 3>> faces;
  if (qw < 1 || qh < 1) return faces;
  SV_CHECK_EQ(quads.size(), std::size_t(qw) * std::size_t(qh));
  const FlagSums flagged(quads, qw, qh);
  if (!flagged.any()) return faces;
  const bool perspective = map.lightType != LightType::Directional;
  for (const TriangleSoup& mesh : meshes) {
    if (!mesh.closed) continue;
    SV_CHECK_EQ(mesh.xyz.size() % 3, 0u);
    SV_CHECK_EQ(mesh.indices.size() % 3, 0u);
    const std::size_t vertices = mesh.xyz.size() / 3, triangles = mesh.indices.size() / 3;
    const std::vector<ViewVertex> image = imageOf(map, mesh);
    std::vector<std::uint8_t> take(triangles, kNotTaken);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, triangles, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t t = r.begin(); t != r.end(); ++t) {
        const std::size_t k0 = mesh.indices[3 * t], k1 = mesh.indices[3 * t + 1], k2 = mesh.indices[3 * t + 2];
        SV_CHECK_LT(std::max({k0, k1, k2}), vertices);
        const ViewVertex &a = image[k0], &b = image[k1], &c = image[k2];
        if (!(a.inRange && b.inRange && c.inRange) || lightFacing(a.view, b.view, c.view, perspective) != 1) continue;
        const double x0 = std::min({a.x, b.x, c.x}), x1 = std::max({a.x, b.x, c.x});
        const double y0 = std::min({a.y, b.y, c.y}), y1 = std::max({a.y, b.y, c.y});
        if (!insideWindow(map, x0, x1, y0, y1)) continue;
        take[t] = flagged.anyIn(x0, x1, y0, y1) ? kTaken : kEligible;
      }
    });
    growOverEdges(mesh, take);
    const auto world = [&](std::size_t k) {
      return glm::dvec3(mesh.xyz[3 * k], mesh.xyz[3 * k + 1], mesh.xyz[3 * k + 2]);
    };
    for (std::size_t t = 0; t < triangles; ++t)
      if (take[t] == kTaken)
        faces.push_back({world(mesh.indices[3 * t]), world(mesh.indices[3 * t + 1]), world(mesh.indices[3 * t + 2])});
  }
  return faces;
}

}  // namespace shadowvol

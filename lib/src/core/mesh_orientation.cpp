#include "shadowvol/mesh_orientation.h"

#include <cmath>
#include <cstdint>
#include <utility>

#include <glm/geometric.hpp>

#include "shadowvol/triangle_adjacency.h"

namespace shadowvol {
namespace {

constexpr std::int8_t kUnknown = -1;

// Two corners at exactly one position: the weld of triangle_adjacency.h gives it no neighbours.
bool degenerate(const TriangleMesh& m, const std::array<std::uint32_t, 3>& t) {
  const glm::vec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
  return a == b || b == c || c == a;
}

// Signed volume with the triangles of `flip` reversed, summed about `o`, and the sum of its
// terms' magnitudes (for kOrientationVolumeTolerance).
struct Volume {
  double sum = 0.0, magnitude = 0.0;
  bool negative() const { return sum < -kOrientationVolumeTolerance * magnitude; }
  void add(const std::vector<glm::dvec3>& world, const std::array<std::uint32_t, 3>& t, bool flip,
           const glm::dvec3& o) {
    const glm::dvec3 a = world[t[0]] - o, b = world[t[1]] - o, c = world[t[2]] - o;
    const double v = glm::dot(a, glm::cross(b, c)) / 6.0;
    sum += flip ? -v : v;
    magnitude += std::abs(v);
  }
};

// Winding of each triangle relative to its component's first (1 = reverse it to agree); kUnknown
// for degenerate triangles. `component` numbers the components in the order of their first
// triangle. Empty when some link disagrees with both windings (a non-orientable surface).
struct Components {
  std::vector<std::int8_t> flip;
  std::vector<std::uint32_t> component;
  std::uint32_t count = 0;
};

Components windComponents(const TriangleMesh& mesh, const std::vector<std::int32_t>& neighbours) {
  const std::size_t n = mesh.triangles.size();
  Components c{std::vector<std::int8_t>(n, kUnknown), std::vector<std::uint32_t>(n, 0), 0};
  std::vector<std::size_t> stack;
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (c.flip[seed] != kUnknown || degenerate(mesh, mesh.triangles[seed])) continue;
    c.flip[seed] = 0;
    c.component[seed] = c.count;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const std::size_t t = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        const std::int32_t link = neighbours[3 * t + std::size_t(k)];
        const std::size_t other = std::size_t(link & ~kFlippedNeighbour);
        const std::int8_t want = std::int8_t(c.flip[t] ^ ((link & kFlippedNeighbour) ? 1 : 0));
        if (c.flip[other] == kUnknown) {
          c.flip[other] = want;
          c.component[other] = c.count;
          stack.push_back(other);
        } else if (c.flip[other] != want) {
          return {};
        }
      }
    }
    ++c.count;
  }
  return c;
}

}  // namespace

OrientationResult orientOutward(TriangleMesh& mesh, const std::vector<glm::dvec3>& world) {
  OrientationResult r;
  const std::vector<std::int32_t> neighbours = triangleNeighbours(mesh);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (degenerate(mesh, mesh.triangles[t])) continue;
    for (int k = 0; k < 3; ++k)
      if (neighbours[3 * t + std::size_t(k)] == kNoNeighbour) {
        r.left = "not closed (an edge with one triangle, or with three or more)";
        return r;
      }
  }
  Components c = windComponents(mesh, neighbours);
  if (c.flip.empty()) {
    r.left = "not orientable (no winding makes every pair of neighbours agree)";
    return r;
  }
  Bounds3 box;
  for (const auto& p : world) box.extend(p);
  const glm::dvec3 o = box.center();
  // Each component that disagreed within itself faces outward on its own (its first triangle's
  // winding kept, or the other if that one encloses a negative volume).
  std::vector<Volume> volumes(c.count);
  std::vector<bool> repaired(c.count, false);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (c.flip[t] == kUnknown) continue;
    volumes[c.component[t]].add(world, mesh.triangles[t], c.flip[t] == 1, o);
    if (c.flip[t] == 1) repaired[c.component[t]] = true;
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (c.flip[t] != kUnknown && repaired[c.component[t]] && volumes[c.component[t]].negative()) c.flip[t] ^= 1;
  for (const bool k : repaired) r.repairedComponents += k;
  Volume whole;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (c.flip[t] != kUnknown) whole.add(world, mesh.triangles[t], c.flip[t] == 1, o);
  r.volumeBefore = whole.sum;
  r.insideOut = whole.negative();
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if ((c.flip[t] == 1) != r.insideOut) {
      std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
      ++r.reversed;
    }
  }
  return r;
}

}  // namespace shadowvol

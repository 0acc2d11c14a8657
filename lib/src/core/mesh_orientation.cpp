#include "shadowvol/mesh_orientation.h"

#include <cmath>
#include <cstdint>
#include <optional>
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
  bool positive() const { return sum > kOrientationVolumeTolerance * magnitude; }
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
        if (link == kNoNeighbour) continue;  // an open or non-manifold edge
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

// A point's nesting in the other closed parts: inside part q when a ray from it crosses q an odd
// number of times (a skewed direction, in double). Only parts whose box holds the point are cast
// against, and at most `budget` triangle tests in all (then nullopt: not checked).
class PartContainment {
 public:
  PartContainment(const TriangleMesh& mesh, const std::vector<glm::dvec3>& world, const Components& c,
                  std::size_t budget)
      : mesh_(mesh), world_(world), first_(c.count + 1, 0), boxes_(c.count), budget_(budget) {
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      if (c.flip[t] != kUnknown) ++first_[c.component[t] + 1];
    for (std::size_t k = 1; k < first_.size(); ++k) first_[k] += first_[k - 1];
    order_.resize(first_.back());
    std::vector<std::size_t> next(first_.begin(), first_.end() - 1);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      if (c.flip[t] == kUnknown) continue;
      order_[next[c.component[t]]++] = std::uint32_t(t);
      for (const std::uint32_t v : mesh.triangles[t]) boxes_[c.component[t]].extend(world[v]);
    }
  }

  /// A vertex of part `part`, and whether it lies inside another part; nullopt once the budget is spent.
  std::optional<bool> insideAnother(std::uint32_t part) {
    const glm::dvec3 p = world_[mesh_.triangles[order_[first_[part]]][0]];
    for (std::uint32_t q = 0; q + 1 < first_.size(); ++q) {
      if (q == part || !contains(boxes_[q], p)) continue;
      const std::size_t n = first_[q + 1] - first_[q];
      if (work_ + n > budget_) return std::nullopt;
      work_ += n;
      if (crossings(p, q) % 2 == 1) return true;
    }
    return false;
  }

 private:
  static bool contains(const Bounds3& b, const glm::dvec3& p) {
    return p.x >= b.min.x && p.y >= b.min.y && p.z >= b.min.z && p.x <= b.max.x && p.y <= b.max.y && p.z <= b.max.z;
  }

  int crossings(const glm::dvec3& p, std::uint32_t q) const {
    const glm::dvec3 dir = glm::normalize(glm::dvec3(0.5377, 0.8421, 0.0419));  // skewed: avoids edges
    int n = 0;
    for (std::size_t k = first_[q]; k < first_[q + 1]; ++k) {
      const auto& t = mesh_.triangles[order_[k]];
      const glm::dvec3 a = world_[t[0]], e1 = world_[t[1]] - a, e2 = world_[t[2]] - a;
      const glm::dvec3 h = glm::cross(dir, e2);
      const double det = glm::dot(e1, h);
      if (det == 0.0) continue;
      const glm::dvec3 s = p - a;
      const double u = glm::dot(s, h) / det;
      if (u < 0.0 || u > 1.0) continue;
      const glm::dvec3 g = glm::cross(s, e1);
      const double v = glm::dot(dir, g) / det;
      if (v < 0.0 || u + v > 1.0) continue;
      n += glm::dot(e2, g) / det > 0.0;
    }
    return n;
  }

  const TriangleMesh& mesh_;
  const std::vector<glm::dvec3>& world_;
  std::vector<std::size_t> first_;  // part q's triangles: order_[first_[q] .. first_[q + 1])
  std::vector<std::uint32_t> order_;
  std::vector<Bounds3> boxes_;
  std::size_t budget_;
  std::size_t work_ = 0;
};

}  // namespace

// An open mesh: each part whose faces disagree takes the winding of most of its triangles (of
// its first triangle on a tie); its outside is not defined, so nothing more.
void orientOpenParts(TriangleMesh& mesh, const Components& c, OrientationResult& r) {
  std::vector<std::size_t> against(c.count, 0), size(c.count, 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (c.flip[t] == kUnknown) continue;
    ++size[c.component[t]];
    against[c.component[t]] += c.flip[t] == 1;
  }
  for (std::uint32_t q = 0; q < c.count; ++q) r.repairedComponents += against[q] > 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (c.flip[t] == kUnknown) continue;
    const std::uint32_t q = c.component[t];
    const bool keepFirst = 2 * against[q] <= size[q];
    if ((c.flip[t] == 1) == keepFirst) {
      std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
      ++r.reversed;
    }
  }
}

OrientationResult orientOutward(TriangleMesh& mesh, const std::vector<glm::dvec3>& world,
                                std::size_t containmentTests) {
  OrientationResult r;
  const std::vector<std::int32_t> neighbours = triangleNeighbours(mesh);
  bool closed = true;
  for (std::size_t t = 0; t < mesh.triangles.size() && closed; ++t)
    for (int k = 0; k < 3 && !degenerate(mesh, mesh.triangles[t]); ++k)
      closed = closed && neighbours[3 * t + std::size_t(k)] != kNoNeighbour;
  Components c = windComponents(mesh, neighbours);
  if (c.flip.empty()) {
    r.left = "not orientable (no winding makes every pair of neighbours agree)";
    return r;
  }
  if (!closed) {
    r.left = "not closed (an edge with one triangle, or with three or more): its outside is not defined";
    r.open = true;
    orientOpenParts(mesh, c, r);
    return r;
  }
  Bounds3 box;
  for (const auto& p : world) box.extend(p);
  const glm::dvec3 o = box.center();
  // 1. Each part that disagreed within itself faces outward on its own (its first triangle's
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
  // 2. The whole mesh inside out: every triangle reversed.
  Volume whole;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (c.flip[t] != kUnknown) whole.add(world, mesh.triangles[t], c.flip[t] == 1, o);
  r.volumeBefore = whole.sum;
  r.insideOut = whole.negative();
  // 3. A part that agreed within itself and still encloses a negative volume is an inner shell
  // only if it lies inside another part: one that does not (its first vertex outside every other
  // part) was stored inside out on its own, and is reversed.
  std::vector<bool> loose(c.count, false);
  PartContainment containment(mesh, world, c, containmentTests);
  for (std::uint32_t q = 0; q < c.count; ++q) {
    if (repaired[q] || !(r.insideOut ? volumes[q].positive() : volumes[q].negative())) continue;
    const std::optional<bool> inside = containment.insideAnother(q);
    if (!inside) {
      ++r.partsNotChecked;
      continue;
    }
    loose[q] = !*inside;
    r.looseParts += loose[q];
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const bool reverse = (c.flip[t] == 1) != r.insideOut;
    if (reverse != (c.flip[t] != kUnknown && loose[c.component[t]])) {
      std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
      ++r.reversed;
    }
  }
  return r;
}

}  // namespace shadowvol

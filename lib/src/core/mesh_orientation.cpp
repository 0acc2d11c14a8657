#include "shadowvol/mesh_orientation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>

#include <glm/geometric.hpp>

#include "shadowvol/ray_parity.h"
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

// How deep each part of a closed mesh is nested in the others: part p lies inside part q when
// every one of up to kNestingSamples of p's vertices does (ray_parity.h: odd crossings of q). A
// vertex outside q shows that p is not an inner shell of q, even where p is pushed partly into q
// or touches it; an inner shell lies wholly inside. Only parts whose box holds p's box are tested,
// and at most `budget` triangle tests in all (then nullopt).
class PartNesting {
 public:
  PartNesting(const TriangleMesh& mesh, const std::vector<glm::dvec3>& world, const Components& c, std::size_t budget)
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

  /// The number of other parts that hold part p; nullopt once the budget is spent.
  std::optional<std::size_t> depth(std::uint32_t p) {
    std::size_t d = 0;
    for (std::uint32_t q = 0; q + 1 < first_.size(); ++q) {
      if (q == p || !holds(boxes_[q], boxes_[p])) continue;
      const std::optional<bool> in = inside(p, q);
      if (!in) return std::nullopt;
      d += *in;
    }
    return d;
  }

 private:
  static constexpr std::size_t kNestingSamples = 8;

  static bool holds(const Bounds3& outer, const Bounds3& inner) {
    return outer.min.x <= inner.min.x && outer.min.y <= inner.min.y && outer.min.z <= inner.min.z &&
           outer.max.x >= inner.max.x && outer.max.y >= inner.max.y && outer.max.z >= inner.max.z;
  }

  // Every sample of p inside q; nullopt once the budget is spent.
  std::optional<bool> inside(std::uint32_t p, std::uint32_t q) {
    const std::size_t n = first_[p + 1] - first_[p];
    for (std::size_t k = 0; k < kNestingSamples && k < n; ++k) {
      const std::size_t t = first_[p] + (n - 1) * k / std::max<std::size_t>(kNestingSamples - 1, 1);
      const std::size_t cost = first_[q + 1] - first_[q];
      if (work_ + cost > budget_) return std::nullopt;
      work_ += cost;
      if (crossings(world_[mesh_.triangles[order_[t]][0]], q) % 2 == 0) return false;
    }
    return true;
  }

  int crossings(const glm::dvec3& p, std::uint32_t q) const {
    int n = 0;
    for (std::size_t k = first_[q]; k < first_[q + 1]; ++k) {
      const auto& t = mesh_.triangles[order_[k]];
      n += parityRayCrosses(p, world_[t[0]], world_[t[1]], world_[t[2]]);
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

// A closed mesh: each part wound alike (c.flip), then reversed where its volume's sign disagrees
// with its nesting (positive at even depth, negative at odd), or, if flat, where most of its
// triangles were wound the other way.
void orientClosedParts(TriangleMesh& mesh, const std::vector<glm::dvec3>& world, Components& c,
                       std::size_t containmentTests, OrientationResult& r) {
  Bounds3 box;
  for (const auto& p : world) box.extend(p);
  const glm::dvec3 o = box.center();
  std::vector<Volume> volumes(c.count);
  std::vector<std::size_t> against(c.count, 0), size(c.count, 0);
  Volume stored;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (c.flip[t] == kUnknown) continue;
    const std::uint32_t q = c.component[t];
    volumes[q].add(world, mesh.triangles[t], c.flip[t] == 1, o);
    stored.add(world, mesh.triangles[t], false, o);
    ++size[q];
    against[q] += c.flip[t] == 1;
  }
  r.volumeBefore = stored.sum;
  PartNesting nesting(mesh, world, c, containmentTests);
  std::vector<bool> reverse(c.count, false);
  std::size_t wholeParts = 0, partsReversed = 0;
  for (std::uint32_t q = 0; q < c.count; ++q) {
    r.repairedComponents += against[q] > 0;
    const Volume& v = volumes[q];
    if (!v.negative() && !v.positive()) {  // flat: keep the winding of most of its triangles
      reverse[q] = 2 * against[q] > size[q];
      continue;
    }
    std::optional<std::size_t> depth = nesting.depth(q);
    if (!depth) {
      ++r.partsNotChecked;  // taken as not nested, as most parts are
      depth = 0;
    }
    reverse[q] = v.negative() == (*depth % 2 == 0);
    if (against[q] == 0) {
      ++wholeParts;
      partsReversed += reverse[q];
    }
  }
  r.insideOut = partsReversed > 0 && partsReversed == wholeParts;
  r.looseParts = r.insideOut ? 0 : partsReversed;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const bool flip = c.flip[t] == kUnknown ? r.insideOut : (c.flip[t] == 1) != reverse[c.component[t]];
    if (flip) {
      std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
      ++r.reversed;
    }
  }
}

}  // namespace

OrientationResult orientOutward(TriangleMesh& mesh, const std::vector<glm::dvec3>& world,
                                std::size_t containmentTests) {
  OrientationResult r;
  if (mesh.triangles.empty()) return r;
  const std::vector<std::int32_t> neighbours = triangleNeighbours(mesh);
  const bool closed = closedByNeighbours(mesh, neighbours);
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
  orientClosedParts(mesh, world, c, containmentTests, r);
  return r;
}

}  // namespace shadowvol

#include "shadowvol/triangle_adjacency.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <numeric>
#include <string>
#include <tuple>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <glm/geometric.hpp>

#include "shadowvol/check.h"
#include "shadowvol/error.h"

namespace shadowvol {

namespace {

// Welded vertex ids: the smallest index of the vertices with exactly the same position.
std::vector<std::uint32_t> weldByPosition(const std::vector<glm::vec3>& positions) {
  std::vector<std::uint32_t> order(positions.size());
  std::iota(order.begin(), order.end(), 0u);
  auto key = [&](std::uint32_t v) { return std::make_tuple(positions[v].x, positions[v].y, positions[v].z, v); };
  tbb::parallel_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
  std::vector<std::uint32_t> weld(positions.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::uint32_t v = order[k];
    weld[v] = (k > 0 && positions[order[k - 1]] == positions[v]) ? weld[order[k - 1]] : v;
  }
  return weld;
}

// An edge end in the bucket of its smaller welded vertex.
struct EdgeEnd {
  std::uint32_t larger;  // the larger welded vertex
  std::uint32_t slot;    // 3 t + k
  bool forward;          // runs from the smaller welded vertex to the larger
  bool operator<(const EdgeEnd& o) const { return larger != o.larger ? larger < o.larger : slot < o.slot; }
};

// Offsets of the buckets (one per vertex id below `vertices`) that `count(f)` fills: f(key) is
// called once for each entry's bucket key; start[v] .. start[v + 1] is bucket v.
template <typename ForEachKey>
std::vector<std::size_t> bucketStarts(std::size_t vertices, ForEachKey forEachKey) {
  std::vector<std::size_t> start(vertices + 1, 0);
  forEachKey([&](std::uint32_t key) { ++start[std::size_t(key) + 1]; });
  for (std::size_t v = 0; v < vertices; ++v) start[v + 1] += start[v];
  return start;
}

}  // namespace

std::vector<std::int32_t> triangleNeighbours(const TriangleMesh& mesh) {
  const std::size_t n = mesh.triangles.size();
  if (n >= std::size_t(kFlippedNeighbour))
    throw InputError("triangle mesh", "triangles", std::to_string(n), "the triangle walk's neighbours take fewer than 2^30 triangles");
  const std::vector<std::uint32_t> weld = weldByPosition(mesh.positions);
  // Each triangle's welded corners, or none for a degenerate one (no neighbours).
  const auto corners = [&](std::size_t t, std::uint32_t (&w)[3]) {
    const auto& tri = mesh.triangles[t];
    w[0] = weld[tri[0]], w[1] = weld[tri[1]], w[2] = weld[tri[2]];
    return w[0] != w[1] && w[1] != w[2] && w[2] != w[0];
  };
  const std::vector<std::size_t> start = bucketStarts(mesh.positions.size(), [&](auto add) {
    std::uint32_t w[3];
    for (std::size_t t = 0; t < n; ++t)
      if (corners(t, w))
        for (int k = 0; k < 3; ++k) add(std::min(w[k], w[(k + 1) % 3]));
  });
  std::vector<EdgeEnd> ends(start.back());
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  std::uint32_t w[3];
  for (std::size_t t = 0; t < n; ++t)
    if (corners(t, w))
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = w[k], b = w[(k + 1) % 3];
        ends[fill[std::min(a, b)]++] = {std::max(a, b), std::uint32_t(3 * t + std::size_t(k)), a < b};
      }
  std::vector<std::int32_t> neighbours(3 * n, kNoNeighbour);
  // Buckets are disjoint and each link is written from its own bucket: parallel, deterministic.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.positions.size(), 4096),
                    [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t v = r.begin(); v != r.end(); ++v) {
      const auto first = ends.begin() + std::ptrdiff_t(start[v]), last = ends.begin() + std::ptrdiff_t(start[v + 1]);
      std::sort(first, last);
      for (auto b = first; b != last;) {
        auto e = b + 1;
        while (e != last && e->larger == b->larger) ++e;
        if (e - b == 2) {
          const std::int32_t flipped = b->forward == (b + 1)->forward ? kFlippedNeighbour : 0;
          neighbours[b->slot] = std::int32_t((b + 1)->slot / 3) | flipped;
          neighbours[(b + 1)->slot] = std::int32_t(b->slot / 3) | flipped;
        }
        b = e;
      }
    }
  });
  return neighbours;
}

// The edges bucketed by their smaller vertex index (counted, then filled: 4 bytes per edge and 16
// per vertex, linear time; a std::map here once took 64 bytes an edge and, under ASan, passed the
// fuzzer's 500 MB on a legal 118,000 triangle hemisphere), then each vertex's few larger ends
// sorted and read in pairs.
bool closedAsStored(std::span<const std::array<std::uint32_t, 3>> triangles, std::size_t vertices) {
  const auto valid = [](const std::array<std::uint32_t, 3>& t) { return t[0] != t[1] && t[1] != t[2] && t[2] != t[0]; };
  bool any = false;
  for (const auto& t : triangles) {
    SV_CHECK_LT(std::size_t(std::max({t[0], t[1], t[2]})), vertices);
    any = any || valid(t);
  }
  if (!any) return false;
  const std::vector<std::size_t> start = bucketStarts(vertices, [&](auto add) {
    for (const auto& t : triangles)
      if (valid(t))
        for (int k = 0; k < 3; ++k) add(std::min(t[k], t[(k + 1) % 3]));
  });
  std::vector<std::uint32_t> larger(start.back());
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (const auto& t : triangles)
    if (valid(t))
      for (int k = 0; k < 3; ++k) {
        const auto [a, b] = std::minmax(t[k], t[(k + 1) % 3]);
        larger[fill[a]++] = b;
      }
  std::atomic<bool> closed{true};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t v = r.begin(); v != r.end() && closed.load(std::memory_order_relaxed); ++v) {
      const auto b = larger.begin() + std::ptrdiff_t(start[v]), e = larger.begin() + std::ptrdiff_t(start[v + 1]);
      std::sort(b, e);
      for (auto k = b; k != e; k += 2)
        if (k + 1 == e || *k != *(k + 1) || (k + 2 != e && *(k + 2) == *k)) {
          closed.store(false, std::memory_order_relaxed);
          break;
        }
    }
  });
  return closed.load();
}

bool isClosedSurface(const TriangleMesh& mesh) {
  return closedAsStored(mesh) || closedByNeighbours(mesh, triangleNeighbours(mesh));
}

bool closedByNeighbours(const TriangleMesh& mesh, const std::vector<std::int32_t>& neighbours) {
  if (mesh.triangles.empty()) return false;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const glm::vec3 &a = mesh.positions[mesh.triangles[t][0]], &b = mesh.positions[mesh.triangles[t][1]],
                    &c = mesh.positions[mesh.triangles[t][2]];
    if (a == b || b == c || c == a) continue;  // degenerate: bounds nothing, has no neighbours
    for (int k = 0; k < 3; ++k)
      if (neighbours[3 * t + std::size_t(k)] == kNoNeighbour) return false;
  }
  return true;
}

namespace {

// Whether the triangle a, b, c lies on a line (removeExtraTriangles' rule).
bool flatTriangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
  const double height = glm::length(glm::cross(b - a, c - a)) / longest;  // twice the area over the base
  const double magnitude = std::max({std::abs(a.x), std::abs(a.y), std::abs(a.z), std::abs(b.x), std::abs(b.y),
                                     std::abs(b.z), std::abs(c.x), std::abs(c.y), std::abs(c.z)});
  return height <= std::max(1e-6 * longest, 4.0 * std::ldexp(magnitude, -24));
}

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
}

}  // namespace

ExtraTriangles removeExtraTriangles(TriangleMesh& mesh) {
  // A closed mesh has none to lose (two boxes stored apart that touch along a face, one inside
  // out, repeat a face once welded, and are closed as stored).
  if (isClosedSurface(mesh)) return {};
  const std::vector<std::uint32_t> weld = weldByPosition(mesh.positions);
  const std::size_t n = mesh.triangles.size();
  std::vector<std::array<std::uint32_t, 3>> welded(n);
  std::vector<bool> valid(n), drop(n, false);
  for (std::size_t t = 0; t < n; ++t) {
    const auto& tri = mesh.triangles[t];
    welded[t] = {weld[tri[0]], weld[tri[1]], weld[tri[2]]};
    const auto& w = welded[t];
    valid[t] = w[0] != w[1] && w[1] != w[2] && w[2] != w[0];
  }
  ExtraTriangles removed;
  // Repeats: the welded corners rotated to start at the smallest, sorted with the triangle's index,
  // so that the first of equal ones is kept (deterministic).
  std::vector<std::pair<std::array<std::uint32_t, 3>, std::uint32_t>> cycles;
  for (std::size_t t = 0; t < n; ++t) {
    if (!valid[t]) continue;
    auto w = welded[t];
    std::rotate(w.begin(), std::min_element(w.begin(), w.end()), w.end());
    cycles.push_back({w, std::uint32_t(t)});
  }
  std::sort(cycles.begin(), cycles.end());
  for (std::size_t k = 1; k < cycles.size(); ++k)
    if (cycles[k].first == cycles[k - 1].first) {
      drop[cycles[k].second] = true;
      ++removed.duplicates;
    }
  std::vector<std::uint64_t> edges;  // of the triangles kept so far, one entry per use
  edges.reserve(3 * n);
  for (std::size_t t = 0; t < n; ++t)
    if (valid[t] && !drop[t])
      for (int k = 0; k < 3; ++k) edges.push_back(edgeKey(welded[t][k], welded[t][(k + 1) % 3]));
  // Uses of each edge, counted down as flat triangles go (in index order: deterministic), so that
  // each is judged without those before it.
  std::sort(edges.begin(), edges.end());
  std::vector<std::uint64_t> keys;
  std::vector<std::uint32_t> uses;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    if (keys.empty() || keys.back() != edges[k]) keys.push_back(edges[k]), uses.push_back(0);
    ++uses.back();
  }
  const auto useOf = [&](std::uint64_t key) -> std::uint32_t& {
    return uses[std::size_t(std::lower_bound(keys.begin(), keys.end(), key) - keys.begin())];
  };
  for (std::size_t t = 0; t < n; ++t) {
    if (!valid[t] || drop[t]) continue;
    const auto& tri = mesh.triangles[t];
    if (!flatTriangle(glm::dvec3(mesh.positions[tri[0]]), glm::dvec3(mesh.positions[tri[1]]),
                      glm::dvec3(mesh.positions[tri[2]])))
      continue;
    const auto& w = welded[t];
    int odd = 0;  // its edges used an odd number of times, itself included: leaving it out evens them
    for (int k = 0; k < 3; ++k) odd += useOf(edgeKey(w[k], w[(k + 1) % 3])) % 2;
    if (odd >= 2) {
      drop[t] = true;
      ++removed.flat;
      for (int k = 0; k < 3; ++k) --useOf(edgeKey(w[k], w[(k + 1) % 3]));
    }
  }
  // A mesh of nothing else is left whole: emptied, it would lose the warnings about it.
  if (removed.total() == 0 || removed.total() == n) return {};
  std::size_t kept = 0;
  for (std::size_t t = 0; t < n; ++t)
    if (!drop[t]) mesh.triangles[kept++] = mesh.triangles[t];
  mesh.triangles.resize(kept);
  return removed;
}

}  // namespace shadowvol

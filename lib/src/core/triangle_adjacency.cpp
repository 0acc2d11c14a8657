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

struct DirectedEdge {
  std::uint64_t key;   // (smaller welded vertex << 32) | larger
  std::uint32_t slot;  // 3 t + k
  bool forward;        // runs from the smaller welded vertex to the larger
};

}  // namespace

std::vector<std::int32_t> triangleNeighbours(const TriangleMesh& mesh) {
  const std::size_t n = mesh.triangles.size();
  if (n >= std::size_t(kFlippedNeighbour))
    throw InputError("triangle mesh", "triangles", std::to_string(n), "the triangle walk's neighbours take fewer than 2^30 triangles");
  const std::vector<std::uint32_t> weld = weldByPosition(mesh.positions);
  std::vector<DirectedEdge> edges;
  edges.reserve(3 * n);
  for (std::size_t t = 0; t < n; ++t) {
    const auto& tri = mesh.triangles[t];
    const std::uint32_t w[3] = {weld[tri[0]], weld[tri[1]], weld[tri[2]]};
    if (w[0] == w[1] || w[1] == w[2] || w[2] == w[0]) continue;  // degenerate: no neighbours
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = w[k], b = w[(k + 1) % 3];
      edges.push_back({(std::uint64_t(std::min(a, b)) << 32) | std::max(a, b), std::uint32_t(3 * t + k), a < b});
    }
  }
  tbb::parallel_sort(edges.begin(), edges.end(),
                     [](const DirectedEdge& a, const DirectedEdge& b) { return std::tie(a.key, a.slot) < std::tie(b.key, b.slot); });
  std::vector<std::int32_t> neighbours(3 * n, kNoNeighbour);
  for (std::size_t b = 0; b < edges.size();) {
    std::size_t e = b + 1;
    while (e < edges.size() && edges[e].key == edges[b].key) ++e;
    if (e - b == 2) {
      const std::int32_t flipped = edges[b].forward == edges[b + 1].forward ? kFlippedNeighbour : 0;
      neighbours[edges[b].slot] = std::int32_t(edges[b + 1].slot / 3) | flipped;
      neighbours[edges[b + 1].slot] = std::int32_t(edges[b].slot / 3) | flipped;
    }
    b = e;
  }
  return neighbours;
}

// The edges bucketed by their smaller vertex index (counted, then filled: 4 bytes per edge and 16
// per vertex, linear time; a std::map here once took 64 bytes an edge and, under ASan, passed the
// fuzzer's 500 MB on a legal 118,000 triangle hemisphere), then each vertex's few larger ends
// sorted and read in pairs.
bool closedAsStored(const TriangleMesh& m) {
  const auto valid = [](const std::array<std::uint32_t, 3>& t) { return t[0] != t[1] && t[1] != t[2] && t[2] != t[0]; };
  std::size_t vertices = 0;
  for (const auto& t : m.triangles)
    if (valid(t)) vertices = std::max<std::size_t>(vertices, std::size_t(std::max({t[0], t[1], t[2]})) + 1);
  if (vertices == 0) return false;
  std::vector<std::size_t> start(vertices + 1, 0);
  for (const auto& t : m.triangles)
    if (valid(t))
      for (int k = 0; k < 3; ++k) ++start[std::size_t(std::min(t[k], t[(k + 1) % 3])) + 1];
  for (std::size_t v = 0; v < vertices; ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> larger(start[vertices]);
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (const auto& t : m.triangles)
    if (valid(t))
      for (int k = 0; k < 3; ++k) {
        const auto [a, b] = std::minmax(t[k], t[(k + 1) % 3]);
        larger[fill[a]++] = b;
      }
  std::atomic<bool> closed{true};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t v = r.begin(); v != r.end() && closed.load(std::memory_order_relaxed); ++v) {
      const auto b = larger.begin() + start[v], e = larger.begin() + start[v + 1];
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

}  // namespace shadowvol

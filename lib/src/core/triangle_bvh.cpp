#include "shadowvol/triangle_bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <glm/common.hpp>

#include "shadowvol/error.h"

namespace shadowvol {
namespace {

constexpr int kBins = 12;

struct Box {
  glm::vec3 lo{std::numeric_limits<float>::infinity()}, hi{-std::numeric_limits<float>::infinity()};
  void extend(const glm::vec3& p) { lo = glm::min(lo, p), hi = glm::max(hi, p); }
  void extend(const Box& b) { lo = glm::min(lo, b.lo), hi = glm::max(hi, b.hi); }
  bool empty() const { return lo.x > hi.x; }
  double area() const {
    if (empty()) return 0.0;
    const glm::dvec3 d = glm::dvec3(hi) - glm::dvec3(lo);
    return 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
};

struct Builder {
  const TriangleMesh& mesh;
  std::vector<Box> boxes;           // per triangle
  std::vector<glm::vec3> centres;   // per triangle
  std::vector<std::uint32_t> order;
  std::vector<BvhNode> nodes;
  int depth = 0;

  // The best split of order[begin, end) by binned SAH: true with the partition done and `mid`
  // set; false when a leaf is as good (or the centroids coincide).
  bool split(std::uint32_t begin, std::uint32_t end, const Box& bounds, std::uint32_t& mid) {
    Box c;
    for (std::uint32_t k = begin; k < end; ++k) c.extend(centres[order[k]]);
    const glm::vec3 extent = c.hi - c.lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const float scale = float(kBins) / extent[axis];
    if (!(extent[axis] > 0.0f) || !std::isfinite(scale)) return false;  // coincident (or denormal-near) centroids
    auto binOf = [&](std::uint32_t t) {
      return std::min(kBins - 1, std::max(0, int((centres[t][axis] - c.lo[axis]) * scale)));
    };
    std::array<Box, kBins> binBox;
    std::array<std::uint32_t, kBins> binCount{};
    for (std::uint32_t k = begin; k < end; ++k) {
      const int b = binOf(order[k]);
      binBox[b].extend(boxes[order[k]]);
      ++binCount[b];
    }
    std::array<double, kBins> rightCost{};
    Box acc;
    std::uint32_t n = 0;
    for (int b = kBins - 1; b > 0; --b) {
      acc.extend(binBox[b]);
      n += binCount[b];
      rightCost[b] = acc.area() * n;
    }
    double best = std::numeric_limits<double>::infinity();
    int bestBin = -1;
    acc = Box();
    n = 0;
    for (int b = 0; b < kBins - 1; ++b) {
      acc.extend(binBox[b]);
      n += binCount[b];
      const double cost = acc.area() * n + rightCost[b + 1];
      if (n > 0 && n < end - begin && cost < best) best = cost, bestBin = b;
    }
    const double leafCost = bounds.area() * double(end - begin);
    if (bestBin < 0 || (end - begin <= std::uint32_t(kBvhMaxLeafTriangles) && best >= leafCost)) return false;
    const auto it = std::stable_partition(order.begin() + begin, order.begin() + end,
                                          [&](std::uint32_t t) { return binOf(t) <= bestBin; });
    mid = std::uint32_t(it - order.begin());
    return mid > begin && mid < end;
  }

  void build(std::uint32_t node, std::uint32_t begin, std::uint32_t end, int level) {
    depth = std::max(depth, level + 1);
    Box bounds;
    for (std::uint32_t k = begin; k < end; ++k) bounds.extend(boxes[order[k]]);
    BvhNode& n = nodes[node];
    for (int a = 0; a < 3; ++a) n.lo[a] = bounds.lo[a], n.hi[a] = bounds.hi[a];
    std::uint32_t mid = 0;
    const bool mustSplit = end - begin > std::uint32_t(kBvhMaxLeafTriangles);
    if (level + 1 >= kBvhMaxDepth || !split(begin, end, bounds, mid)) {
      if (mustSplit && level + 1 < kBvhMaxDepth) {  // coincident centroids: halve by index
        mid = begin + (end - begin) / 2;
      } else {
        nodes[node].first = begin, nodes[node].count = end - begin;
        return;
      }
    }
    const auto child = std::uint32_t(nodes.size());
    nodes[node].first = child, nodes[node].count = 0;
    nodes.emplace_back();
    nodes.emplace_back();
    build(child, begin, mid, level + 1);
    build(child + 1, mid, end, level + 1);
  }
};

}  // namespace

TriangleBvh buildTriangleBvh(const TriangleMesh& mesh) {
  const std::size_t n = mesh.triangles.size();
  if (n >= (std::size_t(1) << 31))
    throw InputError("triangle bvh", "triangles", std::to_string(n), "at most 2^31 - 1 triangles");
  TriangleBvh out;
  if (n == 0) return out;
  Builder b{mesh, {}, {}, {}, {}, 0};
  b.boxes.resize(n);
  b.centres.resize(n);
  for (std::size_t t = 0; t < n; ++t) {
    Box box;
    for (std::uint32_t v : mesh.triangles[t]) box.extend(mesh.positions[v]);
    b.boxes[t] = box;
    b.centres[t] = 0.5f * (box.lo + box.hi);
  }
  b.order.resize(n);
  std::iota(b.order.begin(), b.order.end(), 0u);
  b.nodes.reserve(2 * n);
  b.nodes.emplace_back();
  b.build(0, 0, std::uint32_t(n), 0);
  out.nodes = std::move(b.nodes);
  out.order = std::move(b.order);
  out.triangles.resize(n);
  for (std::size_t k = 0; k < n; ++k) out.triangles[k] = mesh.triangles[out.order[k]];
  out.depth = b.depth;
  return out;
}

}  // namespace shadowvol

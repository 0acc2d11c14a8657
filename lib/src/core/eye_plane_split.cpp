#include "shadowvol/eye_plane_split.h"

#include "shadowvol/cube_map.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "shadowvol/scene.h"

namespace shadowvol {
namespace {

using Tri = std::array<std::uint32_t, 3>;
constexpr std::uint32_t kUnset = 0xffffffffu;

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t(a) << 32) | b;
}

double squaredLength(const TriangleMesh& m, std::uint32_t a, std::uint32_t b) {
  const glm::dvec3 d = glm::dvec3(m.positions[a]) - glm::dvec3(m.positions[b]);
  return glm::dot(d, d);
}

// The corner k such that edge (t[k], t[k+1]) is the longest; ties go to the lower k.
int longestEdge(const TriangleMesh& m, const Tri& t) {
  int best = 0;
  double len = -1.0;
  for (int k = 0; k < 3; ++k) {
    const double l = squaredLength(m, t[k], t[(k + 1) % 3]);
    if (l > len) best = k, len = l;
  }
  return best;
}

bool needsSplit(const TriangleMesh& m, const Tri& t, std::span<const EyePlane> planes) {
  for (const EyePlane& e : planes) {
    double lo = 1e300, hi = -1e300;
    for (auto v : t) {
      const double d = glm::dot(glm::dvec3(m.positions[v]) - e.eye, e.axis);
      lo = std::min(lo, d), hi = std::max(hi, d);
    }
    if (lo < e.nearPlane && hi > 0.0) {
      const int k = longestEdge(m, t);
      if (squaredLength(m, t[k], t[(k + 1) % 3]) > e.maxEdge * e.maxEdge) return true;
    }
  }
  return false;
}

// Triangle (p, q, r) with edge (p, q) split at s: (p, s, r), (s, q, r), same orientation.
void splitOn(std::uint32_t p, std::uint32_t q, std::uint32_t r, std::uint32_t s, std::vector<Tri>& out) {
  out.push_back({p, s, r});
  out.push_back({s, q, r});
}

// The edges to split this pass: the longest edge of every triangle that needs it, closed so that a
// triangle with any split edge has its longest one split too (what keeps the result conforming).
std::unordered_map<std::uint64_t, std::uint32_t> plannedSplits(const TriangleMesh& m, const std::vector<int>& longest,
                                                               std::span<const EyePlane> planes) {
  std::unordered_map<std::uint64_t, std::uint32_t> split;
  std::vector<std::uint64_t> work;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    if (!needsSplit(m, m.triangles[t], planes)) continue;
    const Tri& tri = m.triangles[t];
    const std::uint64_t key = edgeKey(tri[longest[t]], tri[(longest[t] + 1) % 3]);
    if (split.emplace(key, kUnset).second) work.push_back(key);
  }
  if (work.empty()) return split;
  std::unordered_multimap<std::uint64_t, std::uint32_t> trianglesOf;
  trianglesOf.reserve(3 * m.triangles.size());
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) trianglesOf.emplace(edgeKey(m.triangles[t][k], m.triangles[t][(k + 1) % 3]), std::uint32_t(t));
  while (!work.empty()) {
    const std::uint64_t e = work.back();
    work.pop_back();
    const auto [from, to] = trianglesOf.equal_range(e);
    for (auto it = from; it != to; ++it) {
      const Tri& tri = m.triangles[it->second];
      const int k = longest[it->second];
      const std::uint64_t key = edgeKey(tri[k], tri[(k + 1) % 3]);
      if (split.emplace(key, kUnset).second) work.push_back(key);
    }
  }
  return split;
}

enum class Pass { Done, Split, OverBudget };

// One pass: Done when nothing needs splitting, OverBudget (mesh unchanged) when the pass would
// exceed the budget.
Pass splitPass(TriangleMesh& m, std::span<const EyePlane> planes, std::size_t maxTriangles) {
  std::vector<int> longest(m.triangles.size());
  for (std::size_t t = 0; t < m.triangles.size(); ++t) longest[t] = longestEdge(m, m.triangles[t]);
  auto split = plannedSplits(m, longest, planes);
  if (split.empty()) return Pass::Done;
  std::size_t added = 0;
  for (const Tri& t : m.triangles)
    for (int k = 0; k < 3; ++k) added += split.count(edgeKey(t[k], t[(k + 1) % 3]));
  if (m.triangles.size() + added > maxTriangles) return Pass::OverBudget;
  // Midpoints in a fixed order (sorted keys), so the result does not depend on hashing.
  std::vector<std::uint64_t> keys;
  keys.reserve(split.size());
  for (const auto& [key, v] : split) keys.push_back(key);
  std::sort(keys.begin(), keys.end());
  for (std::uint64_t key : keys) {
    const auto a = std::uint32_t(key >> 32), b = std::uint32_t(key & 0xffffffffu);
    split[key] = std::uint32_t(m.positions.size());
    m.positions.push_back(glm::vec3(0.5 * (glm::dvec3(m.positions[a]) + glm::dvec3(m.positions[b]))));
  }
  auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
    const auto it = split.find(edgeKey(a, b));
    return it == split.end() ? kUnset : it->second;
  };
  std::vector<Tri> out;
  out.reserve(m.triangles.size() + added);
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const Tri& tri = m.triangles[t];
    const int k = longest[t];
    const std::uint32_t a = tri[k], b = tri[(k + 1) % 3], c = tri[(k + 2) % 3];
    const std::uint32_t mab = midpoint(a, b);
    if (mab == kUnset) {
      out.push_back(tri);
      continue;
    }
    // Bisect the longest edge, then each half's remaining original edge if it is split too.
    const std::uint32_t mca = midpoint(c, a), mbc = midpoint(b, c);
    if (mca == kUnset) out.push_back({a, mab, c});
    else splitOn(c, a, mab, mca, out);
    if (mbc == kUnset) out.push_back({mab, b, c});
    else splitOn(b, c, mab, mbc, out);
  }
  m.triangles = std::move(out);
  return Pass::Split;
}

}  // namespace

EyePlaneSplit splitAcrossEyePlanes(TriangleMesh& mesh, std::span<const EyePlane> planes, std::size_t maxTriangles) {
  const std::size_t before = mesh.triangles.size();
  // Each pass bisects the crossing triangles' longest edges; 128 passes bound the work.
  Pass last = Pass::Split;
  for (int pass = 0; pass < 128 && last == Pass::Split; ++pass) last = splitPass(mesh, planes, maxTriangles);
  return {mesh.triangles.size() - before, last == Pass::Done};
}

EyePlaneSplit splitSceneAcrossEyePlanes(Scene& scene, std::size_t maxTriangles) {
  std::vector<EyePlane> planes;
  const Camera& c = scene.camera;
  planes.push_back({c.eye, glm::normalize(c.target - c.eye), c.nearPlane, kEyePlaneEdgeRatio * c.nearPlane});
  const Light& l = scene.light;
  if (l.type == LightType::Spot)
    planes.push_back({l.position, glm::normalize(l.direction), l.nearPlane, kEyePlaneEdgeRatio * l.nearPlane});
  if (l.type == LightType::Point)  // the eye planes of its six cube faces
    for (int f = 0; f < kCubeFaces; ++f)
      planes.push_back({l.position, cubeFaceDirection(f), l.nearPlane, kEyePlaneEdgeRatio * l.nearPlane});
  EyePlaneSplit result;
  std::size_t total = scene.triangleCount();  // kept up to date below: once per object was quadratic
  for (auto& o : scene.objects) {
    const std::size_t room = std::min(maxTriangles > total ? maxTriangles - total : 0,
                                      kMaxEyePlaneTriangles - result.added);
    const EyePlaneSplit r = splitAcrossEyePlanes(o.mesh, planes, o.mesh.triangles.size() + room);
    result.added += r.added;
    total += r.added;
    result.complete = result.complete && r.complete;
  }
  return result;
}

}  // namespace shadowvol

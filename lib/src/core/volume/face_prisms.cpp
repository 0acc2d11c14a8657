#include "volume/face_prisms.h"

#include <bit>
#include <cstdint>
#include <numeric>
#include <unordered_map>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "shadowvol/check.h"

namespace shadowvol::volume {
namespace {

// The faces' corners welded by exact position: ids in order of first use.
struct WeldedFaces {
  std::vector<glm::dvec3> points;
  std::vector<std::array<std::uint32_t, 3>> faces;
};

struct PointHash {
  std::size_t operator()(const glm::dvec3& p) const {
    std::uint64_t h = 0;
    for (int k = 0; k < 3; ++k) h = (h ^ std::bit_cast<std::uint64_t>(p[k] + 0.0)) * 0x9E3779B97F4A7C15ull;
    return std::size_t(h ^ (h >> 29));
  }
};

WeldedFaces weld(std::span<const std::array<glm::dvec3, 3>> faces) {
  WeldedFaces w;
  std::unordered_map<glm::dvec3, std::uint32_t, PointHash> id;
  id.reserve(faces.size() * 2);
  for (const auto& f : faces) {
    std::array<std::uint32_t, 3> t{};
    for (int k = 0; k < 3; ++k) {
      const auto [it, added] = id.try_emplace(f[std::size_t(k)], std::uint32_t(w.points.size()));
      if (added) w.points.push_back(f[std::size_t(k)]);
      t[std::size_t(k)] = it->second;
    }
    w.faces.push_back(t);
  }
  return w;
}

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; }

// Union-find over the faces' corners (slot 3 f + k).
struct Fans {
  std::vector<std::uint32_t> parent;
  explicit Fans(std::size_t slots) : parent(slots) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t s) {
    while (parent[s] != s) s = parent[s] = parent[parent[s]];
    return s;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the smaller slot roots: deterministic
  }
};

// A point moved along its light ray to light-view depth `far` (the map's coordinates).
class FarProjector {
 public:
  FarProjector(const DepthMap& map, double far)
      : view_(map.lightView), invView_(glm::inverse(map.lightView)), far_(far),
        perspective_(map.lightType != LightType::Directional) {}
  glm::dvec3 operator()(const glm::dvec3& p) const {
    glm::dvec4 v = view_ * glm::dvec4(p, 1.0);
    if (perspective_) {
      const double s = far_ / -v.z;  // the apex is the view's origin: scale along the ray
      v.x *= s, v.y *= s;
    }
    v.z = -far_;
    return glm::dvec3(invView_ * v);
  }

 private:
  glm::dmat4 view_, invView_;
  double far_;
  bool perspective_;
};

}  // namespace

FacePrismCounts appendFacePrisms(const DepthMap& map, std::span<const std::array<glm::dvec3, 3>> faces,
                                 VolumeMesh& mesh) {
  FacePrismCounts counts;
  if (faces.empty()) return counts;
  const WeldedFaces w = weld(faces);
  const std::size_t n = w.faces.size();
  SV_CHECK_LT(3 * std::uint64_t(n), std::uint64_t(1) << 31);
  // Directed edges: how often each is used (more than once only where parts of a mesh touch).
  std::unordered_map<std::uint64_t, std::uint32_t> uses;
  uses.reserve(3 * n);
  for (const auto& f : w.faces)
    for (int k = 0; k < 3; ++k) ++uses[edgeKey(f[std::size_t(k)], f[std::size_t((k + 1) % 3)])];
  const auto inner = [&](std::uint32_t a, std::uint32_t b) {
    const auto ab = uses.find(edgeKey(a, b)), ba = uses.find(edgeKey(b, a));
    return ab != uses.end() && ab->second == 1 && ba != uses.end() && ba->second == 1;
  };
  // Corners joined across inner edges are one fan around their vertex.
  std::unordered_map<std::uint64_t, std::uint32_t> slotOfEdge;  // inner directed edge -> its first corner's slot
  slotOfEdge.reserve(3 * n);
  for (std::size_t f = 0; f < n; ++f)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = w.faces[f][std::size_t(k)], b = w.faces[f][std::size_t((k + 1) % 3)];
      if (inner(a, b)) slotOfEdge.emplace(edgeKey(a, b), std::uint32_t(3 * f + std::size_t(k)));
    }
  Fans fans(3 * n);
  const auto nextSlot = [](std::uint32_t s) { return s - s % 3 + (s % 3 + 1) % 3; };
  for (const auto& [key, s] : slotOfEdge) {
    const std::uint32_t a = std::uint32_t(key >> 32), b = std::uint32_t(key);
    if (a > b) continue;  // each pair once
    const std::uint32_t r = slotOfEdge.at(edgeKey(b, a));  // the reverse edge's slot: its corner b
    fans.unite(s, nextSlot(r));                            // both corners at a
    fans.unite(nextSlot(s), r);                            // both corners at b
  }
  // One near and one far vertex per fan, in order of the fans' root slots.
  std::vector<std::uint32_t> copy(3 * n, 0);
  std::vector<std::uint32_t> rootCopy(3 * n, UINT32_MAX);
  std::vector<std::uint32_t> copyPoint;
  for (std::uint32_t s = 0; s < 3 * n; ++s) {
    const std::uint32_t r = fans.find(s);
    if (rootCopy[r] == UINT32_MAX) {
      rootCopy[r] = std::uint32_t(copyPoint.size());
      copyPoint.push_back(w.faces[s / 3][s % 3]);
    }
    copy[s] = rootCopy[r];
  }
  const std::size_t copies = copyPoint.size();
  SV_CHECK_LT(mesh.positions.size() + 2 * copies, std::size_t(UINT32_MAX));
  const auto nearBase = std::uint32_t(mesh.positions.size()), farBase = std::uint32_t(nearBase + copies);
  const FarProjector toFar(map, map.farPlane);
  for (std::size_t c = 0; c < copies; ++c) mesh.positions.push_back(w.points[copyPoint[c]]);
  for (std::size_t c = 0; c < copies; ++c) mesh.positions.push_back(toFar(w.points[copyPoint[c]]));
  mesh.partStarts.push_back(mesh.triangles.size());
  const std::size_t first = mesh.triangles.size();
  for (std::size_t f = 0; f < n; ++f) {  // near caps: the face as it is, its front towards the light
    const std::uint32_t* s = &copy[3 * f];
    mesh.triangles.push_back({nearBase + s[0], nearBase + s[1], nearBase + s[2]});
  }
  for (std::size_t f = 0; f < n; ++f) {  // far caps, reversed: their front away from the light
    const std::uint32_t* s = &copy[3 * f];
    mesh.triangles.push_back({farBase + s[0], farBase + s[2], farBase + s[1]});
  }
  for (std::size_t f = 0; f < n; ++f)  // walls on the border edges a -> b: near b, near a, far a, far b
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = w.faces[f][std::size_t(k)], b = w.faces[f][std::size_t((k + 1) % 3)];
      if (inner(a, b)) continue;
      const std::uint32_t sa = copy[3 * f + std::size_t(k)], sb = copy[3 * f + std::size_t((k + 1) % 3)];
      mesh.triangles.push_back({nearBase + sb, nearBase + sa, farBase + sa});
      mesh.triangles.push_back({nearBase + sb, farBase + sa, farBase + sb});
      ++counts.walls;
    }
  counts.faces = n;
  counts.triangles = mesh.triangles.size() - first;
  return counts;
}

}  // namespace shadowvol::volume

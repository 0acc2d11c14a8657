#include "clip_volume.h"

#include <algorithm>
#include <array>
#include <cstdio>

#include <glm/vec4.hpp>

namespace shadowvol::detail {

namespace {

// The signed distance of clip-space point c from plane k of the clip volume (>= 0 inside):
// w - x, w + x, w - y, w + y, w - z (far), w + z (near).
double planeDistance(const glm::dvec4& c, int k) {
  const double v = k < 2 ? c.x : (k < 4 ? c.y : c.z);
  return c.w + ((k & 1) ? v : -v);
}

// Whether the triangle a, b, c (clip space) keeps any part inside the clip volume: clipped
// against each plane in turn (Sutherland-Hodgman in homogeneous coordinates), until nothing is
// left or all six planes are passed. A triangle touching the volume only on its boundary counts.
bool triangleMeetsClipVolume(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c) {
  std::array<glm::dvec4, 9> poly{a, b, c}, next{};  // each plane adds at most one vertex
  std::size_t n = 3;
  for (int k = 0; k < 6 && n > 0; ++k) {
    std::size_t m = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const glm::dvec4 &p = poly[i], &q = poly[(i + 1) % n];
      const double dp = planeDistance(p, k), dq = planeDistance(q, k);
      if (dp >= 0.0) next[m++] = p;
      if ((dp >= 0.0) != (dq >= 0.0)) next[m++] = p + (dp / (dp - dq)) * (q - p);
    }
    poly = next;
    n = m;
  }
  return n > 0;
}

}  // namespace

bool outsideClipVolume(const glm::dmat4& worldToClip, const TriangleMesh& mesh) {
  if (mesh.positions.empty()) return false;
  std::vector<glm::dvec4> clip(mesh.positions.size());
  std::array<bool, 6> allBeyond;  // x > w, -x > w, y > w, -y > w, z > w (far), -z > w (near)
  allBeyond.fill(true);
  for (std::size_t v = 0; v < clip.size(); ++v) {
    const glm::dvec4 c = clip[v] = worldToClip * glm::dvec4(glm::dvec3(mesh.positions[v]), 1.0);
    const std::array<bool, 6> beyond = {c.x > c.w, -c.x > c.w, c.y > c.w, -c.y > c.w, c.z > c.w, -c.z > c.w};
    for (std::size_t k = 0; k < beyond.size(); ++k) allBeyond[k] = allBeyond[k] && beyond[k];
  }
  if (std::any_of(allBeyond.begin(), allBeyond.end(), [](bool b) { return b; })) return true;
  // The hull straddles the planes: outside only when no triangle reaches inside (regression of a
  // hostile-input probe: a near/far range between a ball and a tilted ground gave no warning).
  if (mesh.triangles.empty()) return false;  // nothing to judge by
  return std::none_of(mesh.triangles.begin(), mesh.triangles.end(), [&](const std::array<std::uint32_t, 3>& t) {
    return triangleMeetsClipVolume(clip[t[0]], clip[t[1]], clip[t[2]]);
  });
}

std::string emptyViewWarning(const glm::dmat4& worldToClip, const std::vector<SceneObject>& objects,
                             const std::string& what, double nearPlane, double farPlane,
                             const std::string& consequence) {
  if (!std::all_of(objects.begin(), objects.end(),
                   [&](const SceneObject& o) { return outsideClipVolume(worldToClip, o.mesh); }))
    return {};
  char planes[160];
  std::snprintf(planes, sizeof planes, " (between its near plane at %.6g and its far plane at %.6g world units): ",
                nearPlane, farPlane);
  return "no object lies " + what + planes + consequence;
}

}  // namespace shadowvol::detail

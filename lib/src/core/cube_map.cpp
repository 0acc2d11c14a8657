#include "shadowvol/cube_map.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "shadowvol/check.h"
#include "shadowvol/error.h"

namespace shadowvol {
namespace {

struct FaceAxes {
  const char* name;
  glm::dvec3 d, u;
};
// OpenGL's cube-map table (cube_map.h).
constexpr FaceAxes kFaces[kCubeFaces] = {
    {"+x", {1, 0, 0}, {0, -1, 0}}, {"-x", {-1, 0, 0}, {0, -1, 0}}, {"+y", {0, 1, 0}, {0, 0, 1}},
    {"-y", {0, -1, 0}, {0, 0, -1}}, {"+z", {0, 0, 1}, {0, -1, 0}}, {"-z", {0, 0, -1}, {0, -1, 0}},
};

const FaceAxes& axes(int face) {
  SV_CHECK(face >= 0 && face < kCubeFaces);
  return kFaces[face];
}

}  // namespace

const char* cubeFaceName(int face) { return axes(face).name; }
glm::dvec3 cubeFaceDirection(int face) { return axes(face).d; }
glm::dvec3 cubeFaceUp(int face) { return axes(face).u; }

Light cubeFaceLight(const Light& point, int face) {
  Light l = point;
  l.type = LightType::Spot;
  l.direction = cubeFaceDirection(face);
  l.up = cubeFaceUp(face);
  l.fovYDegrees = 90.0;
  l.fitPosition = false;
  return l;
}

Light guardedCubeFaceLight(const Light& point, int face, int n, int guard) {
  SV_CHECK(n >= 1 && guard >= 0);
  Light l = cubeFaceLight(point, face);
  const double t = double(n + 2 * guard) / double(n);  // tan of the half-opening
  l.fovYDegrees = 2.0 * glm::degrees(std::atan(t));
  // A point in the guard band lies in a neighbouring face, whose depth of it (its largest offset
  // component, at least the fitted near) is at most t times this face's: the near plane comes
  // closer by t, so no geometry that the fit holds is clipped in the band (a second reader's
  // finding: near 99.49, a point at (100.5, 0, 99) in the +z face's band at depth 99).
  l.nearPlane = point.nearPlane / t;
  return l;
}

glm::dvec3 cubeTexelDirection(int n, int face, double i, double j) {
  const FaceAxes& f = axes(face);
  const double x = (i + 0.5) / n * 2.0 - 1.0, y = (j + 0.5) / n * 2.0 - 1.0;
  return f.d + x * glm::cross(f.d, f.u) + y * f.u;
}

double cubeDepth(const glm::dvec3& offset) {
  return std::max({std::abs(offset.x), std::abs(offset.y), std::abs(offset.z)});
}

CubeLookup cubeLookup(const glm::dvec3& offset, int n) {
  const double ax = std::abs(offset.x), ay = std::abs(offset.y), az = std::abs(offset.z);
  const int axis = (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
  const int face = 2 * axis + (offset[axis] < 0.0 ? 1 : 0);
  const FaceAxes& f = kFaces[face];
  const double depth = glm::dot(offset, f.d);
  CubeLookup r;
  r.face = face;
  r.depth = depth;
  if (!(depth > 0.0)) return r;  // the light's own position: face +x, texel (0, 0) by convention
  const glm::dvec3 right = glm::cross(f.d, f.u);
  const double s = glm::dot(offset, right) / depth, t = glm::dot(offset, f.u) / depth;
  r.texel = {(s + 1.0) * 0.5 * n - 0.5, (t + 1.0) * 0.5 * n - 0.5};
  return r;
}

CubeTexel cubeTexelAcross(int n, int face, int i, int j, int di, int dj) {
  SV_CHECK((di == 0) != (dj == 0) && std::abs(di + dj) == 1);
  SV_CHECK(i >= 0 && j >= 0 && i < n && j < n);
  SV_CHECK(i + di < 0 || i + di >= n || j + dj < 0 || j + dj >= n);
  const FaceAxes& f = axes(face);
  const glm::dvec3 right = glm::cross(f.d, f.u);
  const double a = (i + 0.5) / n * 2.0 - 1.0, b = (j + 0.5) / n * 2.0 - 1.0;
  // The texel centre's direction a R + b U + D, folded over the edge: the coordinate across the
  // edge and the face axis swap roles, so the distance from the edge is kept.
  const glm::dvec3 q = di != 0 ? double(di) * right + b * f.u + (double(di) * a) * f.d
                               : a * right + double(dj) * f.u + (double(dj) * b) * f.d;
  const CubeLookup l = cubeLookup(q, n);
  const auto index = [n](double x) { return std::clamp(int(std::lround(x)), 0, n - 1); };
  return {l.face, index(l.texel.x), index(l.texel.y)};
}

glm::dvec3 CubeDepthMap::lightPosition() const {
  const glm::dmat4 inv = glm::inverse(faces[0].lightView);
  return glm::dvec3(inv[3]);
}

CubeDepthMap makeCubeDepthMap(const Light& point, int n, CaptureMode capture) {
  SV_CHECK(point.type == LightType::Point);
  // The six faces together are held to one map's limit (kCubeFaces * N a side): N <= 2730.
  constexpr int kMaxFaceSide = kMaxWindowSide / kCubeFaces;
  if (n > kMaxFaceSide)
    throw InputError("cube map", "N", std::to_string(n),
                     "a point light's cube map holds six faces of N x N texels, held together to the limit of " +
                         std::to_string(kMaxWindowSide) + " texels a side: N may be at most " +
                         std::to_string(kMaxFaceSide));
  checkDepthMapSize(n, kCubeFaces * n, "cube map", "N");
  CubeDepthMap cube;
  for (int f = 0; f < kCubeFaces; ++f) cube.faces[f] = makeDepthMap(cubeFaceLight(point, f), n, n, capture);
  return cube;
}

}  // namespace shadowvol

// Shared pieces of the GL tests: one renderer for the whole test program (creating a context and
// compiling the shaders once), programmatic scenes, and small image helpers.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "shadowvol/embree/embree_scene.h"
#include "shadowvol/embree/ray_queries.h"
#include "shadowvol/gl/renderer.h"
#include "shadowvol/primitives.h"
#include "shadowvol/scene.h"

namespace shadowvol::gltest {

inline gl::Renderer& sharedRenderer() {
  static gl::Renderer renderer;
  return renderer;
}

inline SceneObject translated(std::string name, std::string type, TriangleMesh mesh, glm::vec3 offset) {
  for (auto& p : mesh.positions) p += offset;
  return SceneObject{std::move(name), std::move(type), std::move(mesh)};
}

/// A closed square plate (2 x 0.1 x 2, centre at height 2) over a single-sided 10 x 10 ground,
/// under a slightly tilted directional light (fitted box). The camera is set by the caller.
inline Scene plateScene() {
  Scene s;
  s.source = "plate (test)";
  s.objects.push_back(SceneObject{"ground", "plane", makePlane(10.0, 10.0, 1)});
  s.objects.push_back(translated("plate", "box", makeBox(2.0, 0.1, 2.0), {0.13f, 2.0f, -0.07f}));
  s.light.type = LightType::Directional;
  s.light.direction = glm::normalize(glm::dvec3(0.15, -1.0, 0.1));
  s.light.fitPosition = true;
  s.camera.eye = {0.0, 8.0, 7.0};
  s.camera.target = {0.0, 0.0, 0.0};
  s.camera.width = 192;
  s.camera.height = 144;
  fitLightAndCamera(s);
  return s;
}

/// Several closed bodies on a closed ground slab under a spot light: a sphere, a box, a tree (a
/// thin trunk), so the volume has steep walls, thin occluders and flat regions.
/// The plate of plateScene() as an axis-aligned box, world space.
constexpr glm::dvec3 kPlateMin{-0.87, 1.95, -1.07}, kPlateMax{1.13, 2.05, 0.93};

/// Slab test of the ray o + t dir against the plate box: the entry and exit parameters of the
/// part of the ray inside the box (clipped to [tMin, tMax]), or nullopt when it misses.
inline std::optional<std::pair<double, double>> rayThroughPlate(const glm::dvec3& o, const glm::dvec3& dir,
                                                                double tMin = -1e300, double tMax = 1e300) {
  double t0 = tMin, t1 = tMax;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(dir[a]) < 1e-300) {
      if (o[a] < kPlateMin[a] || o[a] > kPlateMax[a]) return std::nullopt;
      continue;
    }
    double ta = (kPlateMin[a] - o[a]) / dir[a], tb = (kPlateMax[a] - o[a]) / dir[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (t0 > t1) return std::nullopt;
  return std::make_pair(t0, t1);
}

/// Where the camera ray through window point (wx, wy) (pixels, y up) meets the plate scene's
/// ground (y = 0, |x|, |z| <= 4.9): nullopt when it misses the ground, when the point lies
/// outside the camera's [near, far] (with 0.1 % margin), or when the plate hides it.
struct GroundHit {
  glm::dvec3 eyeRayOrigin, eyeRayDirection, ground;
};
inline std::optional<GroundHit> visibleGround(const Camera& cam, double wx, double wy) {
  const glm::dmat4 inv = glm::inverse(cameraProjection(cam) * cameraView(cam));
  const glm::dvec3 fwd = glm::normalize(cam.target - cam.eye);
  const double nx = wx / cam.width * 2.0 - 1.0, ny = wy / cam.height * 2.0 - 1.0;
  const glm::dvec4 a = inv * glm::dvec4(nx, ny, -1.0, 1.0), b = inv * glm::dvec4(nx, ny, 1.0, 1.0);
  const glm::dvec3 o = glm::dvec3(a) / a.w, dir = glm::dvec3(b) / b.w - o;
  if (!(dir.y < 0.0)) return std::nullopt;
  const double tg = -o.y / dir.y;
  const glm::dvec3 g = o + tg * dir;
  if (std::abs(g.x) > 4.9 || std::abs(g.z) > 4.9) return std::nullopt;
  const double depth = glm::dot(g - cam.eye, fwd);
  if (depth < cam.nearPlane * 1.001 || depth > cam.farPlane * 0.999) return std::nullopt;
  if (rayThroughPlate(o, dir, 0.0, tg)) return std::nullopt;  // the plate is in the way
  return GroundHit{o, dir, g};
}

inline Scene clutterScene() {
  Scene s;
  s.source = "clutter (test)";
  s.objects.push_back(translated("ground", "box", makeBox(12.0, 0.2, 12.0), {0.0f, -0.1f, 0.0f}));
  s.objects.push_back(translated("sphere", "sphere", makeIcoSphere(1.0, 3), {-1.0f, 1.6f, 0.5f}));
  s.objects.push_back(translated("box", "box", makeBox(1.2, 1.0, 0.8), {1.8f, 0.5f, -0.6f}));
  s.objects.push_back(translated("tree", "tree", makeTree(0.12, 1.5, 0.6, 2), {0.4f, 0.0f, 2.0f}));
  s.light.type = LightType::Spot;
  s.light.position = {2.5, 8.0, 3.0};
  s.light.direction = glm::normalize(glm::dvec3(0.0, 0.5, 0.0) - s.light.position);
  s.light.fovYDegrees = 70.0;
  s.camera.eye = {-2.0, 6.5, 9.0};
  s.camera.target = {0.3, 0.5, 0.0};
  s.camera.width = 192;
  s.camera.height = 144;
  fitLightAndCamera(s);
  return s;
}

/// Share of equal bytes of two equally sized buffers.
inline double agreement(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  if (a.size() != b.size() || a.empty()) return 0.0;
  std::size_t same = 0;
  for (std::size_t k = 0; k < a.size(); ++k) same += a[k] == b[k];
  return double(same) / double(a.size());
}

/// The pixels (rows top first, the scene camera's size) whose visible point lies inside the
/// light's frustum: where a z-pass stencil means what a z-fail one does (zpass.h); elsewhere
/// (background, beyond the light) it counts faces the lighting ignores. Embree primary rays.
inline std::vector<char> insideLightMask(const Scene& scene, double lightAspect = 1.0) {
  const EmbreeDevice device;
  std::vector<const TriangleMesh*> meshes;
  for (const auto& o : scene.objects) meshes.push_back(&o.mesh);
  const EmbreeScene rt(device, meshes);
  const CameraHits hits = castPrimaryRays(rt, scene.camera);
  const glm::dmat4 toClip = lightProjection(scene.light, lightAspect) * lightView(scene.light);
  std::vector<char> mask(hits.depth.size(), 0);
  for (std::size_t k = 0; k < mask.size(); ++k) {
    if (hits.isBackground(k)) continue;
    const glm::dvec4 c = toClip * glm::dvec4(hits.point[k], 1.0);
    mask[k] = c.w > 0 && std::abs(c.x) <= c.w && std::abs(c.y) <= c.w && std::abs(c.z) <= c.w;
  }
  return mask;
}

/// Whether `triangles` is what the GPU volume draws (exact cap) for `quads` kept quads: two sheet
/// triangles each and, with z-fail, two cap triangles each; except that the indexed way
/// (volume_index.frag) draws the cap of each block of 8 x 4 kept quads as one fan of 24 triangles
/// (40 fewer). `someFan`: at least one such block is expected.
inline ::testing::AssertionResult gpuVolumeTrianglesFit(std::size_t triangles, std::size_t quads, bool zfail,
                                                        bool indexed, bool someFan = false) {
  const std::size_t perQuad = (zfail ? 4 : 2) * quads;
  if (!zfail || !indexed) {
    if (triangles == perQuad) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << triangles << " triangles for " << quads << " quads, expected " << perQuad;
  }
  if (triangles > perQuad || (perQuad - triangles) % 40 != 0 || (someFan && triangles == perQuad))
    return ::testing::AssertionFailure() << triangles << " triangles for " << quads
                                         << " quads: not 4 per quad less 40 per fan" << (someFan ? " (a fan expected)" : "");
  return ::testing::AssertionSuccess();
}

/// agreement() over the pixels where mask is set.
inline double agreementWhere(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b,
                             const std::vector<char>& mask) {
  if (a.size() != b.size() || a.size() != mask.size()) return 0.0;
  std::size_t same = 0, n = 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (mask[k]) n += 1, same += a[k] == b[k];
  return n ? double(same) / double(n) : 0.0;
}

/// Calls visit(row, c) for every pixel of a w x h image (rows top first) whose class
/// c = classify(wx, wy) (window coordinates of the pixel centre, y up; c < 0: not tested) is
/// also the class of its 8 neighbours: pixels at a class border are skipped.
template <class Classify, class Visit>
void forEachPixelAwayFromBorders(int w, int h, Classify classify, Visit visit) {
  for (int row = 0; row < h; ++row) {
    const int y = h - 1 - row;  // GL window row of image row `row`
    for (int x = 0; x < w; ++x) {
      const int c = classify(x + 0.5, y + 0.5);
      if (c < 0) continue;
      bool border = false;
      for (int dy = -1; dy <= 1 && !border; ++dy)
        for (int dx = -1; dx <= 1 && !border; ++dx) border = classify(x + 0.5 + dx, y + 0.5 + dy) != c;
      if (!border) visit(std::size_t(row) * w + x, c);
    }
  }
}

}  // namespace shadowvol::gltest

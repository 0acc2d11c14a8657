#include <cmath>
#include <utility>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "shadowvol/embree/ray_queries.h"
#include "shadowvol/primitives.h"

namespace shadowvol {
namespace {

// A camera looking from `eye` at `target`, y up, 160 x 120 pixels, near 0.5, far 30.
Camera lookingAt(const glm::dvec3& eye, const glm::dvec3& target, double fovYDegrees) {
  Camera c;
  c.eye = eye;
  c.target = target;
  c.up = {0, 1, 0};
  c.fovYDegrees = fovYDegrees;
  c.width = 160;
  c.height = 120;
  c.nearPlane = 0.5;
  c.farPlane = 30;
  return c;
}

// An 8 x 8 ground plane and `occluder` (of `type`) lifted by `height` over it; no light yet.
Scene overGround(const char* name, const char* type, TriangleMesh occluder, float height) {
  Scene s;
  s.objects.push_back({"ground", "plane", makePlane(8, 8, 1)});
  for (auto& p : occluder.positions) p.y += height;
  s.objects.push_back({name, type, std::move(occluder)});
  return s;
}

// The plate scene: a 2 x 2 plate at y = 1.5 over a ground plane, light straight down.
Scene plateScene() {
  Scene s = overGround("plate", "box", makeBox(2, 0.1, 2), 1.5f);
  s.light.type = LightType::Directional;
  s.light.direction = {0, -1, 0};
  s.light.position = {0, 5, 0};
  s.light.halfExtent = 3;  // the ground beyond |x| or |z| > 3 is outside the light
  s.light.nearPlane = 0.5;
  s.light.farPlane = 6;
  s.camera = lookingAt({6, 5, 4.5}, {0, 0, 0}, 60);  // from the side: the ground under the plate is visible
  return s;
}

std::vector<const TriangleMesh*> meshesOf(const Scene& s) {
  std::vector<const TriangleMesh*> m;
  for (const auto& o : s.objects) m.push_back(&o.mesh);
  return m;
}

// A scene's Embree copy and its camera's primary hits.
struct Cast {
  EmbreeDevice device;
  EmbreeScene rt;
  CameraHits hits;
  explicit Cast(const Scene& s) : rt(device, meshesOf(s)), hits(castPrimaryRays(rt, s.camera)) {}
};

TEST(RayQueries, ExactShadowsOfThePlateMatchItsFootprint) {
  const Scene s = plateScene();
  const Cast c(s);
  const CameraHits& hits = c.hits;
  const auto cls = exactShadows(c.rt, s, hits);
  int shadowed = 0, lit = 0, outside = 0, checked = 0;
  const double margin = 0.15;  // more than a pixel's footprint on the ground here
  for (std::size_t k = 0; k < cls.size(); ++k) {
    if (hits.isBackground(k)) {
      EXPECT_EQ(cls[k], PixelClass::Background);
      continue;
    }
    const glm::dvec3 p = hits.point[k];
    if (std::abs(p.y) > 1e-4) continue;  // the plate itself
    const double m = std::max(std::abs(p.x), std::abs(p.z));
    if (std::abs(m - 1.0) < margin || std::abs(m - 3.0) < margin) continue;  // near an edge
    ++checked;
    const PixelClass want = m < 1.0 ? PixelClass::Shadowed : (m < 3.0 ? PixelClass::Lit : PixelClass::OutsideLight);
    EXPECT_EQ(int(cls[k]), int(want)) << p.x << " " << p.z;
    shadowed += cls[k] == PixelClass::Shadowed;
    lit += cls[k] == PixelClass::Lit;
    outside += cls[k] == PixelClass::OutsideLight;
  }
  EXPECT_GT(checked, 1000);
  EXPECT_GT(shadowed, 100);
  EXPECT_GT(lit, 100);
  EXPECT_GT(outside, 100);
}

// A square sheet (2 x 2, no thickness) at height 0.1 over the ground, lit at 3 degrees above the
// horizon: its shadow is the square moved 0.1 / tan 3 degrees = 1.91 along x, and a start offset
// d along the ground's normal moves the shadow's edges across x by d / tan 3 degrees (19 d).
Scene grazedSheetScene() {
  Scene s = overGround("sheet", "plane", makePlane(2, 2, 1), 0.1f);
  const double a = 3.0 * M_PI / 180.0;
  s.light.type = LightType::Directional;
  s.light.direction = {std::cos(a), -std::sin(a), 0.0};
  s.light.position = -30.0 * s.light.direction;
  s.light.halfExtent = 20;
  s.light.nearPlane = 0.1;
  s.light.farPlane = 100;
  s.camera = lookingAt({1.9, 6, 5}, {1.9, 0, 0}, 45);
  return s;
}

// Ground pixels whose exact class is known analytically with a margin of 1e-3 (in the sheet's
// plane), and how many of them `cls` gets wrong.
int groundPixelsWrong(const Scene& s, const CameraHits& hits, const std::vector<PixelClass>& cls, int* checked) {
  const glm::dvec3 d = s.light.direction;
  int wrong = 0;
  *checked = 0;
  for (std::size_t k = 0; k < cls.size(); ++k) {
    if (hits.isBackground(k) || std::abs(hits.point[k].y) > 1e-6) continue;
    const glm::dvec3 onSheet = hits.point[k] - (0.1 / -d.y) * d;  // back along the light to y = 0.1
    const double m = std::max(std::abs(onSheet.x), std::abs(onSheet.z));
    if (std::abs(m - 1.0) < 1e-3) continue;
    ++*checked;
    wrong += cls[k] != (m < 1.0 ? PixelClass::Shadowed : PixelClass::Lit);
  }
  return wrong;
}

// Regression (docs/results/reference-offset): the legacy reference started each shadow ray 1e-4 of
// the scene's radius (5.7e-4 here) off the surface, which moves this shadow's edges by 0.011 and
// called lit a band of shadowed pixels along them; the default starts at round-off's floor.
TEST(RayQueries, ExactShadowsOfASheetLitAtAGrazingAngleMatchTheAnalyticShadow) {
  const Scene s = grazedSheetScene();
  const Cast c(s);
  int checked = 0;
  EXPECT_EQ(groundPixelsWrong(s, c.hits, exactShadows(c.rt, s, c.hits), &checked), 0);
  EXPECT_GT(checked, 10000);
  const int legacyWrong =
      groundPixelsWrong(s, c.hits, exactShadows(c.rt, s, c.hits, shadowRayOffset(s)), &checked);
  EXPECT_GT(legacyWrong, 0);  // 5 pixels with Embree 3.13
}

// No acne: every point of a convex mesh that faces the light is lit, at the origin and far from it,
// though the shadow rays start only a few float spacings off the surface.
TEST(RayQueries, ExactShadowsLightEveryPointOfALitSphereFacingTheLight) {
  for (const double away : {0.0, 1e3}) {
    Scene s;
    TriangleMesh ball = makeIcoSphere(1.0, 5);
    for (auto& p : ball.positions) p += glm::vec3(float(away));
    s.objects.push_back({"ball", "sphere", ball});
    s.light.type = LightType::Directional;
    s.light.direction = glm::normalize(glm::dvec3(0.3, -1.0, 0.2));
    s.light.position = glm::dvec3(away) - 10.0 * s.light.direction;
    s.light.halfExtent = 2;
    s.light.nearPlane = 1;
    s.light.farPlane = 20;
    s.camera = lookingAt(glm::dvec3(away) + glm::dvec3(1.0, 2.0, 3.0), glm::dvec3(away), 45);
    const Cast c(s);
    const std::vector<PixelClass> cls = exactShadows(c.rt, s, c.hits);
    int lit = 0, shadowed = 0;
    for (PixelClass c : cls) {
      lit += c == PixelClass::Lit;
      shadowed += c == PixelClass::Shadowed;
    }
    EXPECT_EQ(shadowed, 0) << away;
    EXPECT_GT(lit, 3000) << away;
  }
}

TEST(RayQueries, PrimaryRaysSampleGlPixelCentresTopRowFirst) {
  Scene s = plateScene();
  const EmbreeDevice device;
  const EmbreeScene rt(device, meshesOf(s));
  const CameraHits hits = castPrimaryRays(rt, s.camera);
  // Project each visible point back with the camera matrices: it lands on its pixel's centre.
  const glm::dmat4 vp = cameraProjection(s.camera) * cameraView(s.camera);
  for (int r = 0; r < hits.height; r += 7)
    for (int x = 0; x < hits.width; x += 5) {
      const std::size_t k = std::size_t(r) * hits.width + x;
      if (hits.isBackground(k)) continue;
      const glm::dvec4 c = vp * glm::dvec4(hits.point[k], 1.0);
      const double px = (c.x / c.w + 1) * 0.5 * hits.width, py = (c.y / c.w + 1) * 0.5 * hits.height;
      EXPECT_NEAR(px, x + 0.5, 1e-3);
      EXPECT_NEAR(py, (hits.height - 1 - r) + 0.5, 1e-3);  // GL rows count from the bottom
    }
}

// A closed "volume": a box from z = -1 to z = -3 in front of a camera at the origin looking down
// -Z, whose front face is a grid with a vertex exactly on every pixel-centre ray, so those rays
// pass through vertices shared by up to six triangles and along shared edges.
TEST(RayQueries, CrossingsThroughSharedVerticesAndEdgesCountOnce) {
  const int n = 8;  // 8 x 8 pixels, fov 90: pixel centres at NDC -0.875 + 0.25 k
  Camera cam;
  cam.eye = {0, 0, 0};
  cam.target = {0, 0, -1};
  cam.up = {0, 1, 0};
  cam.fovYDegrees = 90;
  cam.width = n;
  cam.height = n;
  cam.nearPlane = 0.1;
  cam.farPlane = 100;
  TriangleMesh vol;
  auto vtx = [&](double x, double y, double z) {
    vol.positions.emplace_back(float(x), float(y), float(z));
    return std::uint32_t(vol.positions.size() - 1);
  };
  // Front face z = -1 facing +Z (towards the camera): grid of (n + 2)^2 vertices over [-1.125, 1.125].
  const int g = n + 2;
  std::vector<std::uint32_t> front(g * g);
  for (int j = 0; j < g; ++j)
    for (int i = 0; i < g; ++i) front[j * g + i] = vtx(-1.125 + 0.25 * i, -1.125 + 0.25 * j, -1.0);
  for (int j = 0; j + 1 < g; ++j)
    for (int i = 0; i + 1 < g; ++i) {
      const auto a = front[j * g + i], b = front[j * g + i + 1], c = front[(j + 1) * g + i + 1], d = front[(j + 1) * g + i];
      vol.triangles.push_back({a, b, c});  // counter-clockwise seen from +Z
      vol.triangles.push_back({a, c, d});
    }
  // Back face z = -3 and the four sides, scaled by 3 so the box is a frustum along the view rays.
  std::vector<std::uint32_t> back(4);
  const double e = 1.125;
  const double corners[4][2] = {{-e, -e}, {e, -e}, {e, e}, {-e, e}};
  for (int k = 0; k < 4; ++k) back[k] = vtx(3 * corners[k][0], 3 * corners[k][1], -3.0);
  vol.triangles.push_back({back[0], back[2], back[1]});  // facing -Z
  vol.triangles.push_back({back[0], back[3], back[2]});
  // Sides: the front rim runs along the grid border.
  std::vector<std::uint32_t> rim;
  for (int i = 0; i < g - 1; ++i) rim.push_back(front[i]);                      // bottom, left to right
  for (int j = 0; j < g - 1; ++j) rim.push_back(front[j * g + g - 1]);          // right, upwards
  for (int i = g - 1; i > 0; --i) rim.push_back(front[(g - 1) * g + i]);        // top, right to left
  for (int j = g - 1; j > 0; --j) rim.push_back(front[j * g]);                  // left, downwards
  const std::size_t perSide = g - 1;
  for (std::size_t k = 0; k < rim.size(); ++k) {
    const auto a = rim[k], b = rim[(k + 1) % rim.size()];
    const std::uint32_t corner = back[k / perSide], nextCorner = back[(k / perSide + 1) % 4];
    vol.triangles.push_back({b, a, corner});
    if ((k + 1) % perSide == 0) vol.triangles.push_back({b, corner, nextCorner});
  }
  // The visible surface: a plane at z = -2, inside the volume.
  TriangleMesh wall = makePlane(40, 40, 1);
  for (auto& p : wall.positions) p = glm::vec3(p.x, -p.z, p.y - 2.0f);  // rotate to face +Z
  const EmbreeDevice device;
  const EmbreeScene sceneRt(device, {&wall});
  const EmbreeScene volumeRt(device, {&vol});
  const CameraHits hits = castPrimaryRays(sceneRt, cam);
  const CrossingCounts counts = countCrossings(volumeRt, cam, hits);
  for (std::size_t k = 0; k < hits.depth.size(); ++k) {
    ASSERT_FALSE(hits.isBackground(k));
    EXPECT_NEAR(hits.depth[k], 2.0f, 1e-5f);
    EXPECT_EQ(counts.zfail[k], 1) << "pixel " << k;
    EXPECT_EQ(counts.zpass[k], 1) << "pixel " << k;
  }
  // Seen from inside the volume (the eye at z = -1.5), z-fail still says 1; z-pass misses the
  // entry and says 0: the case z-fail exists for.
  cam.eye = {0, 0, -1.5};
  cam.target = {0, 0, -2.5};
  cam.nearPlane = 0.01;
  const CameraHits inside = castPrimaryRays(sceneRt, cam);
  const CrossingCounts c2 = countCrossings(volumeRt, cam, inside);
  for (std::size_t k = 0; k < inside.depth.size(); ++k) {
    EXPECT_EQ(c2.zfail[k], 1);
    EXPECT_EQ(c2.zpass[k], 0);
  }
}

}  // namespace
}  // namespace shadowvol

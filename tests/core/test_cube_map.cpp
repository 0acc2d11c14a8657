// The point light's cube map conventions (cube_map.h): faces as OpenGL's cube-map table, texel
// lookup, the pairing of border texels across cube edges, the faces' matrices.
#include <set>
#include <utility>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "shadowvol/cube_map.h"
#include "shadowvol/error.h"

namespace shadowvol {
namespace {

Light point() {
  Light l;
  l.type = LightType::Point;
  l.position = {1.0, 2.0, -3.0};
  l.nearPlane = 0.05;
  l.farPlane = 20.0;
  return l;
}

TEST(CubeMap, FacesFollowOpenGLsTable) {
  // OpenGL 4.6 core, table 8.19: major axis, sc, tc. Our NDC x = sc / |ma|, y = tc / |ma|.
  struct Row { glm::dvec3 major, sc, tc; };
  const Row table[6] = {{{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},  {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},
                        {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},    {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},
                        {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},   {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}}};
  for (int f = 0; f < kCubeFaces; ++f) {
    const DepthMap m = makeDepthMap(cubeFaceLight(point(), f), 8, 8, CaptureMode::Back);
    EXPECT_EQ(m.lightType, LightType::Spot);
    const glm::dvec3 p = point().position + 3.0 * table[f].major + 1.5 * table[f].sc - 0.75 * table[f].tc;
    const glm::dvec2 t = m.texelOf(p);  // NDC (0.5, -0.25) -> texel ((0.5 + 1) * 4 - 0.5, ...)
    EXPECT_NEAR(t.x, 5.5, 1e-9) << cubeFaceName(f);
    EXPECT_NEAR(t.y, 2.5, 1e-9) << cubeFaceName(f);
    EXPECT_NEAR(m.viewDepthOf(p), 3.0, 1e-12) << cubeFaceName(f);
    const CubeLookup l = cubeLookup(p - point().position, 8);
    EXPECT_EQ(l.face, f);
    EXPECT_NEAR(l.texel.x, 5.5, 1e-12);
    EXPECT_NEAR(l.texel.y, 2.5, 1e-12);
    EXPECT_NEAR(l.depth, 3.0, 1e-12);
    EXPECT_NEAR(cubeDepth(p - point().position), 3.0, 1e-12);
  }
}

TEST(CubeMap, TexelCentresLookUpThemselves) {
  for (int n : {2, 3, 16}) {
    for (int f = 0; f < kCubeFaces; ++f) {
      const DepthMap m = makeDepthMap(cubeFaceLight(point(), f), n, n, CaptureMode::Back);
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const glm::dvec3 direct = point().position + 2.0 * cubeTexelDirection(n, f, i, j);
          EXPECT_LT(glm::length(m.worldPoint(i, j, 2.0) - direct), 1e-12) << "the face's matrices agree";
          const CubeLookup l = cubeLookup(m.worldPoint(i, j, 2.0) - point().position, n);
          EXPECT_EQ(l.face, f);
          EXPECT_NEAR(l.texel.x, i, 1e-9);
          EXPECT_NEAR(l.texel.y, j, 1e-9);
        }
    }
  }
}

TEST(CubeMap, BorderTexelsPairUpAcrossEveryEdge) {
  for (int n : {2, 3, 7}) {
    std::set<std::tuple<int, int, int, int, int, int>> pairs;
    for (int f = 0; f < kCubeFaces; ++f) {
      const DepthMap m = makeDepthMap(cubeFaceLight(point(), f), n, n, CaptureMode::Back);
      for (int k = 0; k < n; ++k)
        for (auto [i, j, di, dj] : {std::array<int, 4>{n - 1, k, 1, 0}, {0, k, -1, 0}, {k, n - 1, 0, 1}, {k, 0, 0, -1}}) {
          const CubeTexel t = cubeTexelAcross(n, f, i, j, di, dj);
          EXPECT_NE(t.face, f);
          EXPECT_NE(t.face / 2, f / 2) << "never the opposite face";
          // The pair is a border texel of the other face, as near its edge, and symmetric.
          const DepthMap g = makeDepthMap(cubeFaceLight(point(), t.face), n, n, CaptureMode::Back);
          const glm::dvec3 p = m.worldPoint(i, j, 1.0), q = g.worldPoint(t.i, t.j, 1.0);
          // Both directions lie at the same angle from the shared edge: mirror images across it.
          const glm::dvec3 a = glm::normalize(p - point().position), b = glm::normalize(q - point().position);
          EXPECT_NEAR(glm::dot(a, cubeFaceDirection(f)), glm::dot(b, cubeFaceDirection(t.face)), 1e-12);
          EXPECT_NEAR(glm::dot(a, cubeFaceDirection(t.face)), glm::dot(b, cubeFaceDirection(f)), 1e-12);
          pairs.insert({f, i, j, t.face, t.i, t.j});
        }
    }
    for (const auto& [f, i, j, g, gi, gj] : pairs) EXPECT_TRUE(pairs.count({g, gi, gj, f, i, j})) << n;
  }
}

TEST(CubeMap, FaceLightsShareThePointLightsPlanes) {
  for (int f = 0; f < kCubeFaces; ++f) {
    const Light s = cubeFaceLight(point(), f);
    EXPECT_EQ(s.type, LightType::Spot);
    EXPECT_EQ(s.fovYDegrees, 90.0);
    EXPECT_EQ(s.nearPlane, 0.05);
    EXPECT_EQ(s.farPlane, 20.0);
    EXPECT_EQ(s.position, point().position);
  }
  const CubeDepthMap cube = makeCubeDepthMap(point(), 4, CaptureMode::Front);
  EXPECT_NEAR(glm::length(cube.lightPosition() - point().position), 0.0, 1e-12);
  EXPECT_EQ(cube.capture(), CaptureMode::Front);
  EXPECT_THROW(makeCubeDepthMap(point(), 1, CaptureMode::Back), InputError);
  // A point light's own view is a translation; it has no single projection.
  EXPECT_EQ(lightView(point())[3], glm::dvec4(-1.0, -2.0, 3.0, 1.0));
}

// A guarded face's map (the refined GPU cube volume's faces): its texel (i + g, j + g) has the
// face's texel (i, j) centre, and its border texels lie g texels past the face's edge.
TEST(CubeMap, GuardedFaceLightsKeepTheFacesTexelCentres) {
  for (int n : {5, 64})
    for (int g : {0, 4})
      for (int f = 0; f < kCubeFaces; ++f) {
        const Light l = guardedCubeFaceLight(point(), f, n, g);
        EXPECT_EQ(l.type, LightType::Spot);
        EXPECT_EQ(l.direction, cubeFaceDirection(f));
        const DepthMap map = makeDepthMap(l, n + 2 * g, n + 2 * g, CaptureMode::Back);
        const TexelUnprojector unproject(map);
        for (auto [i, j] : {std::pair{0, 0}, std::pair{n - 1, 0}, std::pair{2, n - 1}, std::pair{n / 2, n / 3}}) {
          const glm::dvec3 p = unproject.worldPoint(i + g, j + g, 3.0) - point().position;
          const glm::dvec3 want = 3.0 * cubeTexelDirection(n, f, i, j);
          EXPECT_NEAR(glm::length(p - want), 0.0, 1e-9) << n << " " << g << " " << f << " " << i << " " << j;
        }
        EXPECT_NEAR(guardedCubeFaceLight(point(), f, n, 0).fovYDegrees, 90.0, 1e-12);
      }
}

// What lies in a guarded face's band belongs to a neighbouring face, where the fitted near plane
// holds it; along the guarded face's axis it may lie nearer: the guarded near plane keeps it (a
// second reader's example: near 99.49, (100.5, 0, 99) in the +z face's band at depth 99).
TEST(CubeMap, GuardedFaceNearPlaneKeepsWhatItsBandHolds) {
  Light p = point();
  p.position = glm::dvec3(0.0);
  p.nearPlane = 99.49;
  p.farPlane = 200.0;
  const int n = 64, g = 4;
  const double t = double(n + 2 * g) / double(n);
  for (int f = 0; f < kCubeFaces; ++f) {
    const Light l = guardedCubeFaceLight(p, f, n, g);
    // The band's outermost corner direction at the smallest own-face depth the fit allows: its
    // largest offset component is the neighbour's depth, its depth along this face's axis 1/t of it.
    const glm::dvec3 corner = cubeTexelDirection(n, f, -g - 0.5, -g - 0.5);
    const double ownFace = std::max({std::abs(corner.x), std::abs(corner.y), std::abs(corner.z)});
    const glm::dvec3 q = corner * (p.nearPlane / ownFace);  // at the fitted near in its own face
    EXPECT_GE(glm::dot(q, cubeFaceDirection(f)), l.nearPlane * (1.0 - 1e-12)) << f;
    EXPECT_NEAR(l.nearPlane, p.nearPlane / t, 1e-12);
    EXPECT_EQ(l.farPlane, p.farPlane);
  }
}

}  // namespace
}  // namespace shadowvol

// Refinement's snap (crossing_snap.h) with Embree's oracles: on a polygonal outline every crossing
// moves onto the outline itself; what it cannot snap keeps bisection's crossing. And the geometry
// it rests on, triangleExit (triangle_exit.h).
#include <algorithm>
#include <array>
#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "shadowvol/boundary_edges.h"
#include "shadowvol/crossing_snap.h"
#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/embree/embree_depth_oracle.h"
#include "shadowvol/silhouette_refinement.h"
#include "shadowvol/triangle_exit.h"
#include "shadowvol/cube_volume.h"
#include "shadowvol/volume_builder.h"
#include "test_util.h"

namespace shadowvol {
namespace {

// A 2 x 2 plate, 0.1 thick, 1.5 above the light's far plane region, turned `turn` degrees about
// the vertical, under a directional light straight down (data/scenes/plate-rotated.json).
Scene rotatedPlate(double turn) {
  const std::string json = R"({"objects": [{"type": "box", "name": "plate", "size": [2, 0.1, 2],
      "transform": {"translate": [0, 1.5, 0], "rotate": [0, )" + std::to_string(turn) + R"(, 0]}}],
      "light": {"type": "directional", "direction": [0, -1, 0], "position": [0, 5, 0], "extent": 4},
      "camera": {"eye": [0, 7, 5], "target": [0, 0, 0], "fov": 50}})";
  return test::fittedScene(json, "plate.json");
}

// How far (world units) the crossing of edge e lies from the plate's outline: its point in the
// plate's own frame, |x| or |z| against the half-size 1.
double offOutline(const DepthMap& map, const BoundaryEdge& e, const Crossing& c, double turn) {
  const glm::dvec2 t = Crossing::texel(e, c.s);
  const glm::dvec3 p = map.worldPoint(t.x, t.y, c.nearDepth);
  const double a = glm::radians(turn);
  const double x = std::cos(a) * p.x - std::sin(a) * p.z, z = std::sin(a) * p.x + std::cos(a) * p.z;
  return std::min(std::abs(std::abs(x) - 1.0) + std::max(0.0, std::abs(z) - 1.0),
                  std::abs(std::abs(z) - 1.0) + std::max(0.0, std::abs(x) - 1.0));
}

struct Crossings {
  DepthMap map;
  BoundaryEdges edges;
  Refinement refinement;
};

Crossings refine(const Scene& scene, const EmbreeDepthOracle& oracle, CaptureMode mode, int steps, bool snap) {
  Crossings c;
  c.map = captureDepthEmbree(scene, 64, 64, mode);
  const SheetDepthRule rule(c.map, 0.0, 0.0);
  c.edges = findBoundaryEdges(c.map, rule, false);
  const SurfaceEndOracle ends = oracle.surfaceEnds();
  c.refinement = refineBoundaryEdges(c.map, c.edges, rule, false, {}, oracle.oracle(), steps, {},
                                     {snap ? &ends : nullptr});
  return c;
}

TEST(CrossingSnap, PutsEveryCrossingOfAPolygonalOutlineOnIt) {
  for (double turn : {30.0, 7.0}) {
    SCOPED_TRACE(turn);
    const Scene scene = rotatedPlate(turn);
    const EmbreeDepthOracle oracle(scene);
    const Crossings bisected = refine(scene, oracle, CaptureMode::Back, 3, false);
    const Crossings snapped = refine(scene, oracle, CaptureMode::Back, 3, true);
    ASSERT_GT(snapped.edges.edges.size(), 50u);
    ASSERT_EQ(snapped.edges.edges.size(), bisected.edges.edges.size());
    const double texel = 8.0 / 64.0;  // the light's 8 x 8 window over 64 texels
    double worstBisected = 0.0, worstSnapped = 0.0;
    std::size_t clamped = 0;
    const double margin = std::ldexp(1.0, -(3 + 2));
    for (std::size_t e = 0; e < snapped.edges.edges.size(); ++e) {
      worstBisected = std::max(worstBisected, offOutline(bisected.map, bisected.edges.edges[e],
                                                         bisected.refinement.crossings[e], turn));
      const Crossing& c = snapped.refinement.crossings[e];
      const double off = offOutline(snapped.map, snapped.edges.edges[e], c, turn);
      if (c.s == margin || c.s == 1.0 - margin) {  // the outline within 2^-5 of a texel centre
        ++clamped;
        EXPECT_LE(off, margin * texel + 1e-5);
        continue;
      }
      worstSnapped = std::max(worstSnapped, off);
    }
    // Bisection with 3 rays: within 2^-4 texel of the outline (the slanted distance is less);
    // the snap: on it, to float rounding of Embree's rays.
    EXPECT_LE(worstBisected, texel / 16.0 + 1e-9);
    EXPECT_GT(worstBisected, texel / 256.0);
    EXPECT_LT(worstSnapped, 1e-5) << "bisection's worst " << worstBisected;
    EXPECT_EQ(snapped.refinement.snapped, snapped.edges.edges.size());
    EXPECT_LE(clamped, snapped.edges.edges.size() / 4);
    // Each snap costs one ray for the triangle's end and at most one probe per round.
    EXPECT_GT(snapped.refinement.raysCast, bisected.refinement.raysCast);
    EXPECT_LE(snapped.refinement.raysCast, bisected.refinement.raysCast + 2 * kSnapRounds * snapped.edges.edges.size());
  }
}

TEST(CrossingSnap, WhatItCannotSnapKeepsBisectionsCrossing) {
  // Midpoint capture records the middle of two surfaces, no triangle: every crossing stays.
  const Scene scene = rotatedPlate(30.0);
  const EmbreeDepthOracle oracle(scene);
  const Crossings bisected = refine(scene, oracle, CaptureMode::Midpoint, 4, false);
  const Crossings snapped = refine(scene, oracle, CaptureMode::Midpoint, 4, true);
  ASSERT_FALSE(snapped.edges.edges.empty());
  EXPECT_EQ(snapped.refinement.snapped, 0u);
  for (std::size_t e = 0; e < snapped.edges.edges.size(); ++e) {
    EXPECT_EQ(snapped.refinement.crossings[e].s, bisected.refinement.crossings[e].s);
    EXPECT_EQ(snapped.refinement.crossings[e].nearDepth, bisected.refinement.crossings[e].nearDepth);
  }
}

TEST(CrossingSnap, TriangleExitIsCyrusBeckOnTheTrianglesImage) {
  // A directional light straight down over an 8 x 8 window at 64^2: texel coordinates are
  // (x + 4) * 8 - 0.5 and (-z + 4) * 8 - 0.5, or so; the test works in the map's own terms.
  Scene scene = rotatedPlate(0.0);
  const DepthMap map = makeDepthMap(scene.light, 64, 64, CaptureMode::Back);
  const std::array<glm::dvec3, 3> tri = {glm::dvec3(-1, 1, -1), glm::dvec3(1, 1, -1), glm::dvec3(-1, 1, 1)};
  const glm::dvec2 a = map.texelOf(tri[0]), b = map.texelOf(tri[1]), c = map.texelOf(tri[2]);
  const glm::dvec2 inside = (a + b + c) / 3.0;
  // Towards the middle of side b-c: it leaves there, at t = 1 when `to` is that middle.
  EXPECT_NEAR(triangleExit(map, tri, inside, 0.5 * (b + c)), 1.0, 1e-12);
  EXPECT_NEAR(triangleExit(map, tri, inside, inside + 2.0 * (0.5 * (b + c) - inside)), 0.5, 1e-12);
  // From a point on side a-b heading out: 0; from a point just outside (rounding): 0 as well.
  EXPECT_EQ(triangleExit(map, tri, 0.5 * (a + b), 0.5 * (a + b) + (0.5 * (a + b) - inside)), 0.0);
  EXPECT_EQ(triangleExit(map, tri, 0.5 * (a + b) + 1e-9 * (0.5 * (a + b) - inside), 0.5 * (a + b) + (0.5 * (a + b) - inside)), 0.0);
  // No path, or an edge-on triangle (vertical under a light straight down): NaN.
  EXPECT_TRUE(std::isnan(triangleExit(map, tri, inside, inside)));
  const std::array<glm::dvec3, 3> edgeOn = {glm::dvec3(-1, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 2, 0)};
  EXPECT_TRUE(std::isnan(triangleExit(map, edgeOn, map.texelOf(glm::dvec3(0, 1, 0)), glm::dvec2(0.0))));
  // A spot light: a corner behind its apex plane gives NaN (its image would be mirrored).
  Light spot = test::refinementSpot();
  const DepthMap spotMap = makeDepthMap(spot, 64, 64, CaptureMode::Back);
  const glm::dvec3 behind = spot.position - 2.0 * spot.direction;
  const std::array<glm::dvec3, 3> reaching = {glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), behind};
  EXPECT_TRUE(std::isnan(triangleExit(spotMap, reaching, spotMap.texelOf(glm::dvec3(0.3, 0, 0.1)), glm::dvec2(32.0))));
}

// Distinct vertices of a volume that share one float position (toTriangleMesh, the writers).
std::size_t floatCollisions(const VolumeMesh& mesh) {
  const TriangleMesh f = mesh.toTriangleMesh();
  std::vector<std::array<float, 3>> p;
  for (const auto& v : f.positions) p.push_back({v.x, v.y, v.z});
  std::sort(p.begin(), p.end());
  return std::size_t(std::distance(std::unique(p.begin(), p.end()), p.end()));
}

// Regression (a hostile-input probe): at K = 16 on the sub-grid's 1/8-texel sub-edges a crossing
// came within float spacing of a lattice node (2^-18 texel), and the exported volume had pairs of
// vertices at one float position, with zero-area triangles; a point light's cube too. Crossings
// now keep floatSafeTexels from the segments' ends.
TEST(CrossingSnap, RefinedVolumesStayApartInFloatAtTheFinestSettings) {
  for (const char* name : {"bunny.json", "point/room.json"}) {
    SCOPED_TRACE(name);
    Scene scene = loadScene(test::sourceDir() / "data/scenes" / name).scene;
    fitLightAndCamera(scene);
    const EmbreeDepthOracle oracle(scene);
    VolumeBuildOptions o;
    o.refineSteps = kMaxRefineSteps;
    o.depthOracle = oracle.oracle();
    o.surfaceEnds = oracle.surfaceEnds();
    VolumeBuildResult r;
    if (scene.light.type == LightType::Point) {
      r = buildCubeVolume(captureCubeEmbree(scene, 512, CaptureMode::Back), o);
    } else {
      o.refineSubdivisions = kMaxRefineSubdivisions;
      r = buildVolume(captureDepthEmbree(scene, 512, 512, CaptureMode::Back), o);
    }
    ASSERT_GT(r.stats.boundaryEdges, 100u);
    EXPECT_EQ(floatCollisions(r.mesh), 0u);
  }
}

// The surface-end oracle also gives the recorded triangle (the rim's, volume/rim_bias.h): where the
// path leaves it, its depth is the plate's top, y = 1.55, under the light shining straight down.
TEST(CrossingSnap, TheSurfaceEndOracleGivesTheTriangleThatEnds) {
  const Scene scene = rotatedPlate(30.0);
  const EmbreeDepthOracle oracle(scene);
  const DepthMap map = captureDepthEmbree(scene, 64, 64, CaptureMode::Front);
  const glm::dvec2 centre = map.texelNdc(31.5, 31.5);
  const std::array<glm::dvec2, 3> from = {centre, centre, map.texelNdc(31.0, 33.0)};
  const std::array<glm::dvec2, 3> to = {map.texelNdc(63.0, 31.5), map.texelNdc(10.0, 55.0), map.texelNdc(31.0, 0.0)};
  std::array<double, 3> t{};
  std::array<std::array<glm::dvec3, 3>, 3> triangle{};
  oracle.surfaceEnds()(map, from, to, t, triangle);
  const TexelUnprojector unproject(map);
  for (std::size_t k = 0; k < t.size(); ++k) {
    ASSERT_TRUE(std::isfinite(t[k])) << k;
    const glm::dvec2 f = (from[k] + 1.0) * 0.5 * 64.0 - 0.5, e = (to[k] + 1.0) * 0.5 * 64.0 - 0.5;
    const glm::dvec2 exit = f + t[k] * (e - f);
    for (const glm::dvec3& corner : triangle[k]) EXPECT_NEAR(corner.y, 1.55, 1e-6) << k;
    const double depth = triangleDepthAt(unproject, triangle[k], exit);
    ASSERT_TRUE(std::isfinite(depth)) << k;
    EXPECT_NEAR(map.worldPoint(exit.x, exit.y, depth).y, 1.55, 1e-6) << k;
  }
}

}  // namespace
}  // namespace shadowvol

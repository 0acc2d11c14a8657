// The refinement sub-grid (VolumeBuildOptions::refineSubdivisions, lib/src/core/volume/subgrid_cells.h):
// option checks, walls on an analytic outline within the sub-edges' bisection step, closed
// oriented manifolds for every option on analytic scenes (the unrefined quads beside the sub-grid
// split without T-junctions), the rays it casts, and determinism. The CGAL checks (validity,
// self-intersections) are in tests/cgal, the stencil agreement in tests/validate.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include <tbb/global_control.h>

#include "analytic_scene.h"
#include "mesh_invariants.h"
#include "shadowvol/error.h"
#include "shadowvol/volume_builder.h"
#include "test_util.h"

namespace shadowvol {
namespace {

using test::AnalyticScene;
using test::closedOrientedManifold;

Light spot() { return test::refinementSpot(); }

AnalyticScene sphereOverGround(bool ground) {
  AnalyticScene s;
  s.spheres.push_back({{0.3, 2.0, -0.2}, 1.3});
  s.ground = ground;
  return s;
}

TEST(SubGrid, OptionsAreChecked) {
  const AnalyticScene s = sphereOverGround(false);
  const DepthMap map = s.depthMap(test::directionalDown(6.0), 16, 16, CaptureMode::Back);
  VolumeBuildOptions o;
  o.refineSteps = 3;
  o.depthOracle = s.oracle();
  for (int bad : {0, 3, 6, 16, -2}) {
    o.refineSubdivisions = bad;
    EXPECT_THROW(buildVolume(map, o), InputError) << bad;
  }
  o.refineSubdivisions = 4;
  o.refineChords = true;
  EXPECT_THROW(buildVolume(map, o), InputError);  // alternatives
  o.refineChords = false;
  o.flattenCap = false;
  EXPECT_THROW(buildVolume(map, o), InputError);  // the mirrored cap does not follow sub-cells
  o.flattenCap = true;
  o.refineSteps = 0;
  EXPECT_THROW(buildVolume(map, o), InputError);  // part of refinement
  o.refineSteps = 3;
  o.refineSubdivisions = 1;
  o.refineGridEverywhere = true;
  EXPECT_THROW(buildVolume(map, o), InputError);  // says where the sub-grid goes: needs one
  o.refineGridEverywhere = false;
  // 1 is the plain refined volume.
  const VolumeBuildResult a = buildVolume(map, o);
  VolumeBuildOptions plain = o;
  const VolumeBuildResult b = buildVolume(map, plain);
  EXPECT_TRUE(std::equal(a.mesh.triangles.begin(), a.mesh.triangles.end(), b.mesh.triangles.begin(), b.mesh.triangles.end()));
  EXPECT_EQ(a.stats.subgridSamples, 0u);
}

// With back capture and no ground the far edges' walls stand on the rim: their far vertices lie on
// the far plane, within the sub-edge's bisection step (2^-(k+1) of texel / S, k = K - log2 S; the
// plain quads' 2^-(K+1) texel is the same) of the circle. (A few sub-edges on the sphere's back near
// the rim are split as surface edges; see subgrid_cells.h.) The adaptive sub-grid cuts some of the
// rim's quads and leaves others plain.
TEST(SubGrid, SphereWallsOnItsSilhouetteCircleWithinTheSubEdgeStep) {
  const AnalyticScene s = sphereOverGround(false);
  const Light light = test::directionalDown(6.0);
  const int n = 32;
  const double texel = 2.0 * light.halfExtent / n;
  const DepthMap map = s.depthMap(light, n, n, CaptureMode::Back);
  for (bool everywhere : {false, true})
    for (int grid : {2, 4, 8}) {
      const std::string what = std::string(everywhere ? "everywhere" : "adaptive") + " grid " + std::to_string(grid);
      VolumeBuildOptions o;
      o.refineSteps = 6;
      o.refineSubdivisions = grid;
      o.refineGridEverywhere = everywhere;
      o.depthOracle = s.oracle();
      const VolumeBuildResult v = buildVolume(map, o);
      ASSERT_TRUE(closedOrientedManifold(v.mesh)) << what;
      const int fineSteps = refineSubEdgeSteps(6, grid);
      const double bound = std::ldexp(texel / grid, -(fineSteps + 1)) + 1e-9;
      std::size_t onFar = 0;
      double worst = 0.0;
      for (const auto& p : v.mesh.positions) {
        if (std::abs(map.viewDepthOf(p) - map.farPlane) > 1e-9 * map.farPlane) continue;
        ++onFar;
        worst = std::max(worst, std::abs(std::hypot(p.x - 0.3, p.z + 0.2) - 1.3));
      }
      EXPECT_LE(worst, bound) << what;
      const std::size_t sampling = v.stats.subgridSamples + std::size_t(fineSteps) * v.stats.subgridBoundaryEdges +
                                   v.stats.ambiguousCells;
      if (everywhere) {
        EXPECT_EQ(v.stats.subgridQuads, v.stats.refinedCells) << what;
        EXPECT_EQ(onFar, v.stats.subgridFarBoundaryEdges) << what;  // no far texel or virtual node is used
        EXPECT_GT(v.stats.subgridFarBoundaryEdges, v.stats.boundaryEdges * std::size_t(grid) / 2) << what;
        EXPECT_EQ(v.stats.raysCast, sampling + v.stats.thinRays) << what;
      } else {
        // A rim 5.2 texels in radius bends by about 1/40 texel across a quad, above the chord test's
        // 2 x 2^-7: some quads are cut, and the ones whose wall runs nearly along the rim stay plain.
        EXPECT_GT(v.stats.subgridQuads, 0u) << what;
        EXPECT_LT(v.stats.subgridQuads, v.stats.refinedCells) << what;
        // The far vertices: the bisected sub-edges', the plain far crossings that are used and the
        // chord points where plain quads' walls bend (on the circle too: within the bound above).
        EXPECT_GE(onFar, v.stats.subgridFarBoundaryEdges + 1) << what;
        EXPECT_LE(onFar, v.stats.subgridFarBoundaryEdges + v.stats.farBoundaryEdges + v.stats.chordPoints) << what;
        // The plain crossings and the chord points that choose come first.
        EXPECT_EQ(v.stats.raysCast, sampling + 6 * (v.stats.boundaryEdges + v.stats.chordPoints) + v.stats.thinRays)
            << what;
        EXPECT_GT(v.stats.chordPoints, 0u) << what;
        // The circle bends the plain quads' walls at their chord points (docs/volume.md "Sub-grid", step 6).
        EXPECT_GT(v.stats.plainBends, 0u) << what;
        EXPECT_LE(v.stats.plainBends, v.stats.refinedCells - v.stats.subgridQuads) << what;
      }
    }
}

// An arm thinner than half a texel that reaches from a plate's straight edge into the far side of
// the edge's quads, covering no texel centre: the plain refined wall runs straight along the plate
// and cuts the arm off; the adaptive sub-grid finds the arm's samples off that wall's surface, cuts
// that quad (and leaves the straight edge's others plain), and its walls go round the arm.
TEST(SubGrid, AdaptiveSubGridFindsAnArmThinnerThanATexel) {
  // Texel centres (n = 32 over [-4, 4]) at +-(k + 0.5) * 0.25: the plate's edge x = 1.7 lies 0.3
  // texel past the centre 1.625, the arm x in [1.7, 1.86] stops short of the next one (1.875), z in
  // [-0.05, 0.05] lies between the centres +-0.125, over the lattice nodes z = 0 (S = 4: x = 1.75,
  // 1.8125 on the arm).
  AnalyticScene s;
  s.boxes.push_back({{0.0, 1.5, 0.0}, {1.7, 0.05, 1.1}, 0.0});
  s.boxes.push_back({{1.78, 1.5, 0.0}, {0.08, 0.05, 0.05}, 0.0});
  const Light light = test::directionalDown(6.0);
  const DepthMap map = s.depthMap(light, 32, 32, CaptureMode::Back);
  auto farthestWall = [&](const VolumeBuildResult& v) {
    double x = -1e300;
    for (const auto& p : v.mesh.positions)
      if (std::abs(map.viewDepthOf(p) - map.farPlane) <= 1e-9 * map.farPlane && std::abs(p.z) < 0.2) x = std::max(x, p.x);
    return x;
  };
  VolumeBuildOptions o;
  o.refineSteps = 6;
  o.depthOracle = s.oracle();
  const VolumeBuildResult plain = buildVolume(map, o);
  o.refineSubdivisions = 4;
  const VolumeBuildResult grid = buildVolume(map, o);
  ASSERT_TRUE(closedOrientedManifold(plain.mesh));
  ASSERT_TRUE(closedOrientedManifold(grid.mesh));
  const double step = std::ldexp(0.25, -7) + 1e-9;  // 2^-(K+1) texel
  EXPECT_LE(farthestWall(plain), 1.7 + step);         // the straight wall along the plate
  EXPECT_GE(farthestWall(grid), 1.8125 - 1e-9);        // past the arm's last lattice node
  EXPECT_LE(farthestWall(grid), 1.86 + step);
  EXPECT_GE(grid.stats.subgridQuads, 1u);
  EXPECT_LT(grid.stats.subgridQuads, grid.stats.refinedCells / 2);
}

// A bar 0.08 wide between two columns of texel centres (32 x 32 over [-4, 4]: centres at
// +-(k + 0.5) * 0.25), 2 long; the sub-grid's nodes at S = 4 (every 1/16 unit) meet it at x = 0.0625.
AnalyticScene hiddenBar(bool ground) {
  AnalyticScene s;
  s.boxes.push_back({{0.05, 1.5, 0.3}, {0.04, 0.05, 1.0}, 0.0});
  s.ground = ground;
  return s;
}

// No texel centre sees the bar: without the search for hidden surfaces the volume is empty (back
// capture) or has no shadow of it (front capture over the ground); with it the quads its image
// overlaps go on the sub-grid, whose nodes find it, and its walls stand round it.
TEST(SubGrid, HiddenSurfaceSearchWallsABarThatNoTexelCentreSees) {
  for (bool ground : {false, true}) {
    const AnalyticScene s = hiddenBar(ground);
    const CaptureMode mode = ground ? CaptureMode::Front : CaptureMode::Back;
    const DepthMap map = s.depthMap(test::directionalDown(6.0), 32, 32, mode);
    ASSERT_EQ(map.hitCount(), ground ? std::size_t(32 * 32) : 0u);  // all on the ground, or none
    VolumeBuildOptions o;
    o.refineSteps = 6;
    o.refineSubdivisions = 4;
    o.depthOracle = s.oracle();
    if (ground) o.bias = 0.0;
    const glm::dvec3 under(0.05, 0.5, 0.3), beside(0.3, 0.5, 0.3), beyond(0.05, 0.5, 1.6);
    const VolumeBuildResult none = buildVolume(map, o);
    EXPECT_EQ(none.stats.hiddenQuads, 0u);
    EXPECT_FALSE(!none.mesh.triangles.empty() && test::insideVolume(none.mesh, under)) << ground;
    o.nearerSurfaces = s.nearerSurfaces();
    o.refineHidden = false;
    EXPECT_TRUE(test::sameMesh(buildVolume(map, o).mesh, none.mesh)) << ground;
    o.refineHidden = true;
    const VolumeBuildResult v = buildVolume(map, o);
    ASSERT_TRUE(closedOrientedManifold(v.mesh)) << ground;
    EXPECT_GE(v.stats.hiddenQuads, 8u) << ground;  // 2 long: 8 texels and a part, in one column
    EXPECT_TRUE(test::insideVolume(v.mesh, under)) << ground;
    EXPECT_FALSE(test::insideVolume(v.mesh, beside)) << ground;
    EXPECT_FALSE(test::insideVolume(v.mesh, beyond)) << ground;
    if (ground) continue;  // (the ground's quads at the map's far ring are refined, plain)
    EXPECT_EQ(v.stats.subgridQuads, v.stats.refinedCells);  // the hidden quads, all cut
    // The walls' far vertices within the sub-edges' bisection step of the bar's sides.
    const double step = std::ldexp(0.25 / 4, -(refineSubEdgeSteps(6, 4) + 1)) + 1e-9;
    std::size_t onFar = 0;
    for (const auto& p : v.mesh.positions) {
      if (std::abs(map.viewDepthOf(p) - map.farPlane) > 1e-9 * map.farPlane) continue;
      ++onFar;
      EXPECT_GE(p.x, 0.01 - step);
      EXPECT_LE(p.x, 0.09 + step);
    }
    EXPECT_GT(onFar, 8u);
  }
}

// A bar over the ground that only the centre node of its quads sees (S = 2: nodes every 0.125, the
// bar 0.08 wide round x = 0): the discontinuity rule on the lattice takes, beyond the ground node at
// the lattice's edge, the texel grid's step (flat ground), so the bar's sub-edges are split and its
// walls stand beside it; before, only the bar's own step down on its far side counted, the jump
// looked like a steep slope, and the sheet sloped from the bar to the texel centres over the lit
// ground. Front and midpoint capture (both record the ground).
TEST(SubGrid, AFeatureOneNodeWideAtTheLatticesEdgeIsWalled) {
  AnalyticScene s;
  s.boxes.push_back({{0.0, 1.5, 0.3}, {0.04, 0.05, 1.0}, 0.0});
  s.ground = true;
  for (CaptureMode mode : {CaptureMode::Front, CaptureMode::Midpoint}) {
    const DepthMap map = s.depthMap(test::directionalDown(6.0), 32, 32, mode);
    VolumeBuildOptions o;
    o.refineSteps = 6;
    o.refineSubdivisions = 2;
    o.depthOracle = s.oracle();
    o.nearerSurfaces = s.nearerSurfaces();
    o.bias = 0.0;
    const VolumeBuildResult v = buildVolume(map, o);
    ASSERT_TRUE(closedOrientedManifold(v.mesh)) << toString(mode);
    EXPECT_GE(v.stats.hiddenQuads, 8u) << toString(mode);
    EXPECT_TRUE(test::insideVolume(v.mesh, {0.0, 0.5, 0.3})) << toString(mode);     // under the bar
    EXPECT_FALSE(test::insideVolume(v.mesh, {0.07, 0.5, 0.3})) << toString(mode);   // beside it, over lit ground
    EXPECT_FALSE(test::insideVolume(v.mesh, {-0.07, 0.5, 0.3})) << toString(mode);
  }
}

// Every option the sub-grid takes, on a sphere and a box over the ground, plates and a bar between
// the texel centres (these two with the search for hidden surfaces), spot and directional lights,
// every capture: closed oriented manifolds, and the unrefined quads next to the sub-grid split at
// its side nodes.
TEST(SubGrid, EveryOptionGivesAClosedOrientedManifold) {
  AnalyticScene mixed = sphereOverGround(true);
  mixed.boxes.push_back({{-1.5, 1.0, 1.2}, {0.6, 1.0, 0.4}, 20.0});
  AnalyticScene plate;
  plate.boxes.push_back({{0.0, 1.5, 0.0}, {1.0, 0.05, 1.0}, 30.0});
  plate.ground = true;
  AnalyticScene bars = hiddenBar(true);
  bars.boxes.push_back({{-1.2, 1.0, -1.0}, {1.0, 0.6, 0.03}, 35.0});  // thinner than a texel, turned
  bars.boxes.push_back({{1.3, 2.0, -0.6}, {0.6, 0.05, 0.6}, 10.0});
  std::size_t builds = 0, split = 0, hidden = 0;
  for (const AnalyticScene* s : {&mixed, &plate, &bars})
    for (const Light& light : {test::directionalDown(6.0), spot()})
      for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front, CaptureMode::Midpoint}) {
        const DepthMap map = s->depthMap(light, 24, 24, mode);
        for (Triangulation tri : {Triangulation::Fixed, Triangulation::Perfect})
          for (bool blur : {false, true})
            for (int grid : {2, 4, 8})
              for (bool everywhere : {false, true}) {
              VolumeBuildOptions o;
              o.refineGridEverywhere = everywhere;
              o.triangulation = tri;
              o.blur = blur;
              o.blurOffset = blur ? 0.01 : 0.0;
              o.refineSteps = 4;
              o.refineSubdivisions = grid;
              o.depthOracle = s->oracle();
              if (s != &mixed) o.nearerSurfaces = s->nearerSurfaces();  // boxes and the ground only
              if (mode == CaptureMode::Front) o.bias = 0.0;  // keep the ground off the far plane
              const VolumeBuildResult v = buildVolume(map, o);
              ASSERT_TRUE(closedOrientedManifold(v.mesh)) << toString(mode) << " " << toString(tri) << " blur " << blur
                                                          << " grid " << grid << " everywhere " << everywhere;
              for (const auto& p : v.mesh.positions) ASSERT_TRUE(std::isfinite(p.x + p.y + p.z));
              ++builds;
              split += v.stats.subgridSplitTriangles;
              hidden += v.stats.hiddenQuads;
            }
      }
  EXPECT_EQ(builds, 3u * 2u * 3u * 24u);
  EXPECT_GT(hidden, builds);
  EXPECT_GT(split, builds);  // front capture over the ground: refined quads border unrefined ones
}

TEST(SubGrid, DeterministicForAnyThreadCount) {
  const AnalyticScene s = sphereOverGround(true);
  const DepthMap map = s.depthMap(spot(), 120, 120, CaptureMode::Midpoint);
  VolumeBuildOptions o;
  o.refineSteps = 5;
  o.refineSubdivisions = 4;
  o.depthOracle = s.oracle();
  VolumeBuildResult one;
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    one = buildVolume(map, o);
  }
  const VolumeBuildResult many = buildVolume(map, o);
  ASSERT_GT(one.stats.subgridQuads, 5u);
  ASSERT_LT(one.stats.subgridQuads, one.stats.refinedCells);
  EXPECT_TRUE(test::sameMesh(one.mesh, many.mesh));
}

}  // namespace
}  // namespace shadowvol

// The GPU's silhouette walk (RefineCrossings::GpuWalk) against bisection with the scene's Embree
// rays: on the same light pass, each boundary edge's crossing from the walk must lie where 14
// bisection rays put it, within their 2^-15 texel plus float rounding, and with the same depths.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "gl_test_support.h"
#include "shadowvol/boundary_edges.h"
#include "shadowvol/error.h"
#include "shadowvol/embree/embree_depth_oracle.h"
#include "shadowvol/silhouette_refinement.h"
#include "shadowvol/walk_crossings.h"

namespace shadowvol {
namespace {

constexpr int kSteps = 14;
// Float rounding of the walk's texel coordinates and of the light pass's depths, in texels; a
// crossing also moves by up to 2^-(kSteps + 1) in bisection.
constexpr double kCrossingTolerance = 2e-3;

struct Compared {
  std::size_t edges = 0, surface = 0, surfaceAgreeing = 0, centres = 0;
};

// Walk and bisection on one map of `scene`, with the quad centres next to boundary edges. Far
// edges must agree; surface edges must with `strictSurface`, else they are counted: where the near
// surface folds away in front of a surface that goes on, or a steep surface goes on, the walk's
// rule (silhouette_walk.comp) and bisection's differ by design.
Compared compare(const Scene& scene, int n, CaptureMode mode, bool strictSurface) {
  gl::Renderer& r = gltest::sharedRenderer();
  r.setScene(scene);
  const DepthMap map = r.captureDepth(n, n, mode);
  const SheetDepthRule rule(map, 0.0, 0.0);
  const BoundaryEdges edges = findBoundaryEdges(map, rule, false);
  std::vector<glm::dvec2> centres;
  for (const BoundaryEdge& e : edges.edges)
    if (e.i + 1 < n && e.j + 1 < n) centres.push_back({e.i + 0.5, e.j + 0.5});
  const std::vector<WalkQuery> queries = walkQueries(edges, centres);
  const std::vector<WalkResult> walked = r.walkSilhouettes(n, n, mode, queries);
  const EmbreeDepthOracle oracle(scene);
  const Refinement bisected = refineBoundaryEdges(map, edges, rule, false, {}, oracle.oracle(), kSteps, centres);
  Compared c;
  const double farPlane = map.farPlane, depthTolerance = 1e-4 * farPlane;
  for (std::size_t k = 0; k < edges.edges.size(); ++k) {
    const WalkResult& w = walked[k];
    const Crossing& b = bisected.crossings[k];
    const bool surface = edges.edges[k].surface;
    ++c.edges;
    if (surface) ++c.surface;
    const double nearDepth = rule.ofSample(w.nearDepth, false), farDepth = rule.ofSample(w.farDepth, false);
    if (surface && !strictSurface) {
      if (w.status == WalkResult::kCrossed && std::abs(w.s - b.s) <= kCrossingTolerance &&
          std::abs(nearDepth - b.nearDepth) <= depthTolerance && std::abs(farDepth - b.farDepth) <= depthTolerance)
        ++c.surfaceAgreeing;
      continue;
    }
    SCOPED_TRACE("edge " + std::to_string(k) + " at " + std::to_string(edges.edges[k].i) + ", " +
                 std::to_string(edges.edges[k].j) + (surface ? " surface" : " far"));
    EXPECT_EQ(w.status, WalkResult::kCrossed);
    if (w.status != WalkResult::kCrossed) continue;
    EXPECT_NEAR(w.s, b.s, kCrossingTolerance);
    EXPECT_NEAR(nearDepth, b.nearDepth, depthTolerance);
    if (surface) {
      EXPECT_NEAR(farDepth, b.farDepth, depthTolerance);
      ++c.surfaceAgreeing;
    }
  }
  // Centres: hit where the rays hit (at the same depth), no hit where they miss, except within
  // float rounding of the outline (none of these centres lies that close on the scenes below).
  for (std::size_t k = 0; k < centres.size(); ++k) {
    const WalkResult& w = walked[edges.edges.size() + k];
    const double walkDepth = rule.ofSample(w.nearDepth, false), rayDepth = bisected.centreDepths[k];
    EXPECT_EQ(walkDepth == farPlane, rayDepth == farPlane) << "centre " << centres[k].x << ", " << centres[k].y;
    if (walkDepth != farPlane && rayDepth != farPlane) {
      EXPECT_NEAR(walkDepth, rayDepth, 1e-4 * farPlane);
    }
    ++c.centres;
  }
  return c;
}

TEST(SilhouetteWalk, PlateCrossingsWhereBisectionPutsThem) {
  const Scene scene = gltest::plateScene();
  for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front}) {  // one layer: no midpoint
    SCOPED_TRACE(toString(mode));
    const Compared c = compare(scene, 64, mode, true);
    EXPECT_GE(c.edges, 4u * 10u);  // the plate spans more than 10 texels a side
    // Front capture sees the ground around the plate: its edges over the ground are surface edges.
    if (mode == CaptureMode::Front) {
      EXPECT_GE(c.surface, 4u * 10u);
    }
  }
}

TEST(SilhouetteWalk, CurvedAndThinOccludersUnderASpotLight) {
  // A sphere, a box and a tree's thin trunk on a closed slab: walks over many triangles, with
  // surface edges over the slab in every capture (it is closed, so its back faces are captured).
  const Scene scene = gltest::clutterScene();
  for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front}) {
    SCOPED_TRACE(toString(mode));
    const Compared c = compare(scene, 96, mode, false);
    EXPECT_GE(c.edges, 100u);
    EXPECT_GT(c.surface, 0u);
    // Measured at 96^2 (back / front): 150 of 162 and 147 of 167 surface edges agree.
    EXPECT_GE(c.surfaceAgreeing * 5, c.surface * 4) << c.surfaceAgreeing << " of " << c.surface;
  }
}

// Queries outside the map are refused before anything is read; sizes may change between walks
// (the triangle record follows the light targets when they are remade).
TEST(SilhouetteWalk, RefusesQueriesOutsideTheMapAndFollowsSizeChanges) {
  gl::Renderer& r = gltest::sharedRenderer();
  r.setScene(gltest::plateScene());
  const WalkQuery outside{WalkQuery::kEdge, 63, 10, 0u};  // P = (63, 10), Q = (64, 10): off a 64-wide map
  EXPECT_THROW(r.walkSilhouettes(64, 64, CaptureMode::Back, std::vector<WalkQuery>{outside}), InputError);
  const WalkQuery centre{WalkQuery::kCentre, 10, 63, 0u};  // quad (10, 63) needs row 64
  EXPECT_THROW(r.walkSilhouettes(64, 64, CaptureMode::Back, std::vector<WalkQuery>{centre}), InputError);
  const Compared first = compare(gltest::plateScene(), 64, CaptureMode::Back, true);
  (void)r.captureDepth(48, 48, CaptureMode::Back);  // the light targets remade at another size
  const Compared again = compare(gltest::plateScene(), 64, CaptureMode::Back, true);
  EXPECT_EQ(first.edges, again.edges);
}

}  // namespace
}  // namespace shadowvol

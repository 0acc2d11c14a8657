// From the silhouette walk's raw answers to refinement's crossings (walk_crossings.h): the margin,
// the sheet-depth rule, the fallbacks and the centre depths.
#include <gtest/gtest.h>

#include "shadowvol/walk_crossings.h"
#include "test_util.h"

namespace shadowvol {
namespace {

TEST(WalkCrossings, AnswersBecomeCrossingsByTheRule) {
  DepthMap map = makeDepthMap(test::directionalDown(12.0), 6, 6, CaptureMode::Back);
  std::fill(map.depth.begin(), map.depth.end(), DepthMap::kNoHit);
  map.depth[map.index(2, 2)] = 3.0f;  // an occluder texel
  map.depth[map.index(3, 2)] = 8.0f;  // a receiver beside it
  const SheetDepthRule rule(map, 0.5, 0.0);  // bias 0.5
  BoundaryEdges edges;
  edges.edges = {{2, 2, 0, true, true},    // surface edge (2,2) -> (3,2)
                 {2, 2, 1, true, false},   // far edge (2,2) -> (2,3)
                 {1, 2, 0, false, false}}; // far edge (2,2) -> (1,2), near end at Q
  const std::vector<glm::dvec2> centres = {{2.5, 2.5}, {1.5, 1.5}};
  const std::vector<WalkQuery> q = walkQueries(edges, centres);
  ASSERT_EQ(q.size(), 5u);
  EXPECT_EQ(q[0].flags, 0u | 2u | 4u);
  EXPECT_EQ(q[1].flags, 1u | 2u);
  EXPECT_EQ(q[2].flags, 0u);
  EXPECT_EQ(q[3].kind, WalkQuery::kCentre);
  EXPECT_EQ(q[3].i, 2);
  EXPECT_EQ(q[3].j, 2);

  std::vector<WalkResult> a(5);
  a[0] = {0.4f, 3.2f, 3.1f, WalkResult::kCrossed};  // far vertex not beyond the near one: R's own depth
  a[1] = {0.0001f, 3.1f, DepthMap::kNoHit, WalkResult::kCrossed};  // at the near end: the margin
  a[2] = {0.5f, 0.0f, 0.0f, WalkResult::kFailed};  // fallback
  a[3] = {0.5f, 3.3f, DepthMap::kNoHit, WalkResult::kReached};
  a[4] = {0.5f, DepthMap::kNoHit, DepthMap::kNoHit, WalkResult::kCrossed};
  const Refinement r = refinementFromWalks(map, edges, rule, false, {}, a, centres.size());
  ASSERT_EQ(r.crossings.size(), 3u);
  EXPECT_DOUBLE_EQ(r.crossings[0].s, double(0.4f));
  EXPECT_DOUBLE_EQ(r.crossings[0].nearDepth, double(3.2f) + 0.5);
  EXPECT_DOUBLE_EQ(r.crossings[0].farDepth, 8.5);  // the far end's sheet depth
  EXPECT_DOUBLE_EQ(r.crossings[1].s, kWalkEdgeMargin);
  EXPECT_DOUBLE_EQ(r.crossings[1].nearDepth, double(3.1f) + 0.5);
  EXPECT_DOUBLE_EQ(r.crossings[1].farDepth, map.farPlane);
  EXPECT_DOUBLE_EQ(r.crossings[2].s, 0.5);          // fallback: the middle of the edge,
  EXPECT_DOUBLE_EQ(r.crossings[2].nearDepth, 3.5);  // the near end's own sheet depth
  EXPECT_EQ(r.fallbacks, 1u);
  ASSERT_EQ(r.centreDepths.size(), 2u);
  EXPECT_DOUBLE_EQ(r.centreDepths[0], double(3.3f) + 0.5);
  EXPECT_DOUBLE_EQ(r.centreDepths[1], map.farPlane);
  // A surface edge whose walk came back without a crossing falls back too, with both ends' depths.
  a[0].status = WalkResult::kReached;
  const Refinement f = refinementFromWalks(map, edges, rule, false, {}, a, centres.size());
  EXPECT_EQ(f.fallbacks, 2u);
  EXPECT_DOUBLE_EQ(f.crossings[0].nearDepth, 3.5);
  EXPECT_DOUBLE_EQ(f.crossings[0].farDepth, 8.5);
}

}  // namespace
}  // namespace shadowvol

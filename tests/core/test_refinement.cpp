// Sub-texel silhouette refinement (boundary_edges.h, silhouette_refinement.h, refineSteps):
// analytic scenes with known outlines (plates, a sphere, a thin occluder, an occluder over a
// receiver, a saddle), the discontinuity rule on both kinds of edges, which rays are cast, and the
// combinatorial invariants of refined volumes. The CGAL checks of refined volumes on every
// shipped scene are in tests/cgal.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <tuple>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <tbb/global_control.h>

#include "analytic_scene.h"
#include "mesh_invariants.h"
#include "shadowvol/boundary_edges.h"
#include "shadowvol/depth_oracle.h"
#include "shadowvol/error.h"
#include "shadowvol/silhouette_refinement.h"
#include "shadowvol/volume_builder.h"
#include "test_util.h"

namespace shadowvol {
namespace {

using test::AnalyticScene;
using test::closedOrientedManifold;

// A 2 x 2 plate, 0.1 thick, 1.5 above the ground (data/scenes/plate.json), turned about y.
AnalyticScene plate(double turnDegrees, bool ground = false) {
  AnalyticScene s;
  s.boxes.push_back({{0.0, 1.5, 0.0}, {1.0, 0.05, 1.0}, turnDegrees});
  s.ground = ground;
  return s;
}

Light spot() { return test::refinementSpot(); }

struct Refined {
  DepthMap map;
  BoundaryEdges edges;
  Refinement refinement;
};

// The boundary edges of a map of `scene` and their crossings with `steps` rays each (no blur,
// default bias).
Refined refine(const AnalyticScene& scene, const Light& light, int n, CaptureMode mode, int steps) {
  Refined r;
  r.map = scene.depthMap(light, n, n, mode);
  const SheetDepthRule rule(r.map, defaultBias(r.map), 0.0);
  r.edges = findBoundaryEdges(r.map, rule, false);
  r.refinement = refineBoundaryEdges(r.map, r.edges, rule, false, {}, scene.oracle(), steps);
  return r;
}

// World point of edge e's crossing at light-view depth d.
glm::dvec3 crossingPoint(const Refined& r, std::size_t e, double d) {
  const glm::dvec2 t = Crossing::texel(r.edges.edges[e], r.refinement.crossings[e].s);
  return TexelUnprojector(r.map).worldPoint(t.x, t.y, d);
}

TEST(Refinement, DiscontinuityRuleSplitsStepsNotSlopes) {
  TexelFootprint f;
  f.a = 0.1;  // 0.1 world units per texel at every depth (an orthographic light)
  // A step far above the footprint, flat on both sides: split.
  EXPECT_TRUE(discontinuous(3.0, 5.0, 0.0, 0.0, f));
  // The same jump on a surface that changes its depth by as much every texel: continuous.
  EXPECT_FALSE(discontinuous(3.0, 5.0, 2.0, 2.0, f));
  // A surface sloped on one side only (an occluder's edge over a flat receiver): split.
  EXPECT_TRUE(discontinuous(3.0, 5.0, 2.0, 0.0, f));
  // Steps growing towards a round object's rim (at most 2.41 times per texel): continuous.
  EXPECT_FALSE(discontinuous(3.0, 5.0, 0.83, 0.0 + 100.0, f));
  // No neighbour on either side: the footprint alone decides (2 footprints).
  EXPECT_FALSE(discontinuous(3.0, 3.19, -1.0, -1.0, f));
  EXPECT_TRUE(discontinuous(3.0, 3.21, -1.0, -1.0, f));
  // A missing neighbour leaves the other side's step.
  EXPECT_FALSE(discontinuous(3.0, 5.0, -1.0, 1.5, f));
  EXPECT_TRUE(discontinuous(3.0, 5.0, -1.0, 0.6, f));
}

TEST(Refinement, BothKindsOfBoundaryEdgeOnAPlateOverTheGround) {
  // Back capture: the ground (single-sided, facing the light) is not captured: far edges only.
  const auto back = refine(plate(0.0, true), test::directionalDown(6.0), 64, CaptureMode::Back, 3);
  ASSERT_FALSE(back.edges.edges.empty());
  for (const auto& e : back.edges.edges) EXPECT_FALSE(e.surface);
  // Front capture, bias 0: the plate over the captured ground: surface edges, the wall from the
  // plate's top down to the ground.
  AnalyticScene s = plate(0.0, true);
  DepthMap map = s.depthMap(test::directionalDown(6.0), 64, 64, CaptureMode::Front);
  const SheetDepthRule rule(map, 0.0, 0.0);
  const BoundaryEdges edges = findBoundaryEdges(map, rule, false);
  const Refinement r = refineBoundaryEdges(map, edges, rule, false, {}, s.oracle(), 3);
  std::size_t surface = 0;
  for (std::size_t e = 0; e < edges.edges.size(); ++e) {
    if (!edges.edges[e].surface) continue;  // the ground's border (ring) edges are far edges
    ++surface;
    EXPECT_NEAR(r.crossings[e].nearDepth, 5.0 - 1.55, 1e-5);  // the plate's top
    EXPECT_NEAR(r.crossings[e].farDepth, 5.0, 1e-5);          // the ground
  }
  EXPECT_EQ(surface, 4u * 16u);  // the plate spans 16 texels a side: 4 x 16 boundary edges
  // The ground under a tilted spot light changes its depth smoothly: no surface edge on it.
  AnalyticScene g;
  g.ground = true;
  const DepthMap gm = g.depthMap(spot(), 64, 64, CaptureMode::Front);
  const BoundaryEdges ge = findBoundaryEdges(gm, SheetDepthRule(gm, 0.0, 0.0), false);
  for (const auto& e : ge.edges) EXPECT_FALSE(e.surface) << e.i << ", " << e.j;
}

// Every crossing of the plate (turned by `turn` degrees) lies within 2^-(K+1) texel of its
// outline, except in the quads at its corners.
void expectPlateOutline(double turn) {
  const Light light = test::directionalDown(6.0);
  for (int steps : {1, 3, 6}) {
    const int n = 64;
    const double texel = 2.0 * light.halfExtent / n;
    const auto r = refine(plate(turn), light, n, CaptureMode::Back, steps);
    ASSERT_GE(r.edges.edges.size(), 64u);  // the plate spans 16 texels a side
    const double a = turn * std::numbers::pi / 180.0;
    std::size_t checked = 0;
    for (std::size_t e = 0; e < r.edges.edges.size(); ++e) {
      const glm::dvec3 p = crossingPoint(r, e, 3.0);
      // Plate coordinates (turned back).
      const double u = std::cos(a) * p.x - std::sin(a) * p.z, v = std::sin(a) * p.x + std::cos(a) * p.z;
      const double fromCorner = std::hypot(std::abs(u) - 1.0, std::abs(v) - 1.0);
      if (fromCorner < 1.5 * texel * std::sqrt(2.0)) continue;  // a corner quad
      const double outline = std::abs(std::abs(u) > std::abs(v) ? std::abs(u) - 1.0 : std::abs(v) - 1.0);
      EXPECT_LE(outline, std::ldexp(texel, -(steps + 1)) + 1e-9) << "K " << steps << " at " << p.x << ", " << p.z;
      ++checked;
    }
    EXPECT_GE(checked, r.edges.edges.size() * 2 / 3);  // all but the corner quads
  }
}

TEST(Refinement, AxisAlignedPlateContourWithinTheBisectionStep) { expectPlateOutline(0.0); }

TEST(Refinement, RotatedPlateContourWithinTheBisectionStep) { expectPlateOutline(30.0); }

TEST(Refinement, SphereCrossingsOnItsSilhouetteCircle) {
  AnalyticScene s;
  s.spheres.push_back({{0.3, 2.0, -0.2}, 1.3});
  const Light light = test::directionalDown(6.0);
  const int n = 48;
  const double texel = 2.0 * light.halfExtent / n;
  for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front, CaptureMode::Midpoint})
    for (int steps : {2, 5}) {
      const auto r = refine(s, light, n, mode, steps);
      ASSERT_GT(r.edges.edges.size(), 40u);
      // The walls' far vertices (every crossing and chord point) lie on the circle too.
      VolumeBuildOptions o;
      o.refineSteps = steps;
      o.refineChords = true;
      o.depthOracle = s.oracle();
      if (mode == CaptureMode::Front) o.bias = 0.0;
      const VolumeBuildResult v = buildVolume(r.map, o);
      ASSERT_GT(v.stats.chordPoints, 20u);
      std::size_t onFar = 0;
      for (const auto& p : v.mesh.positions) {
        if (std::abs(r.map.viewDepthOf(p) - r.map.farPlane) > 1e-9 * r.map.farPlane) continue;
        ++onFar;
        // Along the bisection segment the step is 2^-(K+1) of its length (at most the quad's
        // diagonal), and the segment meets the circle at any angle: sqrt(2) x the edges' bound.
        EXPECT_LE(std::abs(std::hypot(p.x - 0.3, p.z + 0.2) - 1.3), std::sqrt(2.0) * std::ldexp(texel, -(steps + 1)) + 1e-9)
            << toString(mode) << " K " << steps;
      }
      EXPECT_EQ(onFar, r.edges.edges.size() + v.stats.chordPoints);
      for (std::size_t e = 0; e < r.edges.edges.size(); ++e) {
        // Only the rim: no step on the sphere's own surface is taken for a second surface.
        EXPECT_FALSE(r.edges.edges[e].surface) << toString(mode);
        const glm::dvec3 p = crossingPoint(r, e, 3.0);
        const double radius = std::hypot(p.x - 0.3, p.z + 0.2);
        EXPECT_LE(std::abs(radius - 1.3), std::ldexp(texel, -(steps + 1)) + 1e-9) << toString(mode) << " K " << steps;
      }
    }
}

TEST(Refinement, RaysGoOnlyToBoundaryEdges) {
  const AnalyticScene s = plate(0.0);
  std::size_t queries = 0;
  std::vector<glm::dvec2> points;
  const DepthMap map = s.depthMap(test::directionalDown(6.0), 64, 64, CaptureMode::Back);
  VolumeBuildOptions o;
  o.refineSteps = 4;
  o.refineChords = false;
  o.depthOracle = s.oracle(&queries, &points);
  const VolumeBuildResult v = buildVolume(map, o);
  // The plate spans 16 texels a side: 4 x 16 edges leave it, each gets 4 rays; no ambiguous quad.
  EXPECT_EQ(v.stats.boundaryEdges, 64u);
  EXPECT_EQ(v.stats.farBoundaryEdges, 64u);
  EXPECT_EQ(v.stats.ambiguousCells, 0u);
  EXPECT_EQ(v.stats.chordPoints, 0u);
  EXPECT_EQ(queries, 4u * 64u);
  EXPECT_EQ(v.stats.raysCast, queries);
  EXPECT_EQ(v.stats.refinedCells, 4u * 15u + 4u);  // between the side texels, plus one at each corner
  const BoundaryEdges edges = findBoundaryEdges(map, SheetDepthRule(map, 0.0, 0.0), false);
  for (const glm::dvec2& p : points) {
    // On a grid edge: one coordinate an integer, the edge a boundary edge.
    const bool alongI = p.y == std::floor(p.y);
    ASSERT_TRUE(alongI || p.x == std::floor(p.x)) << p.x << ", " << p.y;
    const int i = int(std::floor(p.x)), j = int(std::floor(p.y));
    EXPECT_LT(edges.find(i, j, alongI ? 0 : 1), edges.edges.size()) << p.x << ", " << p.y;
  }
  EXPECT_TRUE(closedOrientedManifold(v.mesh));
  // With chord points: every refined quad here has two boundary edges, so one more point each,
  // 4 rays apiece, all inside the refined quads.
  queries = 0;
  points.clear();
  o.refineChords = true;
  const VolumeBuildResult c = buildVolume(map, o);
  EXPECT_EQ(c.stats.chordPoints, c.stats.refinedCells);
  EXPECT_EQ(queries, 4u * (64u + c.stats.chordPoints));
  EXPECT_EQ(c.stats.raysCast, queries);
  std::set<std::pair<int, int>> refinedQuads;
  for (const auto& e : edges.edges) {  // the quads on both sides of every boundary edge
    refinedQuads.insert({e.i, e.j});
    refinedQuads.insert(e.axis == 0 ? std::pair{e.i, e.j - 1} : std::pair{e.i - 1, e.j});
  }
  for (const glm::dvec2& p : points) {
    const bool onEdge = p.x == std::floor(p.x) || p.y == std::floor(p.y);
    EXPECT_TRUE(onEdge || refinedQuads.count({int(std::floor(p.x)), int(std::floor(p.y))})) << p.x << ", " << p.y;
  }
  EXPECT_TRUE(closedOrientedManifold(c.mesh));
}

// The GPU's boundary flags (refine_common.glsl's bits) of an edge set, as boundary_edges.comp writes them.
std::vector<std::uint32_t> flagsOf(const BoundaryEdges& edges, int w, int h) {
  std::vector<std::uint32_t> flags(std::size_t(w) * std::size_t(h), 0);
  for (const BoundaryEdge& e : edges.edges)
    flags[std::size_t(e.j) * std::size_t(w) + std::size_t(e.i)] |=
        (kFlagBoundary | (e.nearAtP ? kFlagNearAtP : 0u) | (e.surface ? kFlagSurface : 0u)) << e.axis;
  return flags;
}

// An edge set read from the GPU's flags is the one the flags were written from, with the same
// split bits, and the count of differing edges sees each kind of difference.
TEST(Refinement, BoundaryEdgesFromFlagsAreTheEdgesFlagged) {
  // Front capture of the plate over the ground: far edges (the ring) and surface edges.
  const DepthMap map = plate(30.0, true).depthMap(test::directionalDown(6.0), 64, 48, CaptureMode::Front);
  const SheetDepthRule rule(map, 0.0, 0.0);
  std::vector<std::uint8_t> split(std::size_t(64) * 48, 0xFF), splitFromFlags(split.size(), 0xFF);
  const BoundaryEdges edges = findBoundaryEdges(map, rule, false, {}, split.data());
  std::vector<std::uint32_t> flags = flagsOf(edges, 64, 48);
  flags[100] |= 0xFFFFFFC0u;  // the unfolding's round bits and above: ignored
  const BoundaryEdges read = boundaryEdgesFromFlags(64, 48, flags, splitFromFlags.data());
  ASSERT_GT(std::count_if(edges.edges.begin(), edges.edges.end(), [](const BoundaryEdge& e) { return e.surface; }), 0);
  EXPECT_EQ(differingBoundaryEdges(edges, read), 0u);
  EXPECT_EQ(read.edges.size(), edges.edges.size());
  EXPECT_EQ(read.rowStart, edges.rowStart);
  EXPECT_EQ(splitFromFlags, split);
  for (std::size_t k = 0; k < edges.edges.size(); ++k)
    EXPECT_EQ(read.find(edges.edges[k].i, edges.edges[k].j, edges.edges[k].axis), k);
  // One edge dropped, one near end turned, one kind changed, one edge added: four.
  BoundaryEdges other = read;
  other.edges.erase(other.edges.begin() + 3);
  other.edges[10].nearAtP = !other.edges[10].nearAtP;
  other.edges[20].surface = !other.edges[20].surface;
  std::vector<std::uint32_t> moreFlags = flagsOf(other, 64, 48);
  ASSERT_EQ(moreFlags[std::size_t(5) * 64 + 5], 0u);
  moreFlags[std::size_t(5) * 64 + 5] = kFlagBoundary << 1;
  EXPECT_EQ(differingBoundaryEdges(edges, boundaryEdgesFromFlags(64, 48, moreFlags)), 4u);
  EXPECT_EQ(differingBoundaryEdges(boundaryEdgesFromFlags(64, 48, moreFlags), edges), 4u);
}

// A boundary-edge source replaces the rule: the build refines the edges it gives. Here the rule's
// own edges (the same volume), then those and a false split on a sphere (a surface edge on a
// continuous surface, which the rule's comment calls harmless: one more wall, still closed).
TEST(Refinement, BoundaryEdgeSourceDecidesTheEdges) {
  AnalyticScene s;
  s.spheres.push_back({{0.0, 2.0, 0.0}, 1.3});
  const DepthMap map = s.depthMap(test::directionalDown(6.0), 64, 64, CaptureMode::Back);
  // Texels P = (i, 32), Q = (i + 1, 32) on the sphere (its far side: back capture), inside its rim,
  // at different depths; their edge is no boundary edge.
  const int i = 36, j = 32;
  ASSERT_LT(map.depth[map.index(i + 2, j)], map.farPlane);
  const bool nearAtP = map.depth[map.index(i, j)] < map.depth[map.index(i + 1, j)];
  ASSERT_NE(map.depth[map.index(i, j)], map.depth[map.index(i + 1, j)]);
  VolumeBuildOptions o;
  o.refineSteps = 4;
  o.depthOracle = s.oracle();
  const VolumeBuildResult viaRule = buildVolume(map, o);
  ASSERT_GT(viaRule.stats.boundaryEdges, 0u);
  std::size_t calls = 0;
  bool falseSplit = false;
  o.boundaryEdgeSource = [&](const DepthMap& m, const SheetDepthRule& rule, bool blur, std::span<const double> blurred,
                             std::uint8_t* splitBits) {
    ++calls;
    const BoundaryEdges found = findBoundaryEdges(m, rule, blur, blurred);
    EXPECT_EQ(found.find(i, j, 0), found.edges.size());
    std::vector<std::uint32_t> flags = flagsOf(found, m.width, m.height);
    if (falseSplit) flags[m.index(i, j)] |= kFlagBoundary | (nearAtP ? kFlagNearAtP : 0u) | kFlagSurface;
    return boundaryEdgesFromFlags(m.width, m.height, flags, splitBits);
  };
  const VolumeBuildResult viaSource = buildVolume(map, o);
  EXPECT_EQ(calls, 1u);
  EXPECT_EQ(viaSource.stats.boundaryEdges, viaRule.stats.boundaryEdges);
  EXPECT_EQ(viaSource.mesh.positions, viaRule.mesh.positions);
  EXPECT_EQ(viaSource.mesh.triangles, viaRule.mesh.triangles);
  falseSplit = true;
  const VolumeBuildResult split = buildVolume(map, o);
  EXPECT_EQ(split.stats.boundaryEdges, viaRule.stats.boundaryEdges + 1);
  EXPECT_EQ(split.stats.refinedCells, viaRule.stats.refinedCells + 2);  // the quads on both sides of the edge
  EXPECT_TRUE(closedOrientedManifold(split.mesh));
}

// The topmost (nearest the light) surface of a volume over texel point (u, v): the smallest
// light-view depth among its triangles whose light-space footprint contains the point; the far
// plane when none does (outside the volume).
double topDepthAt(const VolumeMesh& mesh, const DepthMap& map, glm::dvec2 uv) {
  double best = map.farPlane;
  for (const auto& t : mesh.triangles) {
    glm::dvec2 q[3];
    double d[3];
    for (int k = 0; k < 3; ++k) q[k] = map.texelOf(mesh.positions[t[k]]), d[k] = map.viewDepthOf(mesh.positions[t[k]]);
    const double area = (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[1].y - q[0].y) * (q[2].x - q[0].x);
    if (std::abs(area) < 1e-12) continue;  // a wall
    double w[3];
    for (int k = 0; k < 3; ++k) {
      const glm::dvec2 a = q[(k + 1) % 3], b = q[(k + 2) % 3];
      w[k] = ((b.x - a.x) * (uv.y - a.y) - (b.y - a.y) * (uv.x - a.x)) / area;
    }
    if (w[0] < 0 || w[1] < 0 || w[2] < 0) continue;
    best = std::min(best, w[0] * d[0] + w[1] * d[1] + w[2] * d[2]);
  }
  return best;
}

// fillFromOracle: every texel is the oracle at its centre, asked once; a small map in one batch, a
// large one in batches of whole rows (300 x 300: 218 rows, then 82); a non-square map keeps its
// own size and fields.
TEST(Refinement, FillFromOracleAsksEachTexelCentreOnce) {
  for (auto [w, h, batches] : {std::tuple{7, 5, 1}, std::tuple{300, 300, 2}}) {
    DepthMap map = makeDepthMap(test::directionalDown(6.0), w, h, CaptureMode::Front);
    int calls = 0;
    std::size_t asked = 0;
    const DepthOracle oracle = [&](const DepthMap& m, std::span<const glm::dvec2> ndc, std::span<float> depth) {
      ++calls;
      asked += ndc.size();
      EXPECT_EQ(&m, &map);
      EXPECT_EQ(ndc.size(), depth.size());
      for (std::size_t k = 0; k < ndc.size(); ++k) depth[k] = float(3.0 + ndc[k].x + 0.5 * ndc[k].y);
    };
    fillFromOracle(map, oracle);
    EXPECT_EQ(calls, batches);
    EXPECT_EQ(asked, std::size_t(w) * std::size_t(h));
    ASSERT_EQ(map.depth.size(), std::size_t(w) * std::size_t(h));
    int wrong = 0;
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const glm::dvec2 c = map.texelNdc(i, j);
        wrong += map.at(i, j) != float(3.0 + c.x + 0.5 * c.y);
      }
    EXPECT_EQ(wrong, 0) << w << " x " << h;
    EXPECT_EQ(map.capture, CaptureMode::Front);
  }
}

TEST(Refinement, SaddleQuadDecidedByTheCentreRay) {
  // Two texels on the diagonal of quad (8, 8) are hit (8, 8) and (9, 9); the other two are not.
  // Joined: a bar along that diagonal through the quad's centre. Apart: two small boxes.
  const Light light = test::directionalDown(6.0);
  const int n = 18;
  const double texel = 2.0 * light.halfExtent / n;
  DepthMap probe = makeDepthMap(light, n, n, CaptureMode::Back);
  const TexelUnprojector unproject(probe);
  auto world = [&](double i, double j) { return unproject.worldPoint(i, j, 1.0); };
  for (bool joined : {true, false}) {
    AnalyticScene s;
    for (glm::dvec2 c : {glm::dvec2(8, 8), glm::dvec2(9, 9)}) {
      const glm::dvec3 w = world(c.x, c.y);
      s.boxes.push_back({{w.x, 2.0, w.z}, {0.35 * texel, 0.2, 0.35 * texel}, 0.0});
    }
    if (joined) {  // a bar from one texel centre to the other, 0.3 texel wide
      const glm::dvec3 a = world(8, 8), b = world(9, 9), m = 0.5 * (a + b);
      const double angle = std::atan2(-(b.z - a.z), b.x - a.x) * 180.0 / std::numbers::pi;
      s.boxes.push_back({{m.x, 2.0, m.z}, {0.5 * glm::length(b - a), 0.2, 0.15 * texel}, angle});
    }
    const DepthMap map = s.depthMap(light, n, n, CaptureMode::Back);
    ASSERT_FALSE(DepthMap::isNoHit(map.at(8, 8)));
    ASSERT_FALSE(DepthMap::isNoHit(map.at(9, 9)));
    ASSERT_TRUE(DepthMap::isNoHit(map.at(9, 8)));
    ASSERT_TRUE(DepthMap::isNoHit(map.at(8, 9)));
    VolumeBuildOptions o;
    o.refineSteps = 4;
    o.depthOracle = s.oracle();
    const VolumeBuildResult v = buildVolume(map, o);
    EXPECT_EQ(v.stats.ambiguousCells, 1u);
    EXPECT_TRUE(closedOrientedManifold(v.mesh));
    const double centre = topDepthAt(v.mesh, map, {8.5, 8.5});
    if (joined) {
      EXPECT_LT(centre, 0.5 * (map.at(8, 8) + map.farPlane)) << "the hit corners are joined";
    } else {
      EXPECT_EQ(centre, map.farPlane) << "the hit corners stay apart";
    }
  }
}

TEST(Refinement, ThinOccluderOnOneTexelCentre) {
  // A 0.4 x 0.4 texel square on the centre of texel (8, 8): only that texel is hit; its four
  // edges cross 0.2 texel from its centre, and the volume's footprint is that square's diamond.
  const Light light = test::directionalDown(6.0);
  const int n = 17;
  const double texel = 2.0 * light.halfExtent / n;
  DepthMap probe = makeDepthMap(light, n, n, CaptureMode::Back);
  const glm::dvec3 c = TexelUnprojector(probe).worldPoint(8, 8, 1.0);
  AnalyticScene s;
  s.boxes.push_back({{c.x, 2.0, c.z}, {0.2 * texel, 0.1, 0.2 * texel}, 0.0});
  const int steps = 6;
  const auto r = refine(s, light, n, CaptureMode::Back, steps);
  ASSERT_EQ(r.edges.edges.size(), 4u);
  for (std::size_t e = 0; e < 4; ++e) EXPECT_NEAR(r.refinement.crossings[e].s, 0.2, std::ldexp(1.0, -(steps + 1)));
  VolumeBuildOptions o;
  o.refineSteps = steps;
  o.depthOracle = s.oracle();
  const VolumeBuildResult v = buildVolume(r.map, o);
  EXPECT_TRUE(closedOrientedManifold(v.mesh));
  EXPECT_LT(topDepthAt(v.mesh, r.map, {8.0, 8.0}), r.map.farPlane);   // the texel's centre: inside
  EXPECT_EQ(topDepthAt(v.mesh, r.map, {8.3, 8.0}), r.map.farPlane);   // beyond its crossings: outside
  EXPECT_EQ(topDepthAt(v.mesh, r.map, {8.0, 7.7}), r.map.farPlane);
  // Unrefined, the sheet slants from the texel centre to its neighbours' centres.
  EXPECT_LT(topDepthAt(buildVolume(r.map).mesh, r.map, {8.3, 8.0}), r.map.farPlane);
}

TEST(Refinement, OptionsAreChecked) {
  const AnalyticScene s = plate(0.0);
  const DepthMap map = s.depthMap(test::directionalDown(6.0), 16, 16, CaptureMode::Back);
  VolumeBuildOptions o;
  o.refineSteps = 2;  // no oracle
  EXPECT_THROW(buildVolume(map, o), InputError);
  o.depthOracle = s.oracle();
  o.cap = FarCap::Quad;
  EXPECT_THROW(buildVolume(map, o), InputError);
  o.cap = FarCap::Exact;
  for (int bad : {-1, kMaxRefineSteps + 1}) {
    o.refineSteps = bad;
    EXPECT_THROW(buildVolume(map, o), InputError) << bad;
  }
  // refineSteps 0 is the unrefined volume, oracle or not.
  o.refineSteps = 0;
  const VolumeBuildResult a = buildVolume(map, o), b = buildVolume(map);
  EXPECT_TRUE(std::equal(a.mesh.positions.begin(), a.mesh.positions.end(), b.mesh.positions.begin(), b.mesh.positions.end()));
  EXPECT_TRUE(std::equal(a.mesh.triangles.begin(), a.mesh.triangles.end(), b.mesh.triangles.begin(), b.mesh.triangles.end()));
  EXPECT_EQ(a.stats.raysCast, 0u);
  // A bad depth is refused before any ray is cast.
  DepthMap badMap = map;
  badMap.depth[badMap.index(3, 4)] = -1.0f;
  std::size_t queries = 0;
  o.refineSteps = 3;
  o.depthOracle = s.oracle(&queries);
  EXPECT_THROW(buildVolume(badMap, o), InputError);
  EXPECT_EQ(queries, 0u);
}

// Every option combination on analytic scenes (plates, a sphere and a box, over the ground or
// not), spot and directional lights, all capture modes: closed oriented manifolds.
TEST(Refinement, EveryOptionGivesAClosedOrientedManifold) {
  AnalyticScene mixed;
  mixed.spheres.push_back({{0.3, 2.0, -0.2}, 1.0});
  mixed.boxes.push_back({{-1.5, 1.0, 1.2}, {0.6, 1.0, 0.4}, 20.0});
  mixed.ground = true;
  const AnalyticScene scenes[] = {plate(0.0, true), plate(30.0, true), mixed};
  std::size_t builds = 0, refinedCells = 0, surfaceEdges = 0;
  for (const AnalyticScene& s : scenes)
    for (const Light& light : {test::directionalDown(6.0), spot()})
      for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front, CaptureMode::Midpoint}) {
        const DepthMap map = s.depthMap(light, 40, 40, mode);
        for (Triangulation tri : {Triangulation::Fixed, Triangulation::Perfect})
          for (bool blur : {false, true})
            for (bool flat : {true, false}) {
              VolumeBuildOptions o;
              o.triangulation = tri;
              o.blur = blur;
              o.blurOffset = blur ? 0.01 : 0.0;
              o.flattenCap = flat;
              o.refineSteps = 3;
              o.refineChords = tri == Triangulation::Perfect;  // both ways across the combinations
              o.depthOracle = s.oracle();
              if (mode == CaptureMode::Front) o.bias = 0.0;  // keep the ground off the far plane
              const VolumeBuildResult v = buildVolume(map, o);
              ASSERT_TRUE(closedOrientedManifold(v.mesh))
                  << toString(mode) << " " << toString(tri) << " blur " << blur << " flat " << flat;
              EXPECT_EQ(v.stats.raysCast, 3 * (v.stats.boundaryEdges + v.stats.chordPoints) + v.stats.ambiguousCells);
              ++builds;
              refinedCells += v.stats.refinedCells;
              surfaceEdges += v.stats.boundaryEdges - v.stats.farBoundaryEdges;
            }
      }
  EXPECT_EQ(builds, 3u * 2u * 3u * 8u);
  EXPECT_GT(refinedCells, builds * 20);
  EXPECT_GT(surfaceEdges, 0u);  // front and midpoint capture over the ground
}

TEST(Refinement, DeterministicForAnyThreadCount) {
  AnalyticScene s;
  s.spheres.push_back({{0.3, 2.0, -0.2}, 1.3});
  s.ground = true;
  const DepthMap map = s.depthMap(spot(), 200, 200, CaptureMode::Midpoint);
  VolumeBuildOptions o;
  o.refineSteps = 5;
  o.refineChords = true;
  o.depthOracle = s.oracle();
  VolumeBuildResult one;
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    one = buildVolume(map, o);
  }
  const VolumeBuildResult many = buildVolume(map, o);
  ASSERT_GT(one.stats.boundaryEdges, 100u);
  EXPECT_TRUE(test::sameMesh(one.mesh, many.mesh));
}

}  // namespace
}  // namespace shadowvol

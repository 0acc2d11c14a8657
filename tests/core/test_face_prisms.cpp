// The refined volume's face prisms (caster_faces.h, volume/face_prisms.h; docs/volume.md "Face
// prisms"): which faces are taken, and the closed part their prisms make, on hand-made faces under
// a directional light straight down (from y = 5, far plane 6: the far plane is y = -1).
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "mesh_invariants.h"
#include "shadowvol/caster_faces.h"
#include "shadowvol/depth_map.h"
#include "shadowvol/nearer_surfaces.h"
#include "shadowvol/primitives.h"
#include "shadowvol/triangle_adjacency.h"
#include "test_util.h"
#include "volume/face_prisms.h"
#include "volume/prism_columns.h"

namespace shadowvol {
namespace {

using Face = std::array<glm::dvec3, 3>;

DepthMap mapDown(int n = 16) { return makeDepthMap(test::directionalDown(6.0), n, n, CaptureMode::Entry); }

TriangleMesh moved(TriangleMesh m, const glm::vec3& by) {
  for (auto& p : m.positions) p += by;
  return m;
}

// A unit box at height 2: of its 12 faces only the top's two face the light (the sides are
// edge-on); with every quad flagged they are taken, with none nothing is, and an open plate is
// never taken.
TEST(CasterFaces, TheLitFacesOfClosedMeshesInFlaggedColumns) {
  const DepthMap map = mapDown();
  const TriangleMesh box = moved(makeBox(1.0, 1.0, 1.0), {0.0f, 2.0f, 0.0f});
  const TriangleMesh plate = moved(makePlane(2.0, 2.0, 1), {0.0f, 1.0f, 0.0f});
  const std::vector<TriangleSoup> soups{soupOf(box), soupOf(plate)};
  ASSERT_TRUE(soups[0].closed);
  ASSERT_FALSE(soups[1].closed);
  std::vector<std::uint8_t> all(std::size_t(15 * 15), 1), none(all.size(), 0);
  const std::vector<Face> faces = findCasterFaces(map, soups, all);
  ASSERT_EQ(faces.size(), 2u);
  for (const Face& f : faces)
    for (const glm::dvec3& p : f) EXPECT_EQ(p.y, 2.5);  // the top
  EXPECT_TRUE(findCasterFaces(map, soups, none).empty());
  // One flagged quad far from the box: its faces' images (texels 6.5 to 8.5 of 16 over 8 units)
  // do not reach it; a quad under the box does.
  std::vector<std::uint8_t> one = none;
  one[0] = 1;
  EXPECT_TRUE(findCasterFaces(map, soups, one).empty());
  one.assign(one.size(), 0);
  one[7 * 15 + 7] = 1;
  EXPECT_EQ(findCasterFaces(map, soups, one).size(), 2u);
}

// A face reaching a flagged quad brings the whole region of faces towards the light that it lies
// in: one quad under a sphere takes all of its lit side, as every quad does; a second sphere whose
// faces reach no flagged quad gives none. Given neighbours are used: the same links as found give
// the same faces, no links leave only the faces whose images reach the quad.
TEST(CasterFaces, AFlaggedQuadTakesItsWholeLitRegion) {
  const DepthMap map = mapDown(32);  // 32 texels over 8 units: texel (i, j) at x = (i + 0.5) / 4 - 4
  const TriangleMesh sphere = moved(makeIcoSphere(1.0, 2), {-2.0f, 2.0f, 0.0f});
  const TriangleMesh other = moved(makeIcoSphere(1.0, 2), {2.0f, 2.0f, 0.0f});
  std::vector<TriangleSoup> soups{soupOf(sphere), soupOf(other)};
  ASSERT_TRUE(soups[0].closed && soups[1].closed);
  std::size_t lit = 0;  // the first sphere's faces towards the light
  for (const auto& t : sphere.triangles) {
    const glm::dvec3 a(sphere.positions[t[0]]), b(sphere.positions[t[1]]), c(sphere.positions[t[2]]);
    lit += glm::cross(b - a, c - a).y > 1e-9 * glm::length(glm::cross(b - a, c - a));
  }
  ASSERT_GT(lit, 100u);
  std::vector<std::uint8_t> all(std::size_t(31 * 31), 1), rim(all.size(), 0);
  EXPECT_EQ(findCasterFaces(map, soups, all).size(), 2 * lit);
  rim[std::size_t(16 * 31 + 8)] = 1;  // quad (8, 16): x from -1.875 to -1.625, z from 0.125 to 0.375
  const std::vector<Face> faces = findCasterFaces(map, soups, rim);
  EXPECT_EQ(faces.size(), lit);
  for (const Face& f : faces) EXPECT_LT(f[0].x, 0.0);  // the first sphere's
  const std::vector<std::int32_t> neighbours = triangleNeighbours(sphere);
  soups[0].neighbours = neighbours;
  EXPECT_EQ(findCasterFaces(map, soups, rim), faces);
  const std::vector<std::int32_t> none(neighbours.size(), kNoNeighbour);
  soups[0].neighbours = none;
  const std::size_t seeds = findCasterFaces(map, soups, rim).size();
  EXPECT_GT(seeds, 0u);
  EXPECT_LT(seeds, 20u);
}

// The hand-over's rule (handedToPrisms): a closed mesh wholly between the near and far planes and
// inside the window; not an open one, not one reaching past the far plane (y = -1) or the window's
// edge (x = 4).
TEST(CasterFaces, HandedToThePrismsOnlyWhenWholeInsideTheFrustum) {
  const DepthMap map = mapDown();
  const TriangleMesh box = makeBox(1.0, 1.0, 1.0);
  EXPECT_TRUE(handedToPrisms(map, soupOf(moved(box, {0.0f, 2.0f, 0.0f}))));
  EXPECT_FALSE(handedToPrisms(map, soupOf(moved(makePlane(2.0, 2.0, 1), {0.0f, 1.0f, 0.0f}))));
  EXPECT_FALSE(handedToPrisms(map, soupOf(moved(box, {0.0f, -1.0f, 0.0f}))));
  EXPECT_FALSE(handedToPrisms(map, soupOf(moved(box, {3.8f, 2.0f, 0.0f}))));
  EXPECT_TRUE(handedToPrisms(map, soupOf(moved(box, {3.2f, 2.0f, 0.0f}))));
}

// Stage 0p (volume/prism_columns.h): the corners of a refined quad at which the oracle without the
// casters records something else (a caster handed over) are recaptured, with the quad's other
// corners; a refined quad whose corners it records alike stays the sheet's; the quads with a
// handed-over corner are the prisms' columns, and the oracles handed on answer from the other
// oracle inside those texels' squares only.
TEST(PrismColumns, TheRefinedQuadsWithACasterAreRecapturedWithoutIt) {
  DepthMap map = mapDown(8);
  std::fill(map.depth.begin(), map.depth.end(), 3.0f);
  int calls = 0;
  // The hand-over oracle: a handed-over mesh recorded in the lower half (caster-free record 5), the
  // capture's own 3 above; the map a few ulps off (a GPU's light pass): only the oracle's word counts.
  const HandOverOracle handOver = [&calls](const DepthMap&, std::span<const glm::dvec2> ndc, std::span<float> d,
                                           std::span<std::uint8_t> handed) {
    ++calls;
    for (std::size_t k = 0; k < ndc.size(); ++k) {
      handed[k] = ndc[k].y < 0.0;
      d[k] = handed[k] ? 5.0f : 3.0f;
    }
  };
  const DepthOracle full = [](const DepthMap&, std::span<const glm::dvec2>, std::span<float> d) {
    std::fill(d.begin(), d.end(), 3.0f);
  };
  for (float& d : map.depth) d = std::nextafter(d, 4.0f);
  const std::uint32_t q = 2 * 7 + 3, kept = 5 * 7 + 3;  // quads (3, 2): texels (3..4, 2..3); (3, 5)
  const auto columns =
      std::make_shared<const volume::PrismColumns>(volume::findPrismColumns(map, {{q, kept}}, handOver));
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(columns->rays, 12u);  // 8 corners, 4 of them handed over
  EXPECT_EQ(columns->texelCount, 4u);
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      const bool handed = i >= 3 && i <= 4 && j >= 2 && j <= 3;
      EXPECT_EQ(columns->texels[std::size_t(j * 8 + i)], handed ? 1 : 0) << i << " " << j;
      EXPECT_EQ(columns->map.at(i, j), handed ? 5.0f : std::nextafter(3.0f, 4.0f)) << i << " " << j;
    }
  for (int qj = 0; qj < 7; ++qj)
    for (int qi = 0; qi < 7; ++qi)  // every quad with a corner among those texels
      EXPECT_EQ(columns->quads[std::size_t(qj * 7 + qi)], qi >= 2 && qi <= 4 && qj >= 1 && qj <= 3 ? 1 : 0);
  VolumeBuildOptions o;
  o.depthOracle = full;
  o.withoutCasters.depth = handOver;
  const VolumeBuildOptions h = volume::handOverColumns(o, columns);
  const auto ndc = [](double i, double j) { return glm::dvec2((i + 0.5) / 8 * 2 - 1, (j + 0.5) / 8 * 2 - 1); };
  // Texel (3, 2)'s centre and square, texel (2, 2)'s, and the border between them (to the larger index).
  const std::vector<glm::dvec2> points{ndc(3, 2), ndc(3.4, 2.4), ndc(2, 2), ndc(2.4, 2), ndc(2.5, 2), ndc(5, 3)};
  std::vector<float> depth(points.size());
  h.depthOracle(map, points, depth);
  EXPECT_EQ(depth, (std::vector<float>{5.0f, 5.0f, 3.0f, 3.0f, 5.0f, 3.0f}));
}

// The box's top: one prism from y = 2.5 down to the far plane (y = -1), through the box, closed and
// outward, with a wall on each of the top's four outer edges and none on its diagonal.
TEST(FacePrisms, ABoxsTopGivesOnePrismToTheFarPlane) {
  const DepthMap map = mapDown();
  const TriangleMesh box = moved(makeBox(1.0, 1.0, 1.0), {0.0f, 2.0f, 0.0f});
  std::vector<std::uint8_t> all(std::size_t(15 * 15), 1);
  const std::vector<TriangleSoup> soups{soupOf(box)};
  VolumeMesh mesh;
  const volume::FacePrismCounts c = volume::appendFacePrisms(map, findCasterFaces(map, soups, all), mesh);
  EXPECT_EQ(c.faces, 2u);
  EXPECT_EQ(c.walls, 4u);
  EXPECT_EQ(c.triangles, 2u + 2u + 8u);
  EXPECT_EQ(mesh.partStarts, std::vector<std::size_t>{0});
  EXPECT_TRUE(test::closedOrientedManifold(mesh));
  EXPECT_EQ(test::windingNumber(mesh, {0.1, 1.0, 0.2}), 1);    // under the box
  EXPECT_EQ(test::windingNumber(mesh, {0.1, -0.9, 0.2}), 1);   // just above the far plane
  EXPECT_EQ(test::windingNumber(mesh, {0.1, -1.1, 0.2}), 0);   // beyond it
  EXPECT_EQ(test::windingNumber(mesh, {0.1, 1.7, 0.2}), 1);    // inside the box, behind its top
  EXPECT_EQ(test::windingNumber(mesh, {0.1, 2.7, 0.2}), 0);    // above it
  EXPECT_EQ(test::windingNumber(mesh, {0.6, 1.0, 0.2}), 0);    // beside
  for (const auto& p : mesh.positions) EXPECT_TRUE(p.y == 2.5 || p.y == -1.0);
}

// The same under a spot light (test::refinementSpot, apex (0.6, 7, 0.4), far plane 9): the prism
// widens away from the apex; inside it along a light ray from a point under the bottom, outside
// beside it and beyond the far plane; its far corners on the far plane, on their light rays.
TEST(FacePrisms, UnderASpotLightThePrismFollowsTheRays) {
  const DepthMap map = makeDepthMap(test::refinementSpot(), 32, 32, CaptureMode::Entry);
  const TriangleMesh box = moved(makeBox(1.0, 1.0, 1.0), {0.0f, 2.0f, 0.0f});
  std::vector<std::uint8_t> all(std::size_t(31 * 31), 1);
  const std::vector<TriangleSoup> soups{soupOf(box)};
  const std::vector<Face> faces = findCasterFaces(map, soups, all);
  ASSERT_GE(faces.size(), 2u);  // the top, and sides the apex sees from the front
  VolumeMesh mesh;
  volume::appendFacePrisms(map, faces, mesh);
  EXPECT_TRUE(test::closedOrientedManifold(mesh));
  const glm::dvec3 apex(0.6, 7.0, 0.4), under(0.1, 1.5, -0.2);  // a point of the bottom, behind the top
  for (const double s : {1.2, 2.0, 3.0}) {  // farther along the ray from the apex through it
    const glm::dvec3 p = apex + s * (under - apex);
    EXPECT_EQ(test::windingNumber(mesh, p) > 0, map.viewDepthOf(p) < map.farPlane) << s;
  }
  EXPECT_EQ(test::windingNumber(mesh, {2.5, 0.5, 0.0}), 0);  // beside the shadow
  for (const auto& p : mesh.positions) {
    const double d = map.viewDepthOf(p);
    EXPECT_TRUE(d < map.farPlane * (1.0 - 1e-12) || std::abs(d - map.farPlane) <= 1e-9 * map.farPlane) << d;
  }
}

// Two faces meeting at one vertex (a pinch of the patch's border): each fan gets its own copy of
// the vertex, near and far, so that every vertex is a single fan; the copies coincide.
TEST(FacePrisms, TwoFacesMeetingAtOneVertexGetACopyEach) {
  const DepthMap map = mapDown();
  // Facing up (towards the light): counter-clockwise seen from above.
  const std::vector<Face> faces{Face{glm::dvec3(0, 2, 0), glm::dvec3(0, 2, 1), glm::dvec3(1, 2, 0)},
                                Face{glm::dvec3(0, 2, 0), glm::dvec3(0, 2, -1), glm::dvec3(-1, 2, 0)}};
  VolumeMesh mesh;
  const volume::FacePrismCounts c = volume::appendFacePrisms(map, faces, mesh);
  EXPECT_EQ(c.walls, 6u);
  EXPECT_EQ(mesh.positions.size(), 12u);  // 3 near and 3 far corners per face: the shared one twice
  EXPECT_TRUE(test::closedOrientedManifold(mesh));
  EXPECT_EQ(test::windingNumber(mesh, {0.2, 0.0, 0.2}), 1);
  EXPECT_EQ(test::windingNumber(mesh, {-0.2, 0.0, -0.2}), 1);
  EXPECT_EQ(test::windingNumber(mesh, {0.2, 0.0, -0.2}), 0);
}

// Faces that overlap as seen from the light: their prisms overlap, and the winding number counts
// both where they do (the stencil's count); the part is still closed and oriented. Two adjacent
// faces share their edge without a wall.
TEST(FacePrisms, OverlappingFacesAddUp) {
  const DepthMap map = mapDown();
  const std::vector<Face> faces{
      Face{glm::dvec3(0, 2, 0), glm::dvec3(1, 2, 1), glm::dvec3(1, 2, 0)},        // a square at y = 2 ...
      Face{glm::dvec3(0, 2, 0), glm::dvec3(0, 2, 1), glm::dvec3(1, 2, 1)},        // ... in two faces
      Face{glm::dvec3(0.5, 1, 0.5), glm::dvec3(0.5, 1, 1.5), glm::dvec3(1.5, 1, 0.5)}};  // one lower, overlapping
  VolumeMesh mesh;
  const volume::FacePrismCounts c = volume::appendFacePrisms(map, faces, mesh);
  EXPECT_EQ(c.walls, 4u + 3u);
  EXPECT_TRUE(test::closedOrientedManifold(mesh));
  EXPECT_EQ(test::windingNumber(mesh, {0.6, 0.0, 0.6}), 2);  // under both
  EXPECT_EQ(test::windingNumber(mesh, {0.6, 1.5, 0.6}), 1);  // between them
  EXPECT_EQ(test::windingNumber(mesh, {0.2, 0.0, 0.2}), 1);  // under the square alone
  EXPECT_EQ(test::windingNumber(mesh, {1.2, 0.0, 0.6}), 1);  // under the lower face alone
}

}  // namespace
}  // namespace shadowvol

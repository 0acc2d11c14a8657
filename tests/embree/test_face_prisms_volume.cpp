// The refined volume's face prisms on a whole build (VolumeBuildOptions::facePrisms, docs/volume.md
// "Face prisms"): a closed sphere over an open ground plane under a directional light straight
// down, entry capture, the 4 x 4 sub-grid. The prisms are a second closed part after the volume
// the build makes without them (which is left as it was, unless the sheet hands the columns over:
// the second test); they hold no lit point: every point inside them has the sphere between it and
// the light, or lies inside the sphere.
#include <gtest/gtest.h>

#include "mesh_invariants.h"
#include "refined_options.h"
#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/primitives.h"
#include "shadowvol/scene.h"
#include "test_util.h"

namespace shadowvol {
namespace {

Scene sphereOverGround() {
  TriangleMesh sphere = makeIcoSphere(1.0, 3);
  for (auto& p : sphere.positions) p.y += 2.0f;
  return test::sceneWith({SceneObject{"ground", "plane", makePlane(8.0, 8.0, 1)}, SceneObject{"sphere", "mesh", sphere}});
}

// handOver: the sheet hands the refined quads' columns over to the prisms (withoutCasters).
VolumeBuildResult build(const Scene& scene, bool prisms, bool handOver = false,
                        CaptureMode capture = CaptureMode::Entry) {
  const EmbreeDepthOracle oracle(scene);
  const DepthMap map = captureDepthEmbree(scene, 32, 32, capture);
  VolumeBuildOptions o = test::refinedWithRays(oracle, 6);
  o.refineSubdivisions = 4;
  o.nearerSurfaces = oracle.nearerSurfaces();
  o.casterFaces = oracle.casterFaces();
  if (handOver) o.withoutCasters = oracle.withoutCasters();
  o.facePrisms = prisms;
  return buildVolume(map, o);
}

// Whether the ray from p straight up (towards the light) meets a triangle of `mesh`.
bool blockedFromAbove(const TriangleMesh& mesh, const glm::dvec3& p) {
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
    const glm::dvec3 d(0, 1, 0), e1 = b - a, e2 = c - a, h = glm::cross(d, e2);
    const double det = glm::dot(e1, h);
    if (det == 0.0) continue;
    const glm::dvec3 s = p - a;
    const double u = glm::dot(s, h) / det, v = glm::dot(d, glm::cross(s, e1)) / det;
    if (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && glm::dot(e2, glm::cross(s, e1)) / det > 0.0) return true;
  }
  return false;
}

TEST(FacePrismsVolume, APartOfItsOwnThatHoldsNoLitPoint) {
  const Scene scene = sphereOverGround();
  const VolumeBuildResult without = build(scene, false), with = build(scene, true);
  EXPECT_TRUE(without.mesh.partStarts.empty());
  EXPECT_EQ(without.stats.prismFaces, 0u);
  ASSERT_EQ(with.mesh.partCount(), 2u);
  EXPECT_GT(with.stats.prismFaces, 0u);
  EXPECT_EQ(with.stats.prismTriangles, with.mesh.triangleCount() - with.mesh.partStarts[0]);
  // The first part is the volume without prisms, to the bit.
  ASSERT_EQ(with.mesh.partStarts[0], without.mesh.triangleCount());
  EXPECT_TRUE(std::equal(without.mesh.triangles.begin(), without.mesh.triangles.end(), with.mesh.triangles.begin()));
  EXPECT_TRUE(std::equal(without.mesh.positions.begin(), without.mesh.positions.end(), with.mesh.positions.begin()));
  EXPECT_TRUE(test::closedOrientedManifold(with.mesh));
  const VolumeMesh prisms = with.mesh.partMesh(1);
  EXPECT_TRUE(test::closedOrientedManifold(prisms));
  // Points on a grid around the sphere's shadow (some inside the sphere): inside the prisms only
  // where the sphere is above or around them.
  const TriangleMesh& sphere = scene.objects[1].mesh;
  int inside = 0;
  for (double x = -1.2; x <= 1.2; x += 0.05)
    for (double y : {0.05, 0.5, 1.2})
      for (double z : {-0.33, 0.0, 0.71}) {
        const glm::dvec3 p(x, y, z);
        const int w = test::windingNumber(prisms, p - prisms.origin);
        EXPECT_GE(w, 0);
        if (w == 0) continue;
        ++inside;
        EXPECT_TRUE(blockedFromAbove(sphere, p)) << x << " " << y << " " << z;
      }
  EXPECT_GT(inside, 20);  // the test looks at something
}

// With withoutCasters the sheet records the ground in the refined quads' columns and the prisms
// hold the sphere's shadow there: the union is the exact shadow at every grid point clear of the
// sphere's surface, and near the outline only the prisms hold it.
TEST(FacePrismsVolume, TheSheetHandsTheOutlinesColumnsToThePrisms) {
  const Scene scene = sphereOverGround();
  const VolumeBuildResult with = build(scene, true, true);
  ASSERT_EQ(with.mesh.partCount(), 2u);
  EXPECT_GT(with.stats.prismColumnTexels, 0u);
  EXPECT_GE(with.stats.raysCast, with.stats.prismColumnTexels);
  EXPECT_TRUE(test::closedOrientedManifold(with.mesh));
  const VolumeMesh sheet = with.mesh.partMesh(0), prisms = with.mesh.partMesh(1);
  EXPECT_TRUE(test::closedOrientedManifold(sheet));
  EXPECT_TRUE(test::closedOrientedManifold(prisms));
  const TriangleMesh& sphere = scene.objects[1].mesh;
  const glm::dvec3 centre(0.0, 2.0, 0.0);
  int shadowed = 0, lit = 0;
  for (double x = -1.6; x <= 1.6; x += 0.05)
    for (double y : {0.05, 0.5, 1.2, 1.9, 2.6, 3.2})
      for (double z : {-0.33, 0.0, 0.71}) {
        const glm::dvec3 p(x, y, z);
        if (std::abs(glm::length(p - centre) - 1.0) < 0.05) continue;  // the surface's own tie
        if (glm::length(p - centre) < 1.0) continue;                   // inside the caster
        const bool inside = test::windingNumber(sheet, p - sheet.origin) != 0 ||
                            test::windingNumber(prisms, p - prisms.origin) != 0;
        const bool blocked = blockedFromAbove(sphere, p);
        EXPECT_EQ(inside, blocked) << x << " " << y << " " << z;
        (blocked ? shadowed : lit) += 1;
      }
  EXPECT_GT(shadowed, 50);
  EXPECT_GT(lit, 50);
  // Just under the outline, in a handed-over column: the prisms' shadow, not the sheet's.
  const glm::dvec3 underRim(0.97, 1.5, 0.0);
  ASSERT_TRUE(blockedFromAbove(sphere, underRim));
  EXPECT_EQ(test::windingNumber(sheet, underRim - sheet.origin), 0);
  EXPECT_NE(test::windingNumber(prisms, underRim - prisms.origin), 0);
}

// Nothing to hand over: an open plate over the ground (no closed caster; front capture, what
// --capture auto takes for it) leaves the refined quads to the sheet, and the volume is the one
// without the hand-over, to the bit.
TEST(FacePrismsVolume, AnOpenCasterStaysTheSheets) {
  TriangleMesh plate = makePlane(2.0, 2.0, 1);
  for (auto& p : plate.positions) p.y += 1.5f;
  const Scene scene =
      test::sceneWith({SceneObject{"ground", "plane", makePlane(8.0, 8.0, 1)}, SceneObject{"plate", "mesh", plate}});
  const VolumeBuildResult kept = build(scene, true, false, CaptureMode::Front),
                          handed = build(scene, true, true, CaptureMode::Front);
  EXPECT_GT(handed.stats.refinedCells, 0u);
  EXPECT_EQ(handed.stats.prismColumnTexels, 0u);
  EXPECT_EQ(handed.stats.prismFaces, 0u);
  EXPECT_TRUE(std::equal(kept.mesh.triangles.begin(), kept.mesh.triangles.end(), handed.mesh.triangles.begin(),
                         handed.mesh.triangles.end()));
  EXPECT_TRUE(std::equal(kept.mesh.positions.begin(), kept.mesh.positions.end(), handed.mesh.positions.begin(),
                         handed.mesh.positions.end()));
}

// An open plate over the sphere stays the sheet's wherever it is recorded: under front capture
// (what --capture auto takes for a scene with an open mesh) everywhere, under entry capture where
// the sphere's back face lies behind it (entry capture records no open face with no back face
// behind it: beyond the sphere's outline the plate is not in the map, with or without the prisms).
// Between the plate and the sphere its shadow is kept; the union is the exact shadow of both.
TEST(FacePrismsVolume, AnOpenPlateRecordedInFrontOfAHandedMeshKeepsItsShadow) {
  TriangleMesh plate = makePlane(1.2, 1.2, 1);
  for (auto& p : plate.positions) p += glm::vec3(0.6f, 3.6f, 0.0f);
  Scene scene = sphereOverGround();
  scene.objects.push_back(SceneObject{"plate", "mesh", plate});
  for (const CaptureMode capture : {CaptureMode::Front, CaptureMode::Entry}) {
    const VolumeBuildResult with = build(scene, true, true, capture);
    ASSERT_EQ(with.mesh.partCount(), 2u);
    EXPECT_GT(with.stats.prismColumnTexels, 0u);
    const VolumeMesh sheet = with.mesh.partMesh(0), prisms = with.mesh.partMesh(1);
    const glm::dvec3 centre(0.0, 2.0, 0.0);
    const double xMax = capture == CaptureMode::Entry ? 0.85 : 1.6;  // entry: where the sphere lies behind
    int plateOnly = 0;
    for (double x = -1.6; x <= xMax; x += 0.05)
      for (double y : {0.5, 1.2, 3.1, 3.3})
        for (double z : {-0.33, 0.0, 0.41}) {
          const glm::dvec3 p(x, y, z);
          if (std::abs(glm::length(p - centre) - 1.0) < 0.05 || glm::length(p - centre) < 1.0) continue;
          if (std::abs(x) < 0.03 || std::abs(x - 1.2) < 0.03) continue;  // the plate's edges' own ties
          const bool inside = test::windingNumber(sheet, p - sheet.origin) != 0 ||
                              test::windingNumber(prisms, p - prisms.origin) != 0;
          const bool bySphere = blockedFromAbove(scene.objects[1].mesh, p), byPlate = blockedFromAbove(plate, p);
          EXPECT_EQ(inside, bySphere || byPlate) << toString(capture) << " " << x << " " << y << " " << z;
          plateOnly += byPlate && !bySphere;
        }
    EXPECT_GT(plateOnly, 10) << toString(capture);  // the plate's own shadow was looked at
  }
}

}  // namespace
}  // namespace shadowvol

// Orienting closed meshes outward (mesh_orientation.h): inside-out and shuffled windings repaired;
// hollow solids, open, non-manifold, non-orientable and flat meshes left as stored.
#include <gtest/gtest.h>

#include <utility>

#include "shadowvol/mesh_orientation.h"
#include "shadowvol/primitives.h"

namespace shadowvol {
namespace {

std::vector<glm::dvec3> worldOf(const TriangleMesh& m, const glm::dvec3& offset = glm::dvec3(0.0)) {
  std::vector<glm::dvec3> w;
  for (const auto& p : m.positions) w.push_back(glm::dvec3(p) + offset);
  return w;
}

void reverse(TriangleMesh& m, std::size_t t) {
  std::swap(m.triangles[t][1], m.triangles[t][2]);
}

TriangleMesh reversedAll(TriangleMesh m) {
  for (std::size_t t = 0; t < m.triangleCount(); ++t) reverse(m, t);
  return m;
}

TEST(MeshOrientation, OutwardMeshesAreLeftAlone) {
  for (const TriangleMesh& outward : {makeBox(1.0, 2.0, 3.0), makeIcoSphere(1.0, 2), makeCylinder(0.5, 1.0, 16)}) {
    TriangleMesh m = outward;
    const OrientationResult r = orientOutward(m, worldOf(m));
    EXPECT_EQ(r.reversed, 0u);
    EXPECT_FALSE(r.insideOut);
    EXPECT_GT(r.volumeBefore, 0.0);
    EXPECT_TRUE(r.left.empty()) << r.left;
    EXPECT_EQ(m.triangles, outward.triangles);
  }
}

TEST(MeshOrientation, InsideOutMeshIsReversed) {
  const TriangleMesh sphere = makeIcoSphere(1.0, 2);
  TriangleMesh m = reversedAll(sphere);
  const OrientationResult r = orientOutward(m, worldOf(m, glm::dvec3(1e7, -3e6, 0.0)));  // far from the origin
  EXPECT_TRUE(r.insideOut);
  EXPECT_LT(r.volumeBefore, 0.0);
  EXPECT_EQ(r.reversed, sphere.triangleCount());
  EXPECT_EQ(r.repairedComponents, 0u);
  EXPECT_EQ(m.triangles, sphere.triangles);
}

TEST(MeshOrientation, FacesWoundAgainstTheirNeighboursAgreeAndFaceOutward) {
  const TriangleMesh sphere = makeIcoSphere(1.0, 2);
  for (const bool startInsideOut : {false, true}) {
    TriangleMesh m = startInsideOut ? reversedAll(sphere) : sphere;
    std::size_t shuffled = 0;
    for (std::size_t t = 0; t < m.triangleCount(); t += 3, ++shuffled) reverse(m, t);
    const OrientationResult r = orientOutward(m, worldOf(m));
    EXPECT_EQ(r.repairedComponents, 1u);
    EXPECT_EQ(r.reversed, startInsideOut ? sphere.triangleCount() - shuffled : shuffled);
    EXPECT_EQ(m.triangles, sphere.triangles) << "started inside out: " << startInsideOut;
  }
}

TEST(MeshOrientation, HollowSolidKeepsItsInnerShellInward) {
  TriangleMesh hollow = makeIcoSphere(2.0, 2);
  hollow.append(reversedAll(makeIcoSphere(1.0, 2)));  // the cavity: its faces point into it
  TriangleMesh m = hollow;
  EXPECT_EQ(orientOutward(m, worldOf(m)).reversed, 0u);
  EXPECT_EQ(m.triangles, hollow.triangles);
  // The whole solid inside out: both shells are reversed together.
  m = reversedAll(hollow);
  const OrientationResult r = orientOutward(m, worldOf(m));
  EXPECT_TRUE(r.insideOut);
  EXPECT_EQ(m.triangles, hollow.triangles);
}

TriangleMesh movedBy(TriangleMesh m, const glm::vec3& d) {
  for (auto& p : m.positions) p += d;
  return m;
}

TEST(MeshOrientation, PartInsideOutOnItsOwnIsReversed) {
  // An assembly of two separate parts, one stored inside out (a mirrored part exported as is):
  // smaller than, as large as and larger than the other (the whole volume then negative, zero up to
  // rounding, positive); only that part is reversed (a probe reversed the other with the whole).
  for (const double radius : {0.5, 1.0, 3.0}) {
    TriangleMesh outward = makeIcoSphere(1.0, 2);
    outward.append(movedBy(makeIcoSphere(radius, 2), {6.0f, 0.0f, 0.0f}));
    TriangleMesh m = makeIcoSphere(1.0, 2);
    m.append(movedBy(reversedAll(makeIcoSphere(radius, 2)), {6.0f, 0.0f, 0.0f}));
    const OrientationResult r = orientOutward(m, worldOf(m));
    EXPECT_EQ(r.looseParts, 1u) << "second part's radius " << radius;
    EXPECT_FALSE(r.insideOut);
    EXPECT_EQ(r.reversed, makeIcoSphere(1.0, 2).triangleCount());
    EXPECT_EQ(m.triangles, outward.triangles);
  }
}

TEST(MeshOrientation, IntersectingOrTouchingPartsAreOrientedEachOnItsOwn) {
  // Two spheres overlapping by a fifth of their size, the second inside out: the second alone is
  // reversed, whatever the sign of the whole (a probe saw it decided by rounding).
  TriangleMesh overlapping = makeIcoSphere(1.0, 2);
  overlapping.append(movedBy(makeIcoSphere(1.0, 2), {1.6f, 0.0f, 0.0f}));
  TriangleMesh m = makeIcoSphere(1.0, 2);
  m.append(movedBy(reversedAll(makeIcoSphere(1.0, 2)), {1.6f, 0.0f, 0.0f}));
  orientOutward(m, worldOf(m));
  EXPECT_EQ(m.triangles, overlapping.triangles);
  // Two tetrahedra touching at a corner, one inside out.
  TriangleMesh bowtie;
  bowtie.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  bowtie.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 4, 5}, {0, 6, 4}, {0, 5, 6}, {4, 6, 5}};
  TriangleMesh b = bowtie;
  for (std::size_t t = 4; t < 8; ++t) reverse(b, t);
  const OrientationResult r = orientOutward(b, worldOf(b));
  EXPECT_EQ(r.reversed, 4u);
  EXPECT_EQ(b.triangles, bowtie.triangles);
}

TEST(MeshOrientation, ContainmentBudgetTakesUncheckedPartsAsNotNested) {
  // A hollow solid with three cavities (inward spheres inside a large outward one).
  TriangleMesh hollow = makeIcoSphere(3.0, 2);
  for (const float x : {-1.0f, 0.0f, 1.0f}) hollow.append(movedBy(reversedAll(makeIcoSphere(0.3, 1)), {x, 0.0f, 0.0f}));
  TriangleMesh m = hollow;
  const OrientationResult full = orientOutward(m, worldOf(m));
  EXPECT_EQ(full.partsNotChecked, 0u);
  EXPECT_EQ(full.reversed, 0u);  // found inside the large sphere: cavities, kept inward
  // With fewer tests than one sphere's triangles, none is checked: each taken as a solid of its own.
  const OrientationResult r = orientOutward(m, worldOf(m), 10);
  EXPECT_EQ(r.partsNotChecked, 3u);
  EXPECT_EQ(r.looseParts, 3u);
  EXPECT_EQ(r.reversed, 3 * makeIcoSphere(0.3, 1).triangleCount());
}

TEST(MeshOrientation, PartPushedIntoAnotherIsLeftAlone) {
  // A small outward sphere half sunk into a large one (an eye in a head): both outward, untouched.
  TriangleMesh head = makeIcoSphere(2.0, 2);
  head.append(movedBy(makeIcoSphere(0.5, 2), {2.0f, 0.0f, 0.0f}));
  TriangleMesh m = head;
  EXPECT_EQ(orientOutward(m, worldOf(m)).reversed, 0u);
  EXPECT_EQ(m.triangles, head.triangles);
  // Stored inside out on its own, it is reversed: some of its vertices lie outside the head.
  TriangleMesh sunk = makeIcoSphere(2.0, 2);
  sunk.append(movedBy(reversedAll(makeIcoSphere(0.5, 2)), {2.0f, 0.0f, 0.0f}));
  orientOutward(sunk, worldOf(sunk));
  EXPECT_EQ(sunk.triangles, head.triangles);
}

TEST(MeshOrientation, OpenAndNonManifoldMeshesAreLeftAsStored) {
  TriangleMesh open = reversedAll(makeBox(1.0, 1.0, 1.0));
  open.triangles.pop_back();  // a hole
  TriangleMesh m = open;
  OrientationResult r = orientOutward(m, worldOf(m));
  EXPECT_NE(r.left.find("not closed"), std::string::npos) << r.left;
  EXPECT_EQ(r.reversed, 0u);
  EXPECT_EQ(m.triangles, open.triangles);

  TriangleMesh fin = reversedAll(makeBox(1.0, 1.0, 1.0));  // a third triangle on one edge
  fin.positions.push_back({3.0f, 0.0f, 0.0f});
  fin.triangles.push_back({fin.triangles[0][0], fin.triangles[0][1], std::uint32_t(fin.positions.size() - 1)});
  m = fin;
  r = orientOutward(m, worldOf(m));
  EXPECT_FALSE(r.left.empty());
  EXPECT_EQ(m.triangles, fin.triangles);

  m = makePlane(2.0, 2.0, 2);
  EXPECT_FALSE(orientOutward(m, worldOf(m)).left.empty());
  TriangleMesh empty;
  const OrientationResult none = orientOutward(empty, {});
  EXPECT_TRUE(none.left.empty()) << none.left;
  EXPECT_EQ(none.reversed, 0u);
}

TEST(MeshOrientation, OpenMeshPartsAgreeWithMostOfTheirTriangles) {
  TriangleMesh dome = makeHemisphere(1.0, 16, 4);
  dome.triangles.resize(dome.triangleCount() - 16);  // without its base disc's fan: open
  for (const bool mostFlipped : {false, true}) {
    TriangleMesh m = mostFlipped ? reversedAll(dome) : dome;
    for (std::size_t t = 0; t < m.triangleCount(); t += 5) reverse(m, t);  // a fifth wound the other way
    const OrientationResult r = orientOutward(m, worldOf(m));
    EXPECT_TRUE(r.open);
    EXPECT_FALSE(r.insideOut);
    EXPECT_EQ(r.repairedComponents, 1u);
    EXPECT_EQ(r.reversed, (dome.triangleCount() + 4) / 5);
    EXPECT_EQ(m.triangles, mostFlipped ? reversedAll(dome).triangles : dome.triangles);
  }
}

TEST(MeshOrientation, NonOrientableSurfaceIsLeftAsStored) {
  // The six-vertex projective plane: closed, every edge in two triangles, no consistent winding.
  TriangleMesh rp2;
  rp2.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}};
  rp2.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {0, 5, 1},
                   {1, 2, 4}, {2, 3, 5}, {3, 4, 1}, {4, 5, 2}, {5, 1, 3}};
  TriangleMesh m = rp2;
  const OrientationResult r = orientOutward(m, worldOf(m));
  EXPECT_NE(r.left.find("orientable"), std::string::npos) << r.left;
  EXPECT_EQ(m.triangles, rp2.triangles);
}

TEST(MeshOrientation, FlatDoubleSidedSheetIsNotReversedByRounding) {
  // A quad stored with both windings (each side its own diagonal, so every edge has two
  // triangles): closed, signed volume zero up to rounding, also far from the origin.
  TriangleMesh sheet;
  sheet.positions = {{0.1f, 0.3f, 0.7f}, {1.3f, 0.3f, 0.9f}, {1.1f, 0.3f, 2.2f}, {0.2f, 0.3f, 1.9f}};
  sheet.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 0, 3}, {1, 3, 2}};
  for (const glm::dvec3 offset : {glm::dvec3(0.0), glm::dvec3(1e7, 1e7, -1e7)}) {
    TriangleMesh m = sheet;
    const OrientationResult r = orientOutward(m, worldOf(m, offset));
    EXPECT_TRUE(r.left.empty()) << r.left;
    EXPECT_EQ(r.reversed, 0u);
    EXPECT_EQ(m.triangles, sheet.triangles);
  }
}

TEST(MeshOrientation, DegenerateTrianglesNeitherOpenTheMeshNorStopTheRepair) {
  const TriangleMesh box = makeBox(1.0, 1.0, 1.0);
  TriangleMesh withSliver = box;
  withSliver.triangles.push_back({0, 0, 1});  // two corners at one position
  TriangleMesh m = reversedAll(withSliver);
  const OrientationResult r = orientOutward(m, worldOf(m));
  EXPECT_TRUE(r.insideOut);
  EXPECT_EQ(r.reversed, withSliver.triangleCount());
  EXPECT_EQ(m.triangles, withSliver.triangles);
}

}  // namespace
}  // namespace shadowvol

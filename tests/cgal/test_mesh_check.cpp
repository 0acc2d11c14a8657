// checkMesh on closed meshes with exactly flat (collinear) faces: they are counted, the nesting
// test still runs (over the other faces), and it ends. CGAL's point-in-volume rays retry without end
// on a flat face whose box they cross; a twelfth probe's finding (a volume written with
// --world-coords 1e5 units from the origin and read back in single precision, most of its faces
// rounded flat, hung `check`).
#include <array>
#include <filesystem>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "shadowvol/cgal/mesh_check.h"
#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/mesh_io.h"
#include "shadowvol/scene.h"
#include "shadowvol/volume_builder.h"
#include "shadowvol/volume_mesh.h"

namespace shadowvol {
namespace {

// A closed parallelepiped at `o` with integer edges e1, e2, e3, wound outward (inward with
// `inward`). With `flat`, its triangle (0, 2, 3) is instead cut at the midpoint m of the diagonal
// 0-3 into (0, 2, m) and (m, 2, 3), and the flat triangle (0, m, 3) closes the diagonal.
void addBox(VolumeMesh& mesh, glm::dvec3 o, glm::dvec3 e1, glm::dvec3 e2, glm::dvec3 e3, bool inward, bool flat) {
  const auto base = std::uint32_t(mesh.positions.size());
  for (int k = 0; k < 8; ++k)
    mesh.positions.push_back(o + double(k & 1) * e1 + double((k >> 1) & 1) * e2 + double((k >> 2) & 1) * e3);
  // Corners k = x + 2y + 4z; faces counter-clockwise from outside for a right-handed e1, e2, e3.
  std::vector<std::array<std::uint32_t, 3>> t = {{0, 3, 1}, {4, 5, 7}, {0, 1, 5}, {2, 7, 3},
                                                  {0, 6, 2}, {1, 3, 7}, {0, 5, 4}, {2, 6, 7},
                                                  {0, 4, 6}, {1, 7, 5}, {4, 7, 6}};
  if (flat) {
    const auto m = std::uint32_t(mesh.positions.size() - base);
    mesh.positions.push_back(o + 0.5 * (e1 + e2));  // exactly on the diagonal 0-3 (integer inputs)
    t.push_back({0, 2, m});
    t.push_back({m, 2, 3});
    t.push_back({0, m, 3});  // flat: its 3 -> 0 pairs (0, 3, 1)'s 0 -> 3, its other edges the two above
  } else {
    t.push_back({0, 2, 3});
  }
  for (auto tri : t) {
    if (inward) std::swap(tri[1], tri[2]);
    mesh.triangles.push_back({base + tri[0], base + tri[1], base + tri[2]});
  }
}

TEST(MeshCheck, AFlatFaceIsCountedAndTheNestingStillJudged) {
  const glm::dvec3 e1(8, 4, 0), e2(-4, 8, 4), e3(0, -4, 8);  // not axis-aligned: the flat face's box has volume
  VolumeMesh clean, flat;
  addBox(clean, {0, 0, 0}, e1, e2, e3, false, false);
  addBox(clean, {1, 1, 1}, 0.25 * e1, 0.25 * e2, 0.25 * e3, true, false);  // a cavity inside
  addBox(flat, {0, 0, 0}, e1, e2, e3, false, true);
  addBox(flat, {1, 1, 1}, 0.25 * e1, 0.25 * e2, 0.25 * e3, true, false);

  const MeshCheckReport ok = checkMesh(clean);
  ASSERT_TRUE(ok.valid()) << ok.summary();

  const MeshCheckReport r = checkMesh(flat);
  EXPECT_TRUE(r.closedManifold()) << r.summary();
  EXPECT_EQ(r.degenerateTriangles, 1u) << r.summary();
  EXPECT_TRUE(r.outward) << r.summary();  // the cavity inside, wound inward
  EXPECT_FALSE(r.valid());
  // Wound outward, the cavity is not outward, whatever the flat face.
  VolumeMesh wrong;
  addBox(wrong, {0, 0, 0}, e1, e2, e3, false, true);
  addBox(wrong, {1, 1, 1}, 0.25 * e1, 0.25 * e2, 0.25 * e3, false, false);
  EXPECT_FALSE(checkMesh(wrong).outward);
}

// The probe's case: millimetre objects 1e5 units from the origin. The volume as built (relative to
// its local origin) is valid; its world coordinates, as `build --world-coords` writes them, read
// back in single precision round most of its faces flat, and checking that hung in CGAL's nesting
// test before flat faces were kept from it. `check` reads the file rebased, and finds it valid.
TEST(MeshCheck, AVolumeInWorldCoordinatesFarFromTheOriginEnds) {
  const char* json = R"({"objects": [
      {"type": "plane", "size": 0.01, "transform": {"translate": [100000, -100000, 30000]}},
      {"type": "sphere", "radius": 0.001, "transform": {"translate": [100000, -99999.998, 30000]}},
      {"type": "box", "size": 0.001, "transform": {"translate": [100000.002, -99999.9995, 30000.001], "rotate": [0, 30, 0]}}],
    "camera": {"eye": [100000, -99999.994, 30000.011], "target": [100000, -99999.999, 30000]},
    "light": {"type": "spot", "position": [100000.003, -99999.991, 30000.002],
              "target": [99999.9997, -100000, 29999.9998], "fov": 55}})";
  const Scene scene = parseScene(json, "far-mm.json", ".").scene;
  VolumeMesh volume = buildVolume(captureDepthEmbree(scene, 128, 128, CaptureMode::Back), {}).mesh;
  const MeshCheckReport local = checkMesh(volume);
  ASSERT_TRUE(local.valid()) << local.summary();
  // Written in world coordinates, then read back in float as they are (readTriangleMesh): most
  // faces round flat, and the check still ends; read as `check` reads it (rebased before the
  // rounding), the volume is valid as it was built.
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "shadowvol-far-mm-world.obj";
  writeVolumeMesh(volume, file, true);
  const TriangleMesh rounded = readTriangleMesh(file);
  const RebasedMesh rebased = readRebasedTriangleMesh(file);
  std::filesystem::remove(file);
  auto asVolume = [](const TriangleMesh& m) {
    VolumeMesh v;
    v.positions.assign(m.positions.begin(), m.positions.end());
    v.triangles.assign(m.triangles.begin(), m.triangles.end());
    return v;
  };
  const MeshCheckReport world = checkMesh(asVolume(rounded));
  EXPECT_TRUE(world.closedManifold()) << world.summary();
  ASSERT_GT(world.degenerateTriangles, 0u) << world.summary();
  EXPECT_FALSE(world.valid());
  EXPECT_GT(glm::length(rebased.origin), 1e5);
  const MeshCheckReport kept = checkMesh(asVolume(rebased.mesh));
  EXPECT_TRUE(kept.valid()) << kept.summary();
  EXPECT_EQ(kept.triangles, local.triangles);
}

// A vertex is non-manifold when its triangles are not one fan: a boundary vertex's open fan is one
// (its missing edges are the boundary edges), two fans meeting at a vertex are not (a fifteenth
// probe's finding: every corner of an open square was called non-manifold, and so was every
// vertex of a triangle soup).
TEST(MeshCheck, ABoundaryVertexIsNotNonManifoldTwoFansAtAVertexAre) {
  VolumeMesh square;
  square.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  const MeshCheckReport open = checkMesh(square);
  EXPECT_EQ(open.boundaryEdges, 4u) << open.summary();
  EXPECT_EQ(open.nonManifoldVertices, 0u) << open.summary();
  EXPECT_FALSE(open.closedManifold());
  // A bow tie: two triangles meeting at vertex 0 only.
  VolumeMesh bowTie;
  bowTie.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
  bowTie.triangles = {{0, 1, 2}, {0, 3, 4}};
  EXPECT_EQ(checkMesh(bowTie).nonManifoldVertices, 1u) << checkMesh(bowTie).summary();
  // Two closed boxes sharing a corner: closed fans, two of them at the shared vertex.
  VolumeMesh pinched;
  addBox(pinched, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, false, false);
  addBox(pinched, {1, 1, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, false, false);
  for (auto& t : pinched.triangles)
    for (auto& i : t)
      if (i == 8) i = 7;  // the second box's corner 0 is the first's corner 7
  const MeshCheckReport pinch = checkMesh(pinched);
  EXPECT_EQ(pinch.boundaryEdges, 0u) << pinch.summary();
  EXPECT_EQ(pinch.nonManifoldVertices, 1u) << pinch.summary();
  EXPECT_FALSE(pinch.closedManifold());
  // The box as a soup (three corners of its own per triangle): boundary edges and coincident
  // vertices, no non-manifold vertex.
  VolumeMesh box, soup;
  addBox(box, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, false, false);
  for (const auto& t : box.triangles) {
    const auto base = std::uint32_t(soup.positions.size());
    for (std::uint32_t i : t) soup.positions.push_back(box.positions[i]);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  const MeshCheckReport s = checkMesh(soup);
  EXPECT_EQ(s.boundaryEdges, 36u) << s.summary();
  EXPECT_EQ(s.nonManifoldVertices, 0u) << s.summary();
  EXPECT_EQ(s.coincidentVertices, 36u - 8u) << s.summary();
}

}  // namespace
}  // namespace shadowvol

// Silhouette shadow volumes on the CPU (silhouette_volume.h): closedness and orientation of the
// volume, the silhouette of a box seen along an axis, the caster / receiver rule and the refusal
// of non-manifold objects by name.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include <glm/geometric.hpp>

#include "shadowvol/error.h"
#include "shadowvol/primitives.h"
#include "shadowvol/silhouette_volume.h"
#include "test_util.h"

using namespace shadowvol;

namespace {

SceneObject moved(std::string name, std::string type, TriangleMesh mesh, glm::vec3 offset) {
  for (auto& p : mesh.positions) p += offset;
  return SceneObject{std::move(name), std::move(type), std::move(mesh)};
}

Light spotAbove() {
  Light l;
  l.type = LightType::Spot;
  l.position = {0.3, 8.0, -0.2};
  l.direction = glm::normalize(glm::dvec3(0.0, -1.0, 0.05));
  l.fovYDegrees = 60.0;
  l.nearPlane = 0.5;
  l.farPlane = 20.0;
  return l;
}

Light directionalTilted() {
  Light l;
  l.type = LightType::Directional;
  l.direction = glm::normalize(glm::dvec3(0.3, -1.0, 0.2));
  l.position = glm::dvec3(0.0) - 10.0 * l.direction;
  l.halfExtent = 8.0;
  l.nearPlane = 0.1;
  l.farPlane = 25.0;
  return l;
}

Scene sceneOf(std::vector<SceneObject> objects, const Light& light) {
  Scene s;
  s.source = "silhouette (test)";
  s.objects = std::move(objects);
  s.light = light;
  return s;
}

/// Every directed edge exactly once and its reverse exactly once; the signed volume (divergence
/// theorem) is positive, i.e. the triangles face outward.
void expectClosedAndOutward(const VolumeMesh& m, const std::string& what) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) directed[{t[k], t[(k + 1) % 3]}] += 1;
  std::size_t bad = 0;
  for (const auto& [e, n] : directed) {
    const auto r = directed.find({e.second, e.first});
    bad += n != 1 || r == directed.end() || r->second != 1;
  }
  EXPECT_EQ(bad, 0u) << what;
  double volume = 0.0;
  for (const auto& t : m.triangles)
    volume += glm::dot(m.positions[t[0]], glm::cross(m.positions[t[1]], m.positions[t[2]])) / 6.0;
  EXPECT_GT(volume, 0.0) << what;
  std::printf("%s: %zu triangles, signed volume %.3f\n", what.c_str(), m.triangleCount(), volume);
}

}  // namespace

TEST(SilhouetteVolume, ClosedAndConsistentlyOrientedForSpotAndDirectional) {
  for (const Light& light : {spotAbove(), directionalTilted()}) {
    const char* lightName = light.type == LightType::Spot ? "spot" : "directional";
    for (auto [name, mesh] : {std::pair{"box", makeBox(1.5, 0.7, 1.1)}, std::pair{"sphere", makeIcoSphere(1.0, 3)},
                              std::pair{"tree", makeTree(0.1, 1.2, 0.5, 2)}}) {
      const Scene s = sceneOf({moved(name, name, mesh, {0.2f, 1.5f, 0.1f})}, light);
      const SilhouetteVolume v = buildSilhouetteVolume(s);
      EXPECT_GT(v.silhouetteEdges, 0u);
      EXPECT_EQ(v.lightCapTriangles + v.darkCapTriangles, mesh.triangleCount());
      EXPECT_EQ(v.mesh.triangleCount(), mesh.triangleCount() + 2 * v.silhouetteEdges);
      EXPECT_DOUBLE_EQ(v.extrusionDepth, light.farPlane);
      expectClosedAndOutward(v.mesh, std::string(name) + ", " + lightName);
    }
  }
}

TEST(SilhouetteVolume, DarkCapLiesAtTheExtrusionDepth) {
  const Light light = spotAbove();
  const Scene s = sceneOf({moved("sphere", "sphere", makeIcoSphere(1.0, 2), {0.0f, 2.0f, 0.0f})}, light);
  const SilhouetteVolume v = buildSilhouetteVolume(s);
  const glm::dvec3 dir = glm::normalize(light.direction);
  std::size_t atFar = 0;
  for (const auto& p : v.mesh.positions) {
    const double d = glm::dot(p - light.position, dir);
    if (std::abs(d - light.farPlane) < 1e-9 * light.farPlane)
      ++atFar;
    else
      EXPECT_LT(d, 7.5);  // the sphere's own vertices (depth 5 to 7)
  }
  EXPECT_GT(atFar, 0u);
}

TEST(SilhouetteVolume, BoxSeenAlongAnAxisHasItsFourTopEdges) {
  Light down = directionalTilted();
  down.direction = {0.0, -1.0, 0.0};
  down.position = {0.0, 10.0, 0.0};
  Light spot = spotAbove();
  spot.position = {0.1, 6.0, 0.05};  // above the box's top face, inside its footprint
  spot.direction = {0.0, -1.0, 0.0};
  for (const Light& light : {down, spot}) {
    const Scene s = sceneOf({moved("box", "box", makeBox(2.0, 1.0, 1.0), {0.0f, 0.5f, 0.0f})}, light);
    const SilhouetteOccluders occ(s);
    const auto edges = occ.silhouetteEdges(0, light);
    ASSERT_EQ(edges.size(), 4u);
    std::set<std::pair<std::pair<double, double>, std::pair<double, double>>> got;
    for (const auto& e : edges) {
      EXPECT_EQ(e[0].y, 1.0);  // the top face
      EXPECT_EQ(e[1].y, 1.0);
      got.insert({{e[0].x, e[0].z}, {e[1].x, e[1].z}});
    }
    // Counter-clockwise seen from above (+Y, looking down, x right, z toward the viewer).
    const std::set<std::pair<std::pair<double, double>, std::pair<double, double>>> expected{
        {{-1.0, 0.5}, {1.0, 0.5}}, {{1.0, 0.5}, {1.0, -0.5}}, {{1.0, -0.5}, {-1.0, -0.5}}, {{-1.0, -0.5}, {-1.0, 0.5}}};
    EXPECT_EQ(got, expected);
    const SilhouetteVolume v = buildSilhouetteVolume(s);
    EXPECT_EQ(v.silhouetteEdges, 4u);
    EXPECT_EQ(v.lightCapTriangles, 2u);  // the top face
    EXPECT_EQ(v.darkCapTriangles, 10u);  // the bottom and the edge-on sides (facing away by rule)
  }
}

TEST(SilhouetteVolume, OpenSheetsAreReceiversOnly) {
  const Scene s = sceneOf({SceneObject{"ground", "plane", makePlane(10.0, 10.0, 3)},
                           moved("ball", "sphere", makeIcoSphere(0.5, 2), {0.0f, 1.0f, 0.0f})},
                          spotAbove());
  const SilhouetteOccluders occ(s);
  ASSERT_EQ(occ.objects().size(), 2u);
  EXPECT_EQ(occ.objects()[0].role, SilhouetteRole::ReceiverOnly);
  EXPECT_EQ(occ.objects()[0].boundaryEdges, 12u);
  EXPECT_EQ(occ.objects()[1].role, SilhouetteRole::Caster);
  const SilhouetteVolume v = buildSilhouetteVolume(occ, s.light);
  EXPECT_EQ(v.receiversOnly, std::vector<std::string>{"ground"});
  EXPECT_EQ(v.lightCapTriangles + v.darkCapTriangles, makeIcoSphere(0.5, 2).triangleCount());
  expectClosedAndOutward(v.mesh, "ball over an open ground");
}

// A mesh with split vertices (as STL files store them) is welded: still a closed caster.
TEST(SilhouetteVolume, SplitVerticesAreWelded) {
  const TriangleMesh split = test::splitVertices(makeBox(1.0, 1.0, 1.0));
  const Scene s = sceneOf({moved("stl box", "mesh", split, {0.0f, 1.0f, 0.0f})}, directionalTilted());
  const SilhouetteOccluders occ(s);
  EXPECT_EQ(occ.objects()[0].role, SilhouetteRole::Caster);
  EXPECT_EQ(occ.objects()[0].vertices, 8u);
  expectClosedAndOutward(buildSilhouetteVolume(occ, s.light).mesh, "welded box");
}

// Regression (cow.off from libcgal-demo, vertices 44 and 2903 at identical coordinates): a mesh
// that is closed as stored casts, even where welding by position would make two fans touch.
TEST(SilhouetteVolume, ClosedMeshWithTwoVerticesAtOnePointCasts) {
  // Two closed tetrahedra touching at one point, stored with a vertex each there.
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}, {0, 0, 0}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {7, 4, 5}, {7, 6, 4}, {7, 5, 6}, {4, 6, 5}};
  const Scene s = sceneOf({moved("touching pair", "mesh", m, {0.0f, 2.0f, 0.0f})}, directionalTilted());
  const SilhouetteOccluders occ(s);
  EXPECT_EQ(occ.objects()[0].role, SilhouetteRole::Caster);
  EXPECT_EQ(occ.objects()[0].vertices, 8u);  // as stored, not welded
  expectClosedAndOutward(buildSilhouetteVolume(occ, s.light).mesh, "touching pair");
}

TEST(SilhouetteVolume, NonManifoldObjectsAreRefusedByName) {
  auto expectRefused = [](TriangleMesh mesh, const std::string& fragment) {
    const Scene s = sceneOf({SceneObject{"ground", "plane", makePlane(10.0, 10.0, 1)},
                             moved("broken thing", "mesh", std::move(mesh), {0.0f, 1.0f, 0.0f})},
                            spotAbove());
    try {
      SilhouetteOccluders occ(s);
      ADD_FAILURE() << "accepted: " << fragment;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("'broken thing'"), std::string::npos) << what;
      EXPECT_NE(what.find(fragment), std::string::npos) << what;
      EXPECT_EQ(e.field(), "/objects/1");  // a JSON pointer (it once held the object's name)
      std::printf("refused: %s\n", what.c_str());
    }
  };
  {  // a fin: a third triangle on an edge of a closed box
    TriangleMesh m = makeBox(1.0, 1.0, 1.0);
    const auto t = m.triangles[0];
    m.positions.push_back({0.0f, 3.0f, 0.0f});
    m.triangles.push_back({t[0], t[1], std::uint32_t(m.positions.size() - 1)});
    expectRefused(m, "non-manifold edge");
  }
  {  // one triangle flipped
    TriangleMesh m = makeBox(1.0, 1.0, 1.0);
    std::swap(m.triangles[3][1], m.triangles[3][2]);
    expectRefused(m, "inconsistently oriented");
  }
  {  // two closed tetrahedra sharing one vertex: every edge fine, the vertex is two fans
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 4, 5}, {0, 6, 4}, {0, 5, 6}, {4, 6, 5}};
    expectRefused(m, "non-manifold (two fans touching at a vertex)");
  }
}

TEST(SilhouetteVolume, SpotLightApexPlane) {
  Light light = spotAbove();
  // Entirely behind the light: skipped; straddling the apex plane: refused by name.
  const Scene behind = sceneOf({moved("attic", "box", makeBox(1.0, 1.0, 1.0), {0.0f, 12.0f, 0.0f}),
                                moved("ball", "sphere", makeIcoSphere(0.5, 1), {0.0f, 1.0f, 0.0f})},
                               light);
  const SilhouetteVolume v = buildSilhouetteVolume(behind);
  EXPECT_EQ(v.skipped, std::vector<std::string>{"attic"});
  expectClosedAndOutward(v.mesh, "ball, attic skipped");
  const Scene straddling = sceneOf({moved("pole", "box", makeBox(0.2, 6.0, 0.2), {2.0f, 7.0f, 0.0f})}, light);
  try {
    buildSilhouetteVolume(straddling);
    ADD_FAILURE() << "a caster through the apex plane was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'pole'"), std::string::npos) << e.what();
    EXPECT_EQ(e.field(), "/objects/0");
  }
}

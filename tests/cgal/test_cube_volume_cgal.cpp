// The point light's volume (cube_volume.h) checked with CGAL: closed, outward, welded and free
// of zero-area triangles on the shipped point-light scene in every option combination, and on
// random cube maps whose far texels make every pinch and cut the vertex rule has to split;
// points inside it are the points behind the sheet.
#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "shadowvol/cgal/mesh_check.h"
#include "shadowvol/cube_volume.h"
#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/embree/embree_depth_oracle.h"
#include "shadowvol/error.h"
#include "shadowvol/scene.h"
#include "test_util.h"

namespace shadowvol {
namespace {

Light pointLight(double near = 0.1, double far = 10.0) {
  Light l;
  l.type = LightType::Point;
  l.position = {0.5, -0.25, 1.0};
  l.nearPlane = near;
  l.farPlane = far;
  return l;
}

// Allowed contact: the closed volume has zero thickness where the sheet reaches the far cube (at
// far vertices, which lie on its face planes).
std::function<bool(const glm::dvec3&)> onFarCube(const CubeDepthMap& cube) {
  const glm::dvec3 light = cube.lightPosition();
  const double far = cube.farPlane();
  return [light, far](const glm::dvec3& p) { return std::abs(cubeDepth(p - light) - far) <= 1e-7 * far; };
}

void expectValid(const CubeDepthMap& cube, const VolumeBuildOptions& o, const std::string& what, bool selfCheck) {
  const VolumeBuildResult r = buildCubeVolume(cube, o);
  MeshCheckOptions co;
  co.selfIntersections = selfCheck;
  co.allowedTouch = onFarCube(cube);
  const MeshCheckReport rep = checkMesh(r.mesh, co);
  EXPECT_TRUE(rep.valid()) << what << ": " << rep.summary();
  EXPECT_EQ(rep.coincidentVertices, r.stats.splitVertices) << what << ": " << rep.summary();
  if (o.refineSteps == 0) {  // refined: the walls come on top (they have no far image)
    EXPECT_EQ(r.mesh.triangleCount(), r.stats.capTrianglesBefore + r.stats.capTrianglesAfter) << what;
  } else if (r.stats.boundaryEdges > 0) {
    EXPECT_GT(r.mesh.triangleCount(), r.stats.capTrianglesBefore + r.stats.capTrianglesAfter) << what;
  }
  if (!r.mesh.triangles.empty()) {  // the orientation test is not fooled by the far vertices' contacts
    VolumeMesh reversed = r.mesh;
    for (auto& t : reversed.triangles) std::swap(t[1], t[2]);
    EXPECT_FALSE(checkMesh(reversed).outward) << what << " reversed";
  }
  if (!o.flattenCap) {
    EXPECT_EQ(r.stats.capTrianglesAfter, r.stats.capTrianglesBefore) << what;
  }
}

// The shipped room at the face sizes `sizes` in every capture mode, triangulation, blur and cap;
// with `refineSteps`, refined by the scene's rays (cube_refinement.h), with walls.
void expectValidOnTheRoom(std::initializer_list<int> sizes, int refineSteps) {
  const Scene scene = loadScene(test::sourceDir() / "data" / "scenes" / "point" / "room.json").scene;
  ASSERT_EQ(scene.light.type, LightType::Point);
  const EmbreeDepthOracle oracle(scene);
  for (int n : sizes)
    for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front, CaptureMode::Midpoint}) {
      const CubeDepthMap cube = captureCubeEmbree(scene, n, mode);
      for (Triangulation t : {Triangulation::Fixed, Triangulation::Perfect})
        for (bool blur : {false, true})
          for (bool flatten : {false, true}) {
            VolumeBuildOptions o;
            o.triangulation = t;
            o.blur = blur;
            o.blurOffset = blur ? 0.01 : 0.0;
            o.flattenCap = flatten;
            o.refineSteps = refineSteps;
            if (refineSteps > 0) o.depthOracle = oracle.oracle();
            const std::string what = std::to_string(n) + " " + toString(mode) + " " + toString(t) +
                                     (blur ? " blur" : "") + (flatten ? " flattened" : " mirrored") +
                                     (refineSteps > 0 ? " refined" : "");
            expectValid(cube, o, what, n == 8);
            if (refineSteps == 0) continue;
            const VolumeBuildResult r = buildCubeVolume(cube, o);
            EXPECT_GT(r.stats.boundaryEdges, 0u) << what;
            EXPECT_GT(r.stats.refinedCells, 0u) << what;
            EXPECT_EQ(r.stats.raysCast, std::size_t(refineSteps) * r.stats.boundaryEdges + r.stats.ambiguousCells)
                << what;
          }
    }
}

TEST(CubeVolumeCgal, ClosedOnThePointRoomInEveryCombination) { expectValidOnTheRoom({8, 17, 32}, 0); }

TEST(CubeVolumeCgal, RefinedClosedOnThePointRoomInEveryCombination) { expectValidOnTheRoom({8, 17}, 3); }

// The cells are triangulated in parallel chunks (and refinement's rays batched): the mesh is the
// same with one thread, refined or not, front capture keeping every cell.
TEST(CubeVolumeCgal, TheSameMeshWithOneThread) {
  const Scene scene = loadScene(test::sourceDir() / "data" / "scenes" / "point" / "room.json").scene;
  const EmbreeDepthOracle oracle(scene);
  for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front}) {
    const CubeDepthMap cube = captureCubeEmbree(scene, 64, mode);
    for (int refine : {0, 4}) {
      VolumeBuildOptions o;
      o.refineSteps = refine;
      if (refine > 0) o.depthOracle = oracle.oracle();
      const VolumeBuildResult parallel = buildCubeVolume(cube, o);
      VolumeBuildResult serial;
      {
        tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
        serial = buildCubeVolume(cube, o);
      }
      EXPECT_EQ(parallel.mesh.positions, serial.mesh.positions) << toString(mode) << " " << refine;
      EXPECT_EQ(parallel.mesh.triangles, serial.mesh.triangles) << toString(mode) << " " << refine;
      EXPECT_GT(parallel.stats.flippedQuads, 0u);
    }
  }
}

// An oracle for a synthetic cube map: the depth of the texel nearest the point, on the face
// whose pyramid holds it (a step function; its crossings land on the texels' borders).
DepthOracle nearestTexelOracle(const CubeDepthMap& cube) {
  return [&cube](const DepthMap& m, std::span<const glm::dvec2> ndc, std::span<float> depth) {
    const TexelUnprojector unproject(m);
    for (std::size_t k = 0; k < ndc.size(); ++k) {
      const double i = (ndc[k].x + 1.0) * 0.5 * m.width - 0.5, j = (ndc[k].y + 1.0) * 0.5 * m.height - 0.5;
      const CubeLookup l = cubeLookup(unproject.ray(i, j).direction, cube.size());
      const int ti = std::clamp(int(std::lround(l.texel.x)), 0, cube.size() - 1);
      const int tj = std::clamp(int(std::lround(l.texel.y)), 0, cube.size() - 1);
      depth[k] = cube.faces[l.face].at(ti, tj);
    }
  };
}

// Random cube maps at N = 2 to 9: each texel far with probability pFar, else at a depth from 1 to
// 5; with `refineSteps`, refined by the nearest-texel oracle.
void expectValidOnRandomMaps(std::uint32_t seed, std::initializer_list<double> densities, int trials,
                             int refineSteps) {
  std::mt19937 rng(seed);
  for (int n : {2, 3, 5, 9})
    for (double pFar : densities)
      for (int trial = 0; trial < trials; ++trial) {
        CubeDepthMap cube = makeCubeDepthMap(pointLight(), n, CaptureMode::Back);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        for (DepthMap& f : cube.faces)
          for (float& d : f.depth) d = u(rng) < pFar ? DepthMap::kNoHit : float(1.0 + 4.0 * u(rng));
        for (Triangulation t : {Triangulation::Fixed, Triangulation::Perfect})
          for (bool flatten : {false, true}) {
            VolumeBuildOptions o;
            o.triangulation = t;
            o.flattenCap = flatten;
            o.refineSteps = refineSteps;
            if (refineSteps > 0) o.depthOracle = nearestTexelOracle(cube);
            expectValid(cube, o,
                        std::string(refineSteps > 0 ? "refined " : "") + "n " + std::to_string(n) + " far " +
                            std::to_string(pFar) + " trial " + std::to_string(trial) + " " + toString(t) +
                            (flatten ? " flattened" : " mirrored"),
                        n <= 5);
          }
      }
}

// Refined on random cube maps: far texels and depths far apart (surface edges everywhere, cells
// with three and four boundary sides, across the cube's edges and corners).
TEST(CubeVolumeCgal, RefinedClosedOnRandomPatterns) { expectValidOnRandomMaps(11, {0.0, 0.3, 0.6, 0.9}, 4, 2); }

// Random far texels at several densities: isolated far texels (a closed fan), slits between two
// of them, pinches where regions touch at a vertex, whole far faces, cube edges and corners.
TEST(CubeVolumeCgal, ClosedOnRandomFarPatterns) { expectValidOnRandomMaps(7, {0.05, 0.3, 0.5, 0.7, 0.95}, 6, 0); }

TEST(CubeVolumeCgal, AllFarIsEmptyAndNoFarIsAShell) {
  CubeDepthMap cube = makeCubeDepthMap(pointLight(), 6, CaptureMode::Back);
  VolumeBuildResult r = buildCubeVolume(cube, {});
  EXPECT_EQ(r.mesh.triangleCount(), 0u);
  EXPECT_EQ(r.mesh.vertexCount(), 0u);
  for (DepthMap& f : cube.faces) std::fill(f.depth.begin(), f.depth.end(), 2.0f);
  r = buildCubeVolume(cube, {});
  const MeshCheckReport rep = checkMesh(r.mesh);
  EXPECT_TRUE(rep.valid()) << rep.summary();
  // A shell between the cube of half side 2 and the far cube (half side 10; a little less at the
  // chords across its edges): 8 (10^3 - 2^3) less the chords' corners.
  EXPECT_GT(rep.volume, 0.9 * 8.0 * (1000.0 - 8.0));
  EXPECT_LT(rep.volume, 8.0 * (1000.0 - 8.0));
  EXPECT_EQ(r.stats.quads, 6u * 5u * 5u + 12u * 5u + 8u);
  EXPECT_EQ(r.stats.capTrianglesBefore, 12u * 36u - 4u);
}

TEST(CubeVolumeCgal, InsideIsBehindTheSheet) {
  CubeDepthMap cube = makeCubeDepthMap(pointLight(0.1, 8.0), 16, CaptureMode::Back);
  // A blocky occluder pattern at depth 3 on some texels of every face.
  for (int f = 0; f < kCubeFaces; ++f)
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 16; ++i)
        if (((i / 4) + (j / 4) + f) % 2 == 0) cube.faces[f].depth[cube.faces[f].index(i, j)] = 3.0f;
  const VolumeBuildResult r = buildCubeVolume(cube, {});
  ASSERT_TRUE(checkMesh(r.mesh).valid());
  const VolumeClassifier inside(r.mesh);
  const glm::dvec3 light = cube.lightPosition();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int k = 0; k < 4000; ++k) {
    const glm::dvec3 dir(u(rng), u(rng), u(rng));
    const CubeLookup l = cubeLookup(dir, 16);
    // Only directions well inside a texel block of occluder or of empty space (away from walls).
    const int bi = int(std::floor(l.texel.x + 0.5)), bj = int(std::floor(l.texel.y + 0.5));
    const double fx = l.texel.x + 0.5 - 4.0 * std::floor((l.texel.x + 0.5) / 4.0);
    const double fy = l.texel.y + 0.5 - 4.0 * std::floor((l.texel.y + 0.5) / 4.0);
    if (fx < 1.0 || fx > 3.0 || fy < 1.0 || fy > 3.0 || bi < 0 || bj < 0 || bi > 15 || bj > 15) continue;
    const bool occluded = ((bi / 4) + (bj / 4) + l.face) % 2 == 0;
    const double depth = 0.5 + 7.0 * (0.5 * u(rng) + 0.5);  // 0.5 .. 7.5 along the face axis
    if (std::abs(depth - 3.0) < 0.05) continue;
    const glm::dvec3 p = light + dir * (depth / l.depth);
    const bool expected = occluded && depth > 3.0;
    EXPECT_EQ(inside.classify(p) == VolumeClassifier::Side::Inside, expected)
        << "face " << cubeFaceName(l.face) << " texel " << l.texel.x << ", " << l.texel.y << " depth " << depth;
    ++checked;
  }
  EXPECT_GT(checked, 500);
}

TEST(CubeVolumeCgal, RefusesWhatItCannotDo) {
  CubeDepthMap cube = makeCubeDepthMap(pointLight(), 4, CaptureMode::Back);
  VolumeBuildOptions o;
  o.refineSteps = 4;
  EXPECT_THROW(buildCubeVolume(cube, o), InputError);
  o = {};
  o.cap = FarCap::Quad;
  EXPECT_THROW(buildCubeVolume(cube, o), InputError);
  o = {};
  o.bias = NAN;
  EXPECT_THROW(buildCubeVolume(cube, o), InputError);
  cube.faces[3].depth[5] = -1.0f;
  try {
    buildCubeVolume(cube, {});
    FAIL() << "a negative depth was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("face -y: depth of texel (1, 1)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace shadowvol

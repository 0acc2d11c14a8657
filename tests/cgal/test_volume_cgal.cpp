// The shadow volume checked with CGAL (mesh_check.h): invariants on every scene in data/scenes,
// self-intersections on small cases, point classification against the depth map, the analytic
// plate's cross-section, perfect against fixed triangulation on the rotated plate.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <random>
#include <span>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "shadowvol/cgal/mesh_check.h"
#include "shadowvol/depth_blur.h"
#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/embree/embree_depth_oracle.h"
#include "shadowvol/scene.h"
#include "shadowvol/sheet_depth.h"
#include "shadowvol/volume_builder.h"
#include "test_util.h"

namespace shadowvol {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> sceneFiles() {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(test::sourceDir() / "data" / "scenes"))
    if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

const Scene& cachedScene(const fs::path& path) {
  static std::map<fs::path, Scene> cache;
  auto it = cache.find(path);
  if (it == cache.end()) it = cache.emplace(path, loadScene(path).scene).first;
  return it->second;
}

// Far-plane test for MeshCheckOptions::allowedTouch: the exact volume has zero thickness where the
// sheet reaches the far plane, so sheet and cap may touch there (docs/volume.md).
std::function<bool(const glm::dvec3&)> onFarPlane(const DepthMap& map) {
  return [&map](const glm::dvec3& p) { return std::abs(map.viewDepthOf(p) - map.farPlane) <= 1e-7 * map.farPlane; };
}

struct Combo {
  Triangulation triangulation;
  bool blur;
  int cap;  // 0 exact flattened, 1 exact per texel, 2 quad
  VolumeBuildOptions options() const {
    VolumeBuildOptions o;
    o.triangulation = triangulation;
    o.blur = blur;
    o.blurOffset = blur ? 0.01 : 0.0;
    o.cap = cap == 2 ? FarCap::Quad : FarCap::Exact;
    o.flattenCap = cap == 0;
    return o;
  }
  std::string name() const {
    return std::string(toString(triangulation)) + (blur ? " blur" : "") +
           (cap == 0 ? " exact" : cap == 1 ? " exact-unflattened" : " quad");
  }
};

std::vector<Combo> allCombos() {
  std::vector<Combo> combos;
  for (Triangulation t : {Triangulation::Fixed, Triangulation::Perfect})
    for (bool blur : {false, true})
      for (int cap = 0; cap < 3; ++cap) combos.push_back({t, blur, cap});
  return combos;
}

// Sum of |det(a, b, c)| / 6 over the triangles: the scale of the terms the signed volume sums.
double absoluteVolumeTerms(const VolumeMesh& m) {
  double sum = 0.0;
  for (const auto& t : m.triangles) {
    const glm::dvec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
    sum += std::abs(glm::dot(a, glm::cross(b, c))) / 6.0;
  }
  return sum;
}

TEST(VolumeCgal, InvariantsOnEveryScene) {
  const auto files = sceneFiles();
  ASSERT_GE(files.size(), 10u);
  std::size_t builds = 0, nonEmpty = 0;
  for (const auto& file : files) {
    const Scene& scene = cachedScene(file);
    for (int res : {32, 64})
      for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front, CaptureMode::Midpoint, CaptureMode::Entry}) {
        const DepthMap map = captureDepthEmbree(scene, res, res, mode);
        double exactVolume[2][2] = {{0, 0}, {0, 0}};
        for (const Combo& c : allCombos()) {
          const std::string what = file.filename().string() + " " + std::to_string(res) + " " + toString(mode) + " " +
                                   c.name();
          const auto r = buildVolume(map, c.options());
          const MeshCheckReport rep = checkMesh(r.mesh);
          ++builds;
          ASSERT_TRUE(rep.closedManifold()) << what << ": " << rep.summary();
          EXPECT_EQ(rep.nonFiniteVertices, 0u) << what;
          EXPECT_EQ(rep.degenerateTriangles, 0u) << what << ": " << rep.summary();
          EXPECT_EQ(rep.isolatedVertices, 0u) << what;
          const int ti = c.triangulation == Triangulation::Perfect, bi = c.blur;
          if (c.cap != 2) {
            EXPECT_TRUE(rep.valid()) << what << ": " << rep.summary();
            if (c.cap == 0) {
              EXPECT_EQ(rep.coincidentVertices, r.stats.splitVertices) << what;  // only the documented splits
              exactVolume[ti][bi] = rep.volume;
              EXPECT_LE(r.stats.capTrianglesAfter, r.stats.capTrianglesBefore) << what;
            } else {
              EXPECT_NEAR(rep.volume, exactVolume[ti][bi], 1e-9 * (1 + exactVolume[ti][bi])) << what;
            }
            nonEmpty += rep.triangles > 0;
          } else {
            // The quad cap encloses the same region (its far-plane parts cancel): same volume, up
            // to the rounding of that cancellation, which grows with the far rectangle (a
            // 150-degree light over a wide ground: terms of 5e8 units^3 in all cancelling to 1e-5).
            EXPECT_NEAR(rep.volume, exactVolume[ti][bi], 1e-7 * (1 + exactVolume[ti][bi]) + 1e-12 * absoluteVolumeTerms(r.mesh))
                << what;
          }
        }
      }
  }
  EXPECT_EQ(builds, files.size() * 2 * 4 * 12);
  EXPECT_GT(nonEmpty, builds / 3);
}

// Refinement (refineSteps 3, the scene's Embree rays) on every shipped scene, two sizes, every
// capture and every option combination it allows (the exact cap, flattened or not; the sub-grid
// with the flattened one, and its search for hidden surfaces): valid closed volumes without
// coincident vertices (refinement needs no pinch splits).
TEST(VolumeCgal, RefinedInvariantsOnEveryScene) {
  const auto files = sceneFiles();
  std::size_t builds = 0, refined = 0, hidden = 0, creases = 0, prismFaces = 0, columnTexels = 0;
  for (const auto& file : files) {
    const Scene& scene = cachedScene(file);
    const EmbreeDepthOracle oracle(scene);
    for (int res : {32, 64})
      for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front, CaptureMode::Midpoint, CaptureMode::Entry}) {
        const DepthMap map = captureDepthEmbree(scene, res, res, mode);
        double flatVolume = 0.0;
        for (const Combo& c : allCombos()) {
          if (c.cap == 2) continue;  // refinement needs the exact cap
          VolumeBuildOptions o = c.options();
          o.refineSteps = 3;
          o.refineChords = c.triangulation == Triangulation::Perfect;  // both ways across the combinations
          o.depthOracle = oracle.oracle();
          o.surfaceEnds = oracle.surfaceEnds();  // the snap (crossing_snap.h) where it applies
          const std::string what = file.filename().string() + " " + std::to_string(res) + " " + toString(mode) + " " +
                                   c.name() + " refine 3";
          const auto r = buildVolume(map, o);
          const MeshCheckReport rep = checkMesh(r.mesh);
          ++builds;
          refined += r.stats.refinedCells > 0;
          ASSERT_TRUE(rep.valid()) << what << ": " << rep.summary();
          EXPECT_EQ(rep.coincidentVertices, 0u) << what;
          EXPECT_EQ(r.stats.splitVertices, 0u) << what;
          if (c.cap == 0) flatVolume = rep.volume;
          else EXPECT_NEAR(rep.volume, flatVolume, 1e-9 * (1 + flatVolume)) << what;  // same region, other cap
          if (c.cap != 0) continue;
          // The sub-grid (flattened cap only): adaptive 4 x 4 at 32^2, 2 x 2 on every refined quad at 64^2;
          // with its search for hidden surfaces.
          o.refineChords = false;
          o.refineSubdivisions = res == 32 ? 4 : 2;
          o.refineGridEverywhere = res == 64;
          o.nearerSurfaces = oracle.nearerSurfaces();
          const auto g = buildVolume(map, o);
          const MeshCheckReport gr = checkMesh(g.mesh);
          ++builds;
          ASSERT_TRUE(gr.valid()) << what << " grid " << o.refineSubdivisions << ": " << gr.summary();
          EXPECT_EQ(gr.coincidentVertices, 0u) << what << " grid " << o.refineSubdivisions;
          // and the hidden ones, and with front capture's bias the creases
          EXPECT_EQ(g.stats.refinedCells,
                    r.stats.refinedCells + g.stats.hiddenQuads + g.stats.creaseQuads + g.stats.thinQuads)
              << what;
          hidden += g.stats.hiddenQuads;
          creases += g.stats.creaseQuads;
          EXPECT_EQ(g.stats.creaseQuads > 0 || g.stats.subgridBiasSamples > 0, g.stats.biasUsed > 0.0 && g.stats.refinedCells > 0)
              << what;
          EXPECT_GE(g.stats.raysCast, g.stats.subgridSamples + g.stats.subgridBiasSamples) << what;
          // With the face prisms, the sheet handing the refined quads' columns over to them (the
          // command line's build; the first part without the hand-over is the volume above, to the
          // bit: tests/embree/test_face_prisms_volume.cpp): valid, the prisms a part of their own.
          o.casterFaces = oracle.casterFaces();
          o.withoutCasters = oracle.withoutCasters();
          o.facePrisms = true;
          const auto f = buildVolume(map, o);
          const MeshCheckReport fr = checkMesh(f.mesh);
          ASSERT_TRUE(fr.valid()) << what << " face prisms: " << fr.summary();
          EXPECT_EQ(f.mesh.partStarts.size(), f.stats.prismFaces > 0 ? 1u : 0u) << what;
          EXPECT_TRUE(f.stats.prismColumnTexels == 0 || g.stats.refinedCells > 0) << what;
          if (f.stats.prismColumnTexels == 0) {  // nothing handed over: the first part is the volume above
            EXPECT_EQ(f.mesh.triangleCount(), g.mesh.triangleCount() + f.stats.prismTriangles) << what;
          }
          columnTexels += f.stats.prismColumnTexels;
          prismFaces += f.stats.prismFaces;
        }
      }
  }
  EXPECT_EQ(builds, files.size() * 2 * 4 * (8 + 4));
  EXPECT_GT(refined, files.size() * 2 * 4 * 8 * 9 / 10);
  EXPECT_GT(hidden, 0u);  // thin parts of the shipped scenes between texel centres at these sizes
  EXPECT_GT(creases, 0u);  // front and entry capture: the meshes' concave folds
  EXPECT_GT(prismFaces, 0u);
  EXPECT_GT(columnTexels, 0u);  // the closed meshes' outlines handed over to the prisms
}

// Random hit levels under a random oracle (hits on other levels, misses, anything): refined
// volumes stay valid and free of self-intersections however inconsistent the rays are.
TEST(VolumeCgal, RefinedVolumesOfRandomMapsAndRaysAreValid) {
  std::size_t builds = 0;
  for (int trial = 0; trial < 40; ++trial) {
    std::mt19937 gen{std::uint32_t(trial)};
    Light light = test::directionalDown(20.0);
    if (trial % 2) {
      light.type = LightType::Spot;
      light.fovYDegrees = 50.0;
      light.nearPlane = 1.0;
    }
    const int w = 6 + int(gen() % 14), h = 6 + int(gen() % 14);
    DepthMap map = makeDepthMap(light, w, h, CaptureMode::Back);
    const int levels = 1 + int(gen() % 4);
    auto level = [&](std::mt19937& r) {
      const int l = int(r() % std::uint32_t(levels + 1));
      return l == levels ? DepthMap::kNoHit : float(3 + 3 * l + std::uniform_real_distribution<float>(0, 1)(r));
    };
    for (auto& d : map.depth) d = level(gen);
    const DepthOracle oracle = [&](const DepthMap&, std::span<const glm::dvec2> ndc, std::span<float> depth) {
      for (std::size_t k = 0; k < ndc.size(); ++k) {
        std::mt19937 r{std::uint32_t(std::hash<double>()(ndc[k].x * 1e6 + ndc[k].y))};
        depth[k] = level(r);
      }
    };
    for (Triangulation tri : {Triangulation::Fixed, Triangulation::Perfect})
      for (bool blur : {false, true})
        for (bool flat : {true, false}) {
          VolumeBuildOptions o;
          o.triangulation = tri;
          o.blur = blur;
          o.flattenCap = flat;
          o.refineSteps = 1 + trial % 5;
          o.refineChords = trial % 2 == 0;
          o.depthOracle = oracle;
          // The sub-grid too, on every fourth trial (2 or 4 per texel side, adaptive or everywhere;
          // flattened cap, no chord points): its meshes are larger, and the self-intersection check
          // grows with them.
          for (int grid : {1, 2 << (trial / 4 % 2)}) {
            if (grid > 1 && (!flat || trial % 4 > 1)) continue;
            o.refineSubdivisions = grid;
            o.refineGridEverywhere = grid > 1 && trial / 8 % 2 == 1;
            if (grid > 1) o.refineChords = false;
            const auto r = buildVolume(map, o);
            MeshCheckOptions co;
            co.selfIntersections = true;
            co.allowedTouch = onFarPlane(map);
            const MeshCheckReport rep = checkMesh(r.mesh, co);
            EXPECT_TRUE(rep.valid()) << "trial " << trial << " " << w << "x" << h << " " << toString(tri) << " blur "
                                     << blur << " flat " << flat << " grid " << grid << ": " << rep.summary();
            ++builds;
          }
        }
  }
  EXPECT_EQ(builds, 40u * 8u + 20u * 4u);
}

TEST(VolumeCgal, NoSelfIntersectionsOnSmallCases) {
  std::size_t checked = 0, touching = 0;
  for (const char* name : {"default.json", "plate-rotated.json", "tree.json", "hemisphere-grazing.json", "bunny.json"}) {
    const Scene& scene = cachedScene(test::sourceDir() / "data" / "scenes" / name);
    const EmbreeDepthOracle oracle(scene);
    for (int res : {16, 24})
      for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front}) {
        const DepthMap map = captureDepthEmbree(scene, res, res, mode);
        for (const Combo& c : allCombos()) {
          if (c.cap == 2) continue;  // the quad cap coincides with the far sheet by design
          for (int steps : {0, 4, -4, 40}) {  // -4: 4 steps with chord points; 40: 4 steps on a 4 x 4 sub-grid
            if (steps == 40 && c.cap != 0) continue;  // the sub-grid needs the flattened cap
            VolumeBuildOptions vo = c.options();
            vo.refineSteps = steps == 40 ? 4 : std::abs(steps);
            vo.refineChords = steps < 0;
            vo.refineSubdivisions = steps == 40 ? 4 : 1;
            vo.depthOracle = oracle.oracle();
            vo.surfaceEnds = oracle.surfaceEnds();
            vo.nearerSurfaces = oracle.nearerSurfaces();  // the sub-grid's search for hidden surfaces
            const auto r = buildVolume(map, vo);
            MeshCheckOptions o;
            o.selfIntersections = true;
            o.allowedTouch = onFarPlane(map);
            const MeshCheckReport rep = checkMesh(r.mesh, o);
            ASSERT_TRUE(rep.selfIntersectingPairs.has_value()) << rep.summary();
            EXPECT_EQ(*rep.selfIntersectingPairs, 0u) << name << " " << res << " " << toString(mode) << " " << c.name()
                                                      << " refine " << steps << ": " << rep.summary();
            touching += rep.allowedTouchingPairs;
            ++checked;
          }
        }
      }
  }
  EXPECT_EQ(checked, 5u * 2 * 2 * (8 * 3 + 4));
  RecordProperty("far_plane_touching_pairs", int(touching));
}

// Light-view depth of the sheet vertex of texel (i, j) by the documented rule (no blur).
double effectiveDepth(const DepthMap& map, int i, int j, double bias) {
  return sheetDepthOf(map, i, j, SheetDepthRule(map, bias, 0.0), false);
}

TEST(VolumeCgal, PointClassificationAgreesWithTheDepthMap) {
  std::mt19937_64 rng(7);
  for (const char* name : {"default.json", "tree.json", "plate.json", "bunny.json", "hemisphere-grazing.json"}) {
    const Scene& scene = cachedScene(test::sourceDir() / "data" / "scenes" / name);
    for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front}) {
      const DepthMap map = captureDepthEmbree(scene, 64, 64, mode);
      for (Triangulation tri : {Triangulation::Fixed, Triangulation::Perfect}) {
        VolumeBuildOptions o;
        o.triangulation = tri;
        const auto r = buildVolume(map, o);
        const VolumeClassifier classifier(r.mesh);
        // Half the points from the scene's bounding box, half from its intersection with the
        // volume's bounding box (so that enough points fall in the shadow).
        const Bounds3 box = scene.bounds();
        Bounds3 shadowBox;
        for (const auto& p : r.mesh.positions) shadowBox.extend(p);
        shadowBox.min = glm::max(shadowBox.min, box.min);
        shadowBox.max = glm::min(shadowBox.max, box.max);
        ASSERT_FALSE(shadowBox.empty()) << name;
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        int inside = 0, outside = 0, skipped = 0, wrong = 0;
        const double eps = 1e-6 * map.farPlane;
        for (int n = 0; n < 4000; ++n) {
          const Bounds3& b = n % 2 ? shadowBox : box;
          const glm::dvec3 p = b.min + glm::dvec3(unit(rng), unit(rng), unit(rng)) * (b.max - b.min);
          const glm::dvec2 uv = map.texelOf(p);
          const double d = map.viewDepthOf(p);
          int expected = 0;  // 1 inside, -1 outside, 0 undecided (on or near the sheet)
          if (uv.x < 0 || uv.y < 0 || uv.x > map.width - 1 || uv.y > map.height - 1 || d > map.farPlane + eps ||
              d < map.nearPlane - eps) {
            expected = -1;
          } else {
            const int i0 = std::min(int(uv.x), map.width - 2), j0 = std::min(int(uv.y), map.height - 2);
            double lo = map.farPlane, hi = 0.0;
            for (int dj = 0; dj < 2; ++dj)
              for (int di = 0; di < 2; ++di) {
                const double e = effectiveDepth(map, i0 + di, j0 + dj, r.stats.biasUsed);
                lo = std::min(lo, e);
                hi = std::max(hi, e);
              }
            // The sheet over this quad lies between its corners' depths.
            if (d > hi + eps && d < map.farPlane - eps) expected = 1;
            else if (d < lo - eps) expected = -1;
          }
          if (expected == 0) {
            ++skipped;
            continue;
          }
          const bool in = classifier.classify(p) == VolumeClassifier::Side::Inside;
          if (in != (expected == 1)) ++wrong;
          (expected == 1 ? inside : outside)++;
        }
        const std::string what = std::string(name) + " " + toString(mode) + " " + toString(tri);
        EXPECT_EQ(wrong, 0) << what << " (inside " << inside << ", outside " << outside << ")";
        EXPECT_LT(skipped, 2000) << what;
        EXPECT_GT(inside, 20) << what;
        EXPECT_GT(outside, 100) << what;
      }
    }
  }
}

using test::directionalDown;

// A plate of half sizes (hx, hz) rotated by `degrees` about the light axis, at light depth 3.55
// (y = 1.45), written analytically into a back-capture depth map (texel centres inside -> hit).
DepthMap plateMap(int res, double hx, double hz, double degrees) {
  DepthMap m = makeDepthMap(directionalDown(), res, res, CaptureMode::Back);
  const double a = -degrees * std::numbers::pi / 180.0, c = std::cos(a), s = std::sin(a);  // world -> plate
  for (int j = 0; j < res; ++j)
    for (int i = 0; i < res; ++i) {
      const glm::dvec3 p = m.worldPoint(i, j, 1.0);
      const double x = c * p.x + s * p.z, z = -s * p.x + c * p.z;
      if (std::abs(x) < hx && std::abs(z) < hz) m.depth[m.index(i, j)] = 3.55f;
    }
  return m;
}

TEST(VolumeCgal, AnalyticPlateCrossSectionWithinOneTexel) {
  // 2 x 1 plate, 32 texels over 8 units: 0.25 per texel, edges on texel boundaries.
  const DepthMap m = plateMap(32, 1.0, 0.5, 0.0);
  const double texel = 0.25;
  for (Triangulation tri : {Triangulation::Fixed, Triangulation::Perfect}) {
    VolumeBuildOptions o;
    o.triangulation = tri;
    const auto r = buildVolume(m, o);
    ASSERT_TRUE(checkMesh(r.mesh).valid());
    const VolumeClassifier classifier(r.mesh);
    int in = 0, out = 0;
    for (double x = -2.0; x <= 2.0; x += 0.02)
      for (double z = -2.0; z <= 2.0; z += 0.02) {
        const glm::dvec3 p(x + 1e-4, 0.0, z + 3e-4);  // the ground, off the sampling lattice
        const bool inShrunk = std::abs(p.x) < 1.0 - texel && std::abs(p.z) < 0.5 - texel;
        const bool outGrown = std::abs(p.x) > 1.0 + texel || std::abs(p.z) > 0.5 + texel;
        if (inShrunk) {
          EXPECT_TRUE(classifier.inside(p)) << p.x << "," << p.z;
          ++in;
        } else if (outGrown) {
          EXPECT_FALSE(classifier.inside(p)) << p.x << "," << p.z;
          ++out;
        }
      }
    EXPECT_GT(in, 500);
    EXPECT_GT(out, 10000);
  }
}

// Area (world units^2) where the volume's cross-section at the ground (y = 0) and the exact
// shadow (the plate outline) disagree, by sampling a fine grid.
double footprintError(const VolumeMesh& mesh, double hx, double hz, double degrees) {
  const VolumeClassifier classifier(mesh);
  const double a = -degrees * std::numbers::pi / 180.0, c = std::cos(a), s = std::sin(a);  // world -> plate
  const double step = 0.01;
  int wrong = 0;
  for (double x = -1.8; x <= 1.8; x += step)
    for (double z = -1.8; z <= 1.8; z += step) {
      const glm::dvec3 p(x + 1e-5, 0.0, z + 3e-5);
      const double px = c * p.x + s * p.z, pz = -s * p.x + c * p.z;
      const bool shadow = std::abs(px) < hx && std::abs(pz) < hz;
      if (classifier.inside(p) != shadow) ++wrong;
    }
  return wrong * step * step;
}

TEST(VolumeCgal, PerfectBeatsFixedOnTheRotatedPlate) {
  for (int res : {32, 64}) {
    const DepthMap m = plateMap(res, 1.0, 1.0, 30.0);
    VolumeBuildOptions fixed, perfect;
    fixed.triangulation = Triangulation::Fixed;
    perfect.triangulation = Triangulation::Perfect;
    const auto rf = buildVolume(m, fixed), rp = buildVolume(m, perfect);
    const double ef = footprintError(rf.mesh, 1.0, 1.0, 30.0), ep = footprintError(rp.mesh, 1.0, 1.0, 30.0);
    EXPECT_LT(ep, ef) << res;
    EXPECT_EQ(rf.stats.flippedQuads, 0u);
    EXPECT_GT(rp.stats.flippedQuads, 0u);
    RecordProperty("analytic_" + std::to_string(res) + "_error_fixed", std::to_string(ef));
    RecordProperty("analytic_" + std::to_string(res) + "_error_perfect", std::to_string(ep));
    RecordProperty("analytic_" + std::to_string(res) + "_flipped_fraction",
                   std::to_string(double(rp.stats.flippedQuads) / double(rp.stats.quads)));
  }
  // The same with the Embree capture of data/scenes/plate-rotated.json (back faces: the plate's
  // bottom; the ground is single-sided and not captured).
  const Scene& scene = cachedScene(test::sourceDir() / "data" / "scenes" / "plate-rotated.json");
  const DepthMap m = captureDepthEmbree(scene, 64, 64, CaptureMode::Back);
  VolumeBuildOptions fixed, perfect;
  fixed.triangulation = Triangulation::Fixed;
  const auto rf = buildVolume(m, fixed), rp = buildVolume(m, perfect);
  const double ef = footprintError(rf.mesh, 1.0, 1.0, 30.0), ep = footprintError(rp.mesh, 1.0, 1.0, 30.0);
  EXPECT_LT(ep, ef);
  RecordProperty("scene_64_error_fixed", std::to_string(ef));
  RecordProperty("scene_64_error_perfect", std::to_string(ep));
}

}  // namespace
}  // namespace shadowvol

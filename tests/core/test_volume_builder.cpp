// buildVolume without CGAL: combinatorial invariants on synthetic depth maps, input errors, bias,
// the analytic plate's vertices. The CGAL-checked invariants on real scenes are in tests/cgal.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <tbb/global_control.h>

#include "shadowvol/depth_blur.h"
#include "shadowvol/error.h"
#include "shadowvol/volume_builder.h"
#include "mesh_invariants.h"
#include "test_util.h"

namespace shadowvol {
namespace {

using test::closedOrientedManifold;
using test::directionalDown;

Light spot() {
  Light light;
  light.type = LightType::Spot;
  light.position = {1, 8, 2};
  light.direction = glm::normalize(glm::dvec3(-0.1, -1, -0.2));
  light.fovYDegrees = 50;
  light.nearPlane = 1.0;
  light.farPlane = 15.0;
  return light;
}

std::uint64_t lcg(std::uint64_t& s) {
  s = s * 6364136223846793005ull + 1442695040888963407ull;
  return s >> 33;
}

// Random hit / no-hit patterns with random depths: pinches, slits, holes, islands, diagonal
// contacts. Every option combination must give a closed oriented manifold.
TEST(VolumeBuilder, RandomMapsGiveClosedOrientedManifolds) {
  std::uint64_t seed = 42;
  std::size_t splits = 0, dropped = 0, flips = 0, builds = 0;
  for (int n = 0; n < 40; ++n) {
    const bool perspective = n % 2 == 1;
    const int w = 10 + int(lcg(seed) % 12), h = 10 + int(lcg(seed) % 12);
    DepthMap m = makeDepthMap(perspective ? spot() : directionalDown(), w, h,
                              n % 3 == 0 ? CaptureMode::Front : CaptureMode::Back);
    const int density = 20 + int(lcg(seed) % 70);
    for (auto& d : m.depth)
      if (int(lcg(seed) % 100) < density) d = float(m.nearPlane + 0.5 + (lcg(seed) % 1000) * 0.009);
    for (Triangulation tri : {Triangulation::Fixed, Triangulation::Perfect})
      for (bool blur : {false, true})
        for (int cap = 0; cap < 3; ++cap) {
          VolumeBuildOptions o;
          o.triangulation = tri;
          o.blur = blur;
          o.cap = cap == 2 ? FarCap::Quad : FarCap::Exact;
          o.flattenCap = cap == 0;
          const auto r = buildVolume(m, o);
          ASSERT_TRUE(closedOrientedManifold(r.mesh)) << "map " << n << " " << toString(tri) << " blur " << blur
                                                      << " cap " << cap;
          splits += r.stats.splitVertices;
          dropped += r.stats.droppedQuads;
          flips += r.stats.flippedQuads;
          if (cap == 0) {
            EXPECT_LE(r.stats.capTrianglesAfter, r.stats.capTrianglesBefore);
          }
          ++builds;
        }
  }
  EXPECT_EQ(builds, 40u * 12u);
  EXPECT_GT(splits, 0u);  // the pinch path is exercised
  EXPECT_GT(dropped, 0u);
  EXPECT_GT(flips, 0u);
}

TEST(VolumeBuilder, DiagonalContactIsSplit) {
  // Hits at (3, 4) and (5, 4), everything else no-hit: with the fixed diagonal their kept
  // triangles meet only at the far texel (4, 4) (two fans there), which must be split.
  DepthMap m = makeDepthMap(directionalDown(), 10, 10, CaptureMode::Back);
  m.depth[m.index(3, 4)] = 2.0f;
  m.depth[m.index(5, 4)] = 2.0f;
  VolumeBuildOptions o;
  o.triangulation = Triangulation::Fixed;
  const auto r = buildVolume(m, o);
  EXPECT_TRUE(closedOrientedManifold(r.mesh));
  EXPECT_GE(r.stats.splitVertices, 1u);
  const glm::dvec3 pinch = m.worldPoint(4, 4, m.farPlane);
  EXPECT_EQ(std::count_if(r.mesh.positions.begin(), r.mesh.positions.end(),
                          [&](const glm::dvec3& p) { return glm::length(p - pinch) < 1e-9; }),
            2);
}

TEST(VolumeBuilder, EmptyAndTinyMaps) {
  DepthMap m = makeDepthMap(directionalDown(), 16, 16, CaptureMode::Back);
  auto r = buildVolume(m);
  EXPECT_EQ(r.mesh.triangleCount(), 0u);
  EXPECT_EQ(r.stats.droppedQuads, 15u * 15u);
  VolumeBuildOptions quad;
  quad.cap = FarCap::Quad;
  r = buildVolume(m, quad);  // the full far sheet plus the cancel cap: closed, zero volume
  EXPECT_EQ(r.mesh.triangleCount(), 2u * 15u * 15u + r.stats.capTrianglesAfter);
  for (auto& d : m.depth) d = 3.0f;  // everything hit: only the border ring is far
  r = buildVolume(m);
  EXPECT_TRUE(closedOrientedManifold(r.mesh));
  DepthMap tiny = makeDepthMap(directionalDown(), 1, 5, CaptureMode::Back);
  EXPECT_EQ(buildVolume(tiny).mesh.triangleCount(), 0u);
}

TEST(VolumeBuilder, BadDepthsThrowInputErrorNamingTheTexel) {
  DepthMap m = makeDepthMap(directionalDown(), 8, 8, CaptureMode::Back);
  m.depth[m.index(3, 4)] = std::numeric_limits<float>::quiet_NaN();
  try {
    buildVolume(m);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("(3, 4)"), std::string::npos) << e.what();
    EXPECT_NE(e.value().find("nan"), std::string::npos) << e.what();
  }
  m.depth[m.index(3, 4)] = -1.5f;
  try {
    buildVolume(m);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("(3, 4)"), std::string::npos) << e.what();
    EXPECT_EQ(e.value(), "-1.5");
  }
  m.depth[m.index(3, 4)] = 1.0f;
  VolumeBuildOptions o;
  o.bias = std::numeric_limits<double>::infinity();
  EXPECT_THROW(buildVolume(m, o), InputError);
  // Texels of the border ring become far-plane vertices whatever they hold, but are checked too,
  // with and without blur; the first bad texel in row order is named.
  for (const bool blur : {false, true})
    for (const auto& [i, j] : {std::pair{5, 0}, std::pair{0, 3}, std::pair{7, 6}, std::pair{2, 7}}) {
      DepthMap bad = makeDepthMap(directionalDown(), 8, 8, CaptureMode::Back);
      bad.depth[bad.index(i, j)] = std::numeric_limits<float>::quiet_NaN();
      bad.depth[bad.index(6, 7)] = -2.0f;
      VolumeBuildOptions ob;
      ob.blur = blur;
      try {
        buildVolume(bad, ob);
        ADD_FAILURE() << "no InputError for texel " << i << ", " << j << " blur " << blur;
      } catch (const InputError& e) {
        const std::string where = "(" + std::to_string(i) + ", " + std::to_string(j) + ")";
        EXPECT_NE(std::string(e.what()).find(where), std::string::npos) << e.what();
      }
    }
}

// A map a caller fills by hand (its own renderer's) gets a depth file's checks (a twenty-first
// probe's NaN view gave a mesh of NaN; a NaN far plane or a short depth vector aborted).
TEST(VolumeBuilder, AHandFilledMapsLightAndSizeAreChecked) {
  const DepthMap good = makeDepthMap(directionalDown(), 16, 16, CaptureMode::Back);
  const auto refusal = [](const DepthMap& m) -> std::string {
    try {
      buildVolume(m);
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), "DepthMap") << e.what();
      return e.field();
    }
    return "accepted";
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  DepthMap m = good;
  m.lightView[0][0] = nan;
  EXPECT_EQ(refusal(m), "lightView");
  m = good;
  m.lightView *= 1e-300;
  EXPECT_EQ(refusal(m), "lightView");
  m = good;
  m.lightProjection = glm::dmat4(0.0);
  EXPECT_EQ(refusal(m), "lightProjection");
  m = good;
  m.lightType = LightType::Spot;  // an orthographic projection for a spot light
  EXPECT_EQ(refusal(m), "lightProjection");
  m = good;
  m.lightType = LightType::Point;
  EXPECT_EQ(refusal(m), "lightType");
  m = good;
  m.farPlane = nan;
  EXPECT_EQ(refusal(m), "farPlane");
  m = good;
  m.farPlane = m.nearPlane - 1.0;
  EXPECT_EQ(refusal(m), "farPlane");
  m = good;
  m.origin.x = nan;
  EXPECT_EQ(refusal(m), "origin");
  m = good;
  m.depth.resize(10);
  EXPECT_EQ(refusal(m), "depth");
  m = good;
  m.width = 0;
  EXPECT_EQ(refusal(m), "width x height");
  EXPECT_EQ(refusal(good), "accepted");
}

// The far snap (depth_blur.h) decided on the stored float: the largest float below
// far * (1 - kFarSnap) is a hit, the next float is not; -0 is a valid depth (clamped to near).
TEST(VolumeBuilder, FarSnapBoundaryAndNegativeZero) {
  const DepthMap base = makeDepthMap(directionalDown(), 8, 8, CaptureMode::Back);
  const double farSnap = base.farPlane * (1.0 - kFarSnap);
  float below = float(farSnap);
  while (double(below) >= farSnap) below = std::nextafter(below, 0.0f);
  const float above = std::nextafter(below, std::numeric_limits<float>::infinity());
  ASSERT_GE(double(above), farSnap);
  auto build = [&](float depth) {
    DepthMap m = base;
    m.depth[m.index(3, 3)] = depth;
    return buildVolume(m);
  };
  EXPECT_EQ(build(below).stats.droppedQuads, std::size_t(7 * 7) - 4);  // the texel's four quads kept
  EXPECT_EQ(build(above).stats.droppedQuads, std::size_t(7 * 7));
  EXPECT_TRUE(build(above).mesh.triangles.empty());
  const VolumeBuildResult zero = build(-0.0f);
  EXPECT_EQ(zero.stats.droppedQuads, std::size_t(7 * 7) - 4);
  const TexelUnprojector unproject(base);
  const glm::dvec3 nearPoint = unproject.worldPoint(3, 3, base.nearPlane);
  EXPECT_TRUE(std::any_of(zero.mesh.positions.begin(), zero.mesh.positions.end(),
                          [&](const glm::dvec3& p) { return glm::length(p - nearPoint) < 1e-9; }));
}

// A projection that mixes x and y (a depth map from a file may carry one) takes the builder's
// general unprojection path: the same closed manifold, every vertex exactly TexelUnprojector's
// point for its texel and depth.
TEST(VolumeBuilder, NonSeparableProjection) {
  std::uint64_t seed = 3;
  DepthMap m = makeDepthMap(spot(), 40, 36, CaptureMode::Back);
  glm::dmat4 mix(1.0);  // rotate clip-space x and y by 0.3 rad
  mix[0][0] = std::cos(0.3), mix[0][1] = std::sin(0.3), mix[1][0] = -std::sin(0.3), mix[1][1] = std::cos(0.3);
  m.lightProjection = mix * m.lightProjection;
  for (auto& d : m.depth)
    if (lcg(seed) % 100 < 50) d = float(m.nearPlane + 0.5 + (lcg(seed) % 1000) * 0.009);
  const VolumeBuildResult r = buildVolume(m);
  ASSERT_TRUE(closedOrientedManifold(r.mesh));
  const TexelUnprojector unproject(m);
  std::set<std::pair<double, double>> expected;  // (x, z) of every hit texel's sheet vertex
  for (int j = 1; j < m.height - 1; ++j)
    for (int i = 1; i < m.width - 1; ++i)
      if (!isFarDepth(m.at(i, j), m.farPlane)) {
        const glm::dvec3 p = unproject.worldPoint(i, j, double(m.at(i, j)));
        expected.insert({p.x, p.z});
      }
  std::size_t found = 0;
  for (const auto& p : r.mesh.positions) found += expected.count({p.x, p.z});
  EXPECT_EQ(found, expected.size());
  EXPECT_GT(expected.size(), 100u);
}

// One VolumeBuilder and one result reused across sizes, maps and options give exactly what
// buildVolume gives; after an input error the result is empty and the builder still works.
TEST(VolumeBuilder, ReusedBuilderMatchesBuildVolume) {
  std::uint64_t seed = 5;
  VolumeBuilder builder;
  VolumeBuildResult reused;
  const int sizes[][2] = {{96, 80}, {40, 50}, {130, 110}, {17, 9}, {96, 80}};
  int n = 0;
  for (const auto& [w, h] : sizes) {
    DepthMap m = makeDepthMap(n % 2 ? spot() : directionalDown(), w, h, n % 3 ? CaptureMode::Back : CaptureMode::Front);
    for (auto& d : m.depth)
      if (lcg(seed) % 100 < 45) d = float(m.nearPlane + 0.5 + (lcg(seed) % 1000) * 0.009);
    for (int variant = 0; variant < 4; ++variant) {
      VolumeBuildOptions o;
      o.triangulation = variant % 2 ? Triangulation::Fixed : Triangulation::Perfect;
      o.blur = variant == 2;
      o.cap = variant == 3 ? FarCap::Quad : FarCap::Exact;
      o.flattenCap = variant != 1;
      const VolumeBuildResult fresh = buildVolume(m, o);
      builder.build(m, o, reused);
      EXPECT_EQ(reused.mesh.positions, fresh.mesh.positions) << w << "x" << h << " variant " << variant;
      EXPECT_EQ(reused.mesh.triangles, fresh.mesh.triangles) << w << "x" << h << " variant " << variant;
      EXPECT_EQ(reused.stats.splitVertices, fresh.stats.splitVertices);
      EXPECT_EQ(reused.stats.flippedQuads, fresh.stats.flippedQuads);
      EXPECT_EQ(reused.stats.capTrianglesAfter, fresh.stats.capTrianglesAfter);
    }
    ++n;
  }
  DepthMap bad = makeDepthMap(spot(), 30, 30, CaptureMode::Back);
  bad.depth[bad.index(10, 12)] = -1.0f;
  EXPECT_THROW(builder.build(bad, {}, reused), InputError);
  EXPECT_TRUE(reused.mesh.positions.empty());
  EXPECT_TRUE(reused.mesh.triangles.empty());
  EXPECT_EQ(reused.stats.quads, 0u);
  bad.depth[bad.index(10, 12)] = 5.0f;
  builder.build(bad, {}, reused);
  const VolumeBuildResult fresh = buildVolume(bad);
  EXPECT_EQ(reused.mesh.positions, fresh.mesh.positions);
  EXPECT_EQ(reused.mesh.triangles, fresh.mesh.triangles);
  EXPECT_FALSE(fresh.mesh.triangles.empty());
}

TEST(VolumeBuilder, DefaultBiasDependsOnlyOnMetadata) {
  DepthMap back = makeDepthMap(directionalDown(), 64, 64, CaptureMode::Back);
  EXPECT_EQ(defaultBias(back), 0.0);
  DepthMap front = makeDepthMap(directionalDown(), 64, 64, CaptureMode::Front);
  const double expected = 8.0 / 64.0 + 4.0 * 12.0 * std::ldexp(1.0, -23);  // footprint + 4 float ulps
  EXPECT_NEAR(defaultBias(front), expected, 1e-12);
  DepthMap filled = front;
  for (auto& d : filled.depth) d = 2.5f;
  EXPECT_EQ(defaultBias(filled), defaultBias(front));
  DepthMap fine = makeDepthMap(directionalDown(), 256, 256, CaptureMode::Front);
  EXPECT_LT(defaultBias(fine), defaultBias(front));  // shrinks with the texel footprint
  EXPECT_EQ(defaultBias(makeDepthMap(spot(), 64, 64, CaptureMode::Midpoint)), 0.0);
  // The bias is applied to hit texels, away from the light, and reported.
  for (auto& d : filled.depth) d = 2.5f;
  const auto r = buildVolume(filled);
  EXPECT_DOUBLE_EQ(r.stats.biasUsed, defaultBias(front));
  std::size_t hits = 0;
  for (const auto& p : r.mesh.positions)
    if (std::abs(filled.viewDepthOf(p) - filled.farPlane) > 1e-9) {
      EXPECT_NEAR(filled.viewDepthOf(p), 2.5 + r.stats.biasUsed, 1e-9);
      ++hits;
    }
  EXPECT_EQ(hits, 62u * 62u);
}

// Analytic plate: a 2 x 1 plate at light depth 3.55 under a directional light straight down, over
// an 8 x 8 window at 32 x 32 texels (0.25 per texel): its edges fall on texel boundaries.
TEST(VolumeBuilder, AnalyticPlateVertices) {
  DepthMap m = makeDepthMap(directionalDown(), 32, 32, CaptureMode::Back);
  const double plateDepth = 3.55;
  auto onPlate = [](double x, double z) { return std::abs(x) < 1.0 && std::abs(z) < 0.5; };
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 32; ++i) {
      const glm::dvec3 c = m.worldPoint(i, j, 1.0);
      if (onPlate(c.x, c.z)) m.depth[m.index(i, j)] = float(plateDepth);
    }
  ASSERT_EQ(m.hitCount(), 8u * 4u);
  for (Triangulation tri : {Triangulation::Fixed, Triangulation::Perfect}) {
    VolumeBuildOptions o;
    o.triangulation = tri;
    const auto r = buildVolume(m, o);
    ASSERT_TRUE(closedOrientedManifold(r.mesh));
    std::size_t plate = 0;
    for (const auto& p : r.mesh.positions) {
      const double d = m.viewDepthOf(p);
      if (onPlate(p.x, p.z)) {
        EXPECT_NEAR(d, plateDepth, 1e-6 * plateDepth);
        EXPECT_NEAR(p.y, 5.0 - plateDepth, 1e-6 * plateDepth);
        ++plate;
      } else {
        EXPECT_NEAR(d, m.farPlane, 1e-6 * m.farPlane);
      }
    }
    EXPECT_EQ(plate, 32u);
    // Around the plate, the 10 x 6 ring of far texels less the diagonal corners no kept triangle
    // uses: two with the fixed diagonal, all four with the perfect one (it cuts every corner).
    EXPECT_EQ(r.mesh.vertexCount(), tri == Triangulation::Fixed ? 58u : 56u);
    EXPECT_LT(r.stats.capTrianglesAfter, r.stats.capTrianglesBefore);
    EXPECT_EQ(r.stats.splitVertices, 0u);
  }
}

// Depths pushed to or past the far plane by the bias snap to it: the volume vanishes; depths
// below the near plane are clamped to it.
TEST(VolumeBuilder, BiasClampsToNearAndFar) {
  DepthMap m = makeDepthMap(directionalDown(), 16, 16, CaptureMode::Back);
  for (auto& d : m.depth) d = 5.0f;
  VolumeBuildOptions o;
  o.bias = m.farPlane - 5.0 - 1e-7;  // within the far snap of the plane
  EXPECT_EQ(buildVolume(m, o).mesh.triangleCount(), 0u);
  o.bias = -100.0;
  const auto r = buildVolume(m, o);
  ASSERT_TRUE(closedOrientedManifold(r.mesh));
  for (const auto& p : r.mesh.positions) {
    const double d = m.viewDepthOf(p);
    EXPECT_TRUE(std::abs(d - m.nearPlane) < 1e-9 || std::abs(d - m.farPlane) < 1e-9) << d;
  }
}

// Regression (a hostile-input probe): --bias 1e6 gave an empty volume without a word. An offset of
// at least far - near puts every texel on the far plane: refused, naming the field and the range.
TEST(VolumeBuilder, OffsetsThatEmptyTheRangeAreRefused) {
  DepthMap m = makeDepthMap(directionalDown(), 16, 16, CaptureMode::Back);
  for (auto& d : m.depth) d = float(m.nearPlane);
  const double range = m.farPlane - m.nearPlane;
  VolumeBuildOptions o;
  auto refusal = [&](const VolumeBuildOptions& options) -> std::string {
    try {
      buildVolume(m, options);
    } catch (const InputError& e) {
      return e.field() + ": " + e.problem();
    }
    return "";
  };
  o.bias = range;
  EXPECT_NE(refusal(o).find("bias: is at least the light's depth range"), std::string::npos) << refusal(o);
  o.bias = 1e6;
  EXPECT_NE(refusal(o).find("bias:"), std::string::npos) << refusal(o);
  o.bias = 0.5 * range;
  o.blur = true;
  o.blurOffset = 0.5 * range;
  EXPECT_NE(refusal(o).find("blur offset: plus the bias"), std::string::npos) << refusal(o);
  o.blur = false;  // the blur offset counts only with blur
  EXPECT_EQ(refusal(o), "");
  o.bias = 0.999 * range;  // just inside: texels at the near plane stay off the far plane
  EXPECT_GT(buildVolume(m, o).mesh.triangleCount(), 0u);
}

// The same map gives the same mesh (positions bit for bit, triangles in the same order) with one
// thread as with all of them.
TEST(VolumeBuilder, DeterministicAcrossThreadCounts) {
  std::uint64_t seed = 9;
  DepthMap m = makeDepthMap(spot(), 96, 80, CaptureMode::Back);
  for (auto& d : m.depth)
    if (lcg(seed) % 100 < 40) d = float(2.0 + (lcg(seed) % 1000) * 0.01);
  VolumeBuildOptions o;
  o.blur = true;
  const auto parallel = buildVolume(m, o);
  VolumeBuildResult serial;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    serial = buildVolume(m, o);
  }
  EXPECT_EQ(parallel.mesh.positions, serial.mesh.positions);
  EXPECT_EQ(parallel.mesh.triangles, serial.mesh.triangles);
  EXPECT_GT(parallel.stats.splitVertices + parallel.stats.flippedQuads, 0u);
}

}  // namespace
}  // namespace shadowvol

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "shadowvol/depth_map.h"
#include "shadowvol/embree/capture_ray.h"
#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/embree/embree_scene.h"
#include "shadowvol/error.h"
#include "shadowvol/primitives.h"
#include "test_util.h"

namespace shadowvol {
namespace {

Light makeLight(LightType type) {
  Light l;
  l.type = type;
  l.position = {0.1, 10, 0.05};
  l.direction = glm::normalize(glm::dvec3(0.02, -1, 0.01));
  l.fovYDegrees = 30;
  l.halfExtent = 2.5;
  l.nearPlane = 1;
  l.farPlane = 20;
  return l;
}

Scene sceneOf(const Light& light, std::vector<TriangleMesh> meshes) {
  Scene s;
  for (auto& m : meshes) s.objects.push_back({"obj", "mesh", std::move(m)});
  s.light = light;
  return s;
}

// The ray of texel (i, j) as the capture builds it: t is the light-view depth.
struct Ray {
  glm::dvec3 org, dir;
};
Ray texelRay(const DepthMap& map, int i, int j) {
  const TexelUnprojector u(map);
  const glm::dvec3 p1 = u.worldPoint(i, j, 1.0), p2 = u.worldPoint(i, j, 2.0);
  return {p1 - (p2 - p1), p2 - p1};
}

class CaptureAnalytic : public ::testing::TestWithParam<LightType> {};

TEST_P(CaptureAnalytic, TiltedPlaneAtKnownDistance) {
  TriangleMesh plane = makePlane(60, 60, 1);
  // Tilt by 20 degrees about X and lower to y = 1: plane through (0, 1, 0), normal n.
  const double a = 20.0 * 3.14159265358979323846 / 180.0;
  const glm::dvec3 n(0, std::cos(a), std::sin(a));
  for (auto& p : plane.positions) {
    const double y = p.y * std::cos(a) - p.z * std::sin(a), z = p.y * std::sin(a) + p.z * std::cos(a);
    p = glm::vec3(p.x, float(y + 1.0), float(z));
  }
  const Scene s = sceneOf(makeLight(GetParam()), {plane});
  const DepthMap map = captureDepthEmbree(s, 48, 40, CaptureMode::Front);
  for (int j = 0; j < map.height; ++j)
    for (int i = 0; i < map.width; ++i) {
      const Ray r = texelRay(map, i, j);
      const double t = glm::dot(glm::dvec3(0, 1, 0) - r.org, n) / glm::dot(r.dir, n);
      ASSERT_NEAR(map.at(i, j), t, 1e-5 * t) << i << "," << j;
    }
  // A single-sided plane facing the light is no back face: back capture sees nothing.
  const DepthMap back = captureDepthEmbree(s, 48, 40, CaptureMode::Back);
  EXPECT_EQ(back.hitCount(), 0u);
  // Midpoint with one layer: the second layer is the far plane.
  const DepthMap mid = captureDepthEmbree(s, 48, 40, CaptureMode::Midpoint);
  for (std::size_t k = 0; k < map.depth.size(); ++k)
    ASSERT_NEAR(mid.depth[k], 0.5 * (map.depth[k] + map.farPlane), 1e-5 * map.farPlane);
}

TEST_P(CaptureAnalytic, SphereFrontBackAndMidpoint) {
  // Icosphere of detail 7: 327,680 triangles, radial deviation <= 1e-5 of the radius, so depths
  // away from the silhouette agree with the analytic sphere within 1e-5 relative.
  const glm::dvec3 centre(0.3, 2.0, -0.2);
  const double radius = 1.0;
  TriangleMesh sphere = makeIcoSphere(radius, 7);
  for (auto& p : sphere.positions) p += glm::vec3(centre);
  const Scene s = sceneOf(makeLight(GetParam()), {sphere});
  const int n = 40;
  const DepthMap front = captureDepthEmbree(s, n, n, CaptureMode::Front);
  const DepthMap back = captureDepthEmbree(s, n, n, CaptureMode::Back);
  const DepthMap mid = captureDepthEmbree(s, n, n, CaptureMode::Midpoint);
  int inside = 0, missed = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Ray r = texelRay(front, i, j);
      // Solve |org + t dir - c|^2 = R^2 in double.
      const glm::dvec3 oc = r.org - centre;
      const double A = glm::dot(r.dir, r.dir), B = glm::dot(oc, r.dir), C = glm::dot(oc, oc) - radius * radius;
      const double disc = B * B - A * C;
      // Impact parameter: distance of the centre from the ray's line.
      const double impact = glm::length(glm::cross(oc, r.dir)) / std::sqrt(A);
      if (impact < 0.9 * radius) {
        ++inside;
        const double t0 = (-B - std::sqrt(disc)) / A, t1 = (-B + std::sqrt(disc)) / A;
        ASSERT_NEAR(front.at(i, j), t0, 1e-5 * t0) << i << "," << j;
        ASSERT_NEAR(back.at(i, j), t1, 1e-5 * t1) << i << "," << j;
        ASSERT_NEAR(mid.at(i, j), 0.5 * (t0 + t1), 1e-5 * t1) << i << "," << j;
      } else if (impact > 1.01 * radius) {
        ++missed;
        EXPECT_TRUE(DepthMap::isNoHit(front.at(i, j)));
        EXPECT_TRUE(DepthMap::isNoHit(back.at(i, j)));
        EXPECT_TRUE(DepthMap::isNoHit(mid.at(i, j)));
      }
    }
  EXPECT_GT(inside, 100);  // the test looked at something
  EXPECT_GT(missed, 100);
}

INSTANTIATE_TEST_SUITE_P(BothLights, CaptureAnalytic, ::testing::Values(LightType::Spot, LightType::Directional));

TEST(Capture, BackModeSeesTheUndersideOfAFloatingBoxOverAGround) {
  TriangleMesh box = makeBox(2, 0.5, 2);
  for (auto& p : box.positions) p.y += 3.0f;  // from y = 2.75 to 3.25
  const Light l = makeLight(LightType::Directional);
  const Scene s = sceneOf(l, {makePlane(40, 40, 1), box});
  const DepthMap back = captureDepthEmbree(s, 32, 32, CaptureMode::Back);
  const DepthMap front = captureDepthEmbree(s, 32, 32, CaptureMode::Front);
  const int c = 16;
  // Straight below the light: front sees the top (y = 3.25), back the bottom (y = 2.75);
  // depths along the light axis differ by the box's height over the axis's cosine.
  const double cosine = -glm::normalize(l.direction).y;
  EXPECT_NEAR(back.at(c, c) - front.at(c, c), 0.5 / cosine, 1e-4);
  // Near the edge of the map only the ground is seen: front hits it, back does not.
  EXPECT_FALSE(DepthMap::isNoHit(front.at(0, 0)));
  EXPECT_TRUE(DepthMap::isNoHit(back.at(0, 0)));
}

// Midpoint takes the two nearest surfaces whatever order the BVH reports the hits in (regression:
// a hit after a farther one took the empty second slot, so three stacked plates gave the first
// and the third). Every order of three plates under a directional light, at 1, 2 and 3 below it.
TEST(Capture, MidpointTakesTheTwoNearestSurfacesInAnyHitOrder) {
  std::array<int, 3> order = {0, 1, 2};
  do {
    std::vector<TriangleMesh> plates;
    for (int k : order) {
      TriangleMesh p = makePlane(8, 8, 1);
      for (auto& v : p.positions) v.y = float(9 - k);
      plates.push_back(std::move(p));
    }
    Light l = makeLight(LightType::Directional);
    l.direction = {0, -1, 0};
    l.position = {0, 10, 0};
    const DepthMap m = captureDepthEmbree(sceneOf(l, std::move(plates)), 16, 16, CaptureMode::Midpoint);
    for (float d : m.depth) EXPECT_FLOAT_EQ(d, 1.5f) << order[0] << order[1] << order[2];
  } while (std::next_permutation(order.begin(), order.end()));
}

// Entry capture is front capture's depth wherever back capture records a back face, and no hit
// elsewhere: a sphere over a ground plane facing the light (which only front capture records), and
// a single-sided plate facing the light over the sphere (which back capture skips; entry capture
// records it where the sphere's back face lies behind it).
TEST(Capture, EntryIsFrontWhereBackHasABackFace) {
  TriangleMesh plate = makePlane(1.2, 1.2, 2);
  for (auto& v : plate.positions) v += glm::vec3(0.9f, 3.0f, 0.0f);
  for (LightType type : {LightType::Spot, LightType::Directional}) {
    const Scene s = sceneOf(makeLight(type), {makeIcoSphere(1.5, 4), makePlane(30, 30, 8), plate});
    const DepthMap front = captureDepthEmbree(s, 64, 64, CaptureMode::Front);
    const DepthMap back = captureDepthEmbree(s, 64, 64, CaptureMode::Back);
    const DepthMap entry = captureDepthEmbree(s, 64, 64, CaptureMode::Entry);
    EXPECT_EQ(entry.capture, CaptureMode::Entry);
    std::size_t hits = 0, plateHits = 0, groundOnly = 0;
    for (std::size_t k = 0; k < entry.depth.size(); ++k) {
      if (DepthMap::isNoHit(back.depth[k])) {
        EXPECT_TRUE(DepthMap::isNoHit(entry.depth[k])) << k;
        groundOnly += !DepthMap::isNoHit(front.depth[k]);
        continue;
      }
      ++hits;
      EXPECT_EQ(entry.depth[k], front.depth[k]) << k;
      EXPECT_LT(entry.depth[k], back.depth[k]) << k;  // the sphere's lit side before its back
      plateHits += entry.depth[k] < 7.5f;
    }
    EXPECT_GT(hits, 200u) << toString(type);
    EXPECT_GT(plateHits, 10u) << toString(type);  // the plate (depth about 7) over the sphere
    EXPECT_GT(groundOnly, 2000u) << toString(type);  // lit ground: front capture's, not entry's
  }
}

// Entry capture passes over a face lit nearly edge-on (cosine with the ray below kEntryGrazingCos):
// over a wedge's sloped face lit at half that cosine it records the bottom, the back face behind
// (back capture's depth), and over one lit at twice that cosine the slope (front capture's).
TEST(Capture, EntryPassesOverFacesLitNearlyEdgeOn) {
  for (double share : {0.5, 2.0}) {
    const Scene s = test::grazedWedgeScene(share * kEntryGrazingCos);
    const DepthMap front = captureDepthEmbree(s, 32, 32, CaptureMode::Front);
    const DepthMap back = captureDepthEmbree(s, 32, 32, CaptureMode::Back);
    const DepthMap entry = captureDepthEmbree(s, 32, 32, CaptureMode::Entry);
    std::size_t onSlope = 0;
    for (std::size_t k = 0; k < entry.depth.size(); ++k) {
      if (DepthMap::isNoHit(back.depth[k])) continue;
      const bool slope = front.depth[k] < back.depth[k] - 0.01f;
      onSlope += slope;
      EXPECT_EQ(entry.depth[k], slope && share < 1.0 ? back.depth[k] : front.depth[k]) << share << " " << k;
    }
    EXPECT_GT(onSlope, 400u) << share;  // 16 of the 32 columns
  }
}

TEST(Capture, IsDeterministic) {
  const Scene s = sceneOf(makeLight(LightType::Spot), {makeIcoSphere(1.5, 4), makePlane(30, 30, 8)});
  for (CaptureMode m : {CaptureMode::Front, CaptureMode::Back, CaptureMode::Midpoint, CaptureMode::Entry}) {
    const DepthMap a = captureDepthEmbree(s, 64, 64, m), b = captureDepthEmbree(s, 64, 64, m);
    EXPECT_EQ(0, std::memcmp(a.depth.data(), b.depth.data(), a.depth.size() * sizeof(float))) << toString(m);
  }
}

// captureRays (packets of eight) records what captureRay records one ray at a time, bit for bit, in
// every mode and for batches that do and do not fill their last packet: texel centres and points
// between them over a sphere on the ground with a plate above it and a wedge lit nearly edge-on
// (where entry capture passes a face over), the rays through the sphere's outline included.
TEST(Capture, PacketsRecordWhatOneRayAtATimeDoes) {
  TriangleMesh plate = makePlane(1.2, 1.2, 2);
  for (auto& v : plate.positions) v += glm::vec3(0.9f, 3.0f, 0.0f);
  TriangleMesh wedge = test::grazedWedgeScene(0.5 * kEntryGrazingCos, 2.0).objects.front().mesh;
  for (auto& v : wedge.positions) v += glm::vec3(-2.5f, 0.0f, 1.5f);
  const Scene s = sceneOf(makeLight(LightType::Spot), {makeIcoSphere(1.5, 4), makePlane(30, 30, 8), plate, wedge});
  const EmbreeDevice device;
  const EmbreeScene rt(device, {&s.objects[0].mesh, &s.objects[1].mesh, &s.objects[2].mesh, &s.objects[3].mesh});
  std::uint32_t seed = 12345;
  const auto next = [&seed] { return double((seed = seed * 1664525u + 1013904223u) >> 8) / double(1u << 24); };
  for (CaptureMode m : {CaptureMode::Front, CaptureMode::Back, CaptureMode::Midpoint, CaptureMode::Entry}) {
    const DepthMap map = makeDepthMap(s.light, 40, 40, m);
    const TexelUnprojector u(map);
    std::vector<TexelUnprojector::Ray> rays;
    for (int j = 0; j < map.height; ++j)
      for (int i = 0; i < map.width; ++i) {
        rays.push_back(u.ray(i, j));
        rays.push_back(u.ray(i + next() - 0.5, j + next() - 0.5));
      }
    std::size_t hits = 0;
    for (std::size_t batch : {std::size_t(1), std::size_t(7), std::size_t(8), std::size_t(61), rays.size()}) {
      for (std::size_t k0 = 0; k0 < rays.size(); k0 += batch) {
        const std::size_t n = std::min(batch, rays.size() - k0);
        std::vector<float> depth(n, -1.0f);
        captureRays(rt.get(), std::span(rays).subspan(k0, n), float(map.nearPlane), float(map.farPlane), m, depth);
        for (std::size_t k = 0; k < n; ++k) {
          const float one = captureRay(rt.get(), rays[k0 + k], float(map.nearPlane), float(map.farPlane), m);
          ASSERT_EQ(std::bit_cast<std::uint32_t>(depth[k]), std::bit_cast<std::uint32_t>(one))
              << toString(m) << " " << k0 + k;
          hits += !DepthMap::isNoHit(one);
        }
      }
    }
    EXPECT_GT(hits, 5 * rays.size() / 5) << toString(
        m);  // a fifth of the rays record a surface (the sphere's, at least)
  }
}

// A library caller that skips checkDepthMapSize gets the same refusal, not an internal check.
TEST(Capture, SizesTheMapCannotHaveAreAnInputError) {
  const Scene s = sceneOf(makeLight(LightType::Spot), {makeIcoSphere(1.5, 2)});
  for (const auto& [w, h] : {std::pair{0, 64}, {64, 1}, {-3, -3}, {kMaxDepthMapSide + 1, 2}}) {
    try {
      (void)captureDepthEmbree(s, w, h, CaptureMode::Back);
      ADD_FAILURE() << w << "x" << h << " was captured";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("width x height"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(captureDepthEmbree(s, 2, 2, CaptureMode::Back).depth.size(), 4u);
}

TEST(Capture, NearAndFarClipLikeTheGpu) {
  // A sphere cut by the near plane: texels whose front surface is before near see the next
  // surface beyond near (GL clips the triangle, so the back side shows), never a depth < near.
  Light l = makeLight(LightType::Spot);
  l.nearPlane = 8.0;  // the sphere's top is at 10 - 2 - 1 = 7 along the axis
  TriangleMesh sphere = makeIcoSphere(1.0, 4);
  for (auto& p : sphere.positions) p.y += 2.0f;
  const DepthMap map = captureDepthEmbree(sceneOf(l, {sphere}), 32, 32, CaptureMode::Front);
  std::size_t hits = 0;
  for (float d : map.depth)
    if (!DepthMap::isNoHit(d)) {
      ++hits;
      EXPECT_GE(d, 8.0f);
      EXPECT_LE(d, 20.0f);
    }
  EXPECT_GT(hits, 0u);
}

}  // namespace
}  // namespace shadowvol

// The perfect-triangulation rule flipDiagonal (triangulation.h) on hand-made quads.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "shadowvol/triangulation.h"

namespace shadowvol {
namespace {

// Quad corners in light-view space: texel (i, j) -> (i, j, -depth), one texel = 1 world unit.
struct Quad {
  glm::dvec3 p[4];  // A, B, C, D
};

Quad quadOnPlane(double d0, double gx, double gy) {
  // Depths of a tilted plane: d = d0 + gx * i + gy * j over the corners A (0,0) B (1,0) C (1,1) D (0,1).
  const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
  Quad q;
  for (int k = 0; k < 4; ++k) q.p[k] = {double(di[k]), double(dj[k]), -(d0 + gx * di[k] + gy * dj[k])};
  return q;
}

bool flip(const Quad& q) { return flipDiagonal(q.p[0], q.p[1], q.p[2], q.p[3]); }

// The odd vertex (the one off the plane of the other three) must never be on the chosen diagonal:
// A or C odd -> fixed B-D (no flip); B or D odd -> A-C (flip). This holds when the displacement
// dominates the plane's own tilt (depth steps at silhouettes); for small bumps on steep planes the
// thesis's distance rule can pick either diagonal (see MatchesThesisDistanceFormula).
TEST(Triangulation, OddVertexNeverOnDiagonal) {
  const double planes[][3] = {{10, 0, 0}, {10, 0.3, -0.2}, {5, -1.5, 2.0}, {100, 0.01, 0.02}};
  const double offsets[] = {-80.0, -5.0, -0.5, -1e-3, 1e-3, 0.5, 5.0, 80.0};
  int cases = 0;
  for (const auto& pl : planes)
    for (double off : offsets) {
      if (std::abs(off) < 10.0 * std::max(std::abs(pl[1]), std::abs(pl[2]))) continue;
      for (int odd = 0; odd < 4; ++odd) {
        Quad q = quadOnPlane(pl[0], pl[1], pl[2]);
        q.p[odd].z -= off;
        const bool expected = odd == 1 || odd == 3;
        EXPECT_EQ(flip(q), expected) << "odd corner " << odd << " offset " << off << " plane " << pl[0] << ","
                                     << pl[1] << "," << pl[2];
        ++cases;
      }
    }
  EXPECT_GE(cases, 60);
}

// The division-free form agrees with the thesis's literal formula (normalised plane distances)
// on random non-degenerate quads.
TEST(Triangulation, MatchesThesisDistanceFormula) {
  auto dist = [](const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    return std::abs(glm::dot(p - a, glm::normalize(glm::cross(b - a, c - a))));
  };
  std::uint64_t state = 12345;
  auto uniform = [&]() {  // deterministic LCG in [0, 1)
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) * (1.0 / 9007199254740992.0);
  };
  int flips = 0, checked = 0;
  for (int n = 0; n < 2000; ++n) {
    Quad q = quadOnPlane(10.0 * uniform() + 1.0, uniform() - 0.5, uniform() - 0.5);
    for (auto& p : q.p) p.z -= (uniform() - 0.5) * (n % 2 ? 0.2 : 5.0);
    const auto& [a, b, c, d] = q.p;
    const double dA = dist(a, b, c, d), dB = dist(b, a, c, d), dC = dist(c, a, b, d), dD = dist(d, a, b, c);
    // Skip near-ties, where round-off may decide differently in the two forms.
    const double gap = std::min({std::abs(dA - dB), std::abs(dA - dC), std::abs(dA - dD), std::abs(dB - dC),
                                 std::abs(dB - dD), std::abs(dC - dD)});
    if (gap < 1e-9) continue;
    const bool thesis = (dB > dC && dB > dA) || (dD > dC && dD > dA);
    EXPECT_EQ(flip(q), thesis) << n;
    flips += thesis;
    ++checked;
  }
  EXPECT_GT(checked, 1900);
  EXPECT_GT(flips, 300);  // both outcomes are exercised
  EXPECT_LT(flips, checked - 300);
}

// Depth discontinuity, three texels on the occluder and one on the receiver (the staircase case).
TEST(Triangulation, ThreeOnOccluderOneOnReceiver) {
  for (int odd = 0; odd < 4; ++odd) {
    Quad q = quadOnPlane(2.0, 0, 0);
    q.p[odd].z = -20.0;  // the receiver (or the far plane)
    EXPECT_EQ(flip(q), odd == 1 || odd == 3) << odd;
  }
  // Perspective-like corners (x, y scaled by depth) behave the same.
  for (int odd = 0; odd < 4; ++odd) {
    const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
    glm::dvec3 p[4];
    for (int k = 0; k < 4; ++k) {
      const double d = k == odd ? 30.0 : 3.0;
      p[k] = {(0.01 * di[k] + 0.2) * d, (0.01 * dj[k] - 0.1) * d, -d};
    }
    EXPECT_EQ(flipDiagonal(p[0], p[1], p[2], p[3]), odd == 1 || odd == 3) << odd;
  }
}

// Ties: a symmetric saddle (A, C up, B, D down) has four equal distances: no flip (strict rule).
TEST(Triangulation, TiesKeepFixedDiagonal) {
  Quad q = quadOnPlane(10, 0, 0);
  q.p[0].z += 1;
  q.p[2].z += 1;
  q.p[1].z -= 1;
  q.p[3].z -= 1;
  EXPECT_FALSE(flip(q));
  // B and D displaced alike is the same saddle seen from the other diagonal: four equal distances.
  Quad r = quadOnPlane(10, 0, 0);
  r.p[1].z -= 1;
  r.p[3].z -= 1;
  EXPECT_FALSE(flip(r));
  Quad s = quadOnPlane(10, 0, 0);
  s.p[1].z -= 1;
  s.p[3].z -= 2;  // D is the odd one, B half as much: D farthest -> flip
  EXPECT_TRUE(flip(s));
}

// Planar quads (flat, tilted, far-plane regions) never flip, also near-planar within tolerance.
TEST(Triangulation, PlanarQuadsDoNotFlip) {
  EXPECT_FALSE(flip(quadOnPlane(10, 0, 0)));
  EXPECT_FALSE(flip(quadOnPlane(10, 3.7, -2.1)));
  EXPECT_FALSE(flip(quadOnPlane(1e6, 0, 0)));
  Quad q = quadOnPlane(10, 0.5, 0.5);
  q.p[1].z -= 1e-12;  // far below kPlanarTolerance * L^3
  EXPECT_FALSE(flip(q));
}

// Repeated and collinear points, zero-size quads and non-finite input: false, never a crash.
TEST(Triangulation, DegenerateQuadsDoNotFlip) {
  const glm::dvec3 a(0, 0, -1), b(1, 0, -1), c(1, 1, -1);
  EXPECT_FALSE(flipDiagonal(a, a, a, a));
  EXPECT_FALSE(flipDiagonal(a, a, c, c));
  EXPECT_FALSE(flipDiagonal(a, b, b, c));
  EXPECT_FALSE(flipDiagonal(a, b, a + 2.0 * (b - a), a + 3.0 * (b - a)));  // collinear
  EXPECT_FALSE(flipDiagonal(glm::dvec3(0), glm::dvec3(0), glm::dvec3(0), glm::dvec3(0)));
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(flipDiagonal(a, b, c, glm::dvec3(nan, 0, 0)));
  EXPECT_FALSE(flipDiagonal(a, glm::dvec3(0, inf, 0), c, glm::dvec3(0, 1, -1)));
}

// The rule is invariant under translation, uniform scaling and rotation (it is evaluated on
// light-view points, a rigid image of world space).
TEST(Triangulation, InvariantUnderSimilarity) {
  Quad q = quadOnPlane(5, 0.2, -0.1);
  q.p[3].z -= 0.7;
  ASSERT_TRUE(flip(q));
  for (double scale : {1e-4, 1.0, 1e4})
    for (double angle : {0.0, 0.7, 2.5}) {
      const double c = std::cos(angle), s = std::sin(angle);
      glm::dvec3 p[4];
      for (int k = 0; k < 4; ++k) {
        const glm::dvec3 v = q.p[k] * scale;
        p[k] = glm::dvec3(c * v.x - s * v.z, v.y, s * v.x + c * v.z) + glm::dvec3(100, -50, 3);
      }
      EXPECT_TRUE(flipDiagonal(p[0], p[1], p[2], p[3])) << scale << " " << angle;
    }
}

}  // namespace
}  // namespace shadowvol

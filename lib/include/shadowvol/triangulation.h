// Per-quad diagonal choice ("perfect triangulation", algorithm.md) shared by the CPU builder and,
// mirrored line for line, by the GPU volume shader (shaders/volume_gpu.vert).
//
// Quad corners, counter-clockwise in texel space (i right, j up):
//   A = (i, j), B = (i + 1, j), C = (i + 1, j + 1), D = (i, j + 1).
// Fixed diagonal B-D: triangles (A, B, D) and (B, C, D). Flipped diagonal A-C: (A, B, C), (A, C, D).
//
// The rule is evaluated in light-view space (world units; a rigid image of world space), on the
// four unprojected sheet vertices. dist(X; other three) = 3 V / area(triangle opposite X), V the
// volume of the tetrahedron ABCD, so "X is the farthest from the plane of the others" is "the
// triangle opposite X has the smallest area" and the thesis's rule
//   flip iff (dB > dC and dB > dA) or (dD > dC and dD > dA)
// becomes, without any division (so no NaN for repeated or collinear points),
//   flip iff (aB < aC and aB < aA) or (aD < aC and aD < aA),   aX = area opposite X.
// Degenerate and near-planar quads do not flip: when 6 V <= kPlanarTolerance * L^3 (L the longest
// of the quad's six pairwise distances), the quad counts as planar and keeps the fixed diagonal.
// Ties (equal areas) do not flip: the comparisons are strict.
// Evaluated without sqrt: areas compare as their squares (|n|^2 for the cross products n), and
// the planarity test as (6 V)^2 <= kPlanarTolerance^2 * (L^2)^3; both are the same order as the
// unsquared quantities and in double cannot overflow before coordinates reach 1e50.
#pragma once

#include <string>

#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "shadowvol/enum_names.h"

namespace shadowvol {

enum class Triangulation {
  Fixed,    ///< diagonal B-D everywhere (the thesis's triangle strips)
  Perfect,  ///< per-quad choice by the plane-distance rule above
};

inline constexpr EnumNames<Triangulation, 2> kTriangulationNames{
    {{Triangulation::Fixed, "fixed"}, {Triangulation::Perfect, "perfect"}}};

const char* toString(Triangulation t);
bool parseTriangulation(const std::string& text, Triangulation& t);

/// Relative volume below which a quad is planar (see above). 1e-9 of L^3: far below any real
/// depth step (a step of 1e-9 L cannot be resolved in a float depth map), far above double round-off.
inline constexpr double kPlanarTolerance = 1e-9;

/// True when the quad A B C D (light-view or world space, see above) takes the A-C diagonal.
/// False for non-finite input. Inline: the builder evaluates it once per quad.
inline bool flipDiagonal(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
  const glm::dvec3 ab = b - a, ac = c - a, ad = d - a, bc = c - b, bd = d - b, cd = d - c;
  // Normals of the triangles opposite each corner (twice their areas as length).
  const glm::dvec3 nA = glm::cross(bc, bd), nB = glm::cross(ac, ad), nC = glm::cross(ab, ad), nD = glm::cross(ab, ac);
  const double sA = glm::dot(nA, nA), sB = glm::dot(nB, nB), sC = glm::dot(nC, nC), sD = glm::dot(nD, nD);
  const double sixV = glm::dot(ab, nB);
  const double l2 = std::max(std::max(std::max(glm::dot(ab, ab), glm::dot(ac, ac)), std::max(glm::dot(ad, ad), glm::dot(bc, bc))),
                             std::max(glm::dot(bd, bd), glm::dot(cd, cd)));
  // Not planar, not degenerate, finite (NaN and infinity fail the comparison); branch-free so the
  // builder's per-row loop vectorises.
  const bool solid = sixV * sixV > (kPlanarTolerance * kPlanarTolerance) * (l2 * l2 * l2);
  return solid & (((sB < sC) & (sB < sA)) | ((sD < sC) & (sD < sA)));
}

}  // namespace shadowvol

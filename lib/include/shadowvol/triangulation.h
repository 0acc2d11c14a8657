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
#pragma once

#include <string>

#include <glm/vec3.hpp>

namespace shadowvol {

enum class Triangulation {
  Fixed,    ///< diagonal B-D everywhere (the thesis's triangle strips)
  Perfect,  ///< per-quad choice by the plane-distance rule above
};

const char* toString(Triangulation t);
bool parseTriangulation(const std::string& text, Triangulation& t);

/// Relative volume below which a quad is planar (see above). 1e-9 of L^3: far below any real
/// depth step (a step of 1e-9 L cannot be resolved in a float depth map), far above double round-off.
inline constexpr double kPlanarTolerance = 1e-9;

/// True when the quad A B C D (light-view or world space, see above) takes the A-C diagonal.
bool flipDiagonal(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d);

}  // namespace shadowvol

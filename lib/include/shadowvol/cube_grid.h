// The closed texel grid of a cube map (cube_map.h): the point light's sheet is one surface over
// all six faces, like the grid of one depth map but without a border. Its cells:
//   - quads inside each face, between texels (i, j), (i+1, j), (i+1, j+1), (i, j+1);
//   - quads across each of the 12 cube edges, between two border texels of one face and the two
//     border texels they pair with on the other (cubeTexelAcross);
//   - one triangle at each of the 8 cube corners, between the corner texels of its three faces.
// 6 (N-1)^2 + 12 (N-1) quads and 8 triangles, 12 N^2 - 4 sheet triangles over 6 N^2 texels: a
// closed surface of genus 0. Every cell's corners are counter-clockwise as the light sees them
// (in the texel space of the face it is listed from, continued across the edge), so a cell
// gives the same triangles as a quad of one map (triangulation.h): A B D + B C D, or A B C +
// A C D with the flipped diagonal.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace shadowvol::cube {

/// Texel id of face f's texel (i, j): f N^2 + j N + i.
inline std::uint32_t texelId(int n, int face, int i, int j) {
  return std::uint32_t(face) * std::uint32_t(n) * std::uint32_t(n) + std::uint32_t(j) * std::uint32_t(n) +
         std::uint32_t(i);
}

/// Texels of an N x N cube map, 6 N^2: the first id after the last texel's.
inline std::uint32_t texelCount(int n) { return texelId(n, 6, 0, 0); }

/// Inner quads of an N x N cube map, 6 (N-1)^2: they come first in Grid's order.
inline std::size_t innerQuadCount(int n) { return std::size_t(6) * std::size_t(n - 1) * std::size_t(n - 1); }

/// Grid's index of face f's inner quad (i, j) (corners (i, j) to (i+1, j+1)).
inline std::size_t innerQuadIndex(int n, int face, int i, int j) {
  const std::size_t q = std::size_t(n - 1);
  return (std::size_t(face) * q + std::size_t(j)) * q + std::size_t(i);
}

struct Cell {
  std::array<std::uint32_t, 4> v{};  ///< texel ids A, B, C, D; a corner triangle is A, B, D (C unused)
  bool triangle = false;
  int face = 0;                      ///< the face it lies in (inner quads) or is listed from
  bool inner = false;                ///< inside one face (its far images lie in that face's far plane)
  int cornerCount() const { return triangle ? 3 : 4; }
  /// Corner k of its loop: A B C D, or A B D of a corner triangle.
  std::uint32_t corner(int k) const { return triangle && k == 2 ? v[3] : v[std::size_t(k)]; }
};

/// The direction of texel `id`'s centre from the light, at its face's depth 1 (cubeTexelDirection).
glm::dvec3 texelDirection(int n, std::uint32_t id);

/// Every cell once, deterministically: the inner quads face by face, row by row (computed when
/// asked for: there are 6 (N-1)^2 of them); then the edge quads and corner triangles (kept) in the
/// order of the faces and borders they are first met from.
class Grid {
 public:
  explicit Grid(int n);
  std::size_t size() const { return inner_ + seams_.size(); }
  Cell operator[](std::size_t c) const {
    if (c >= inner_) return seams_[c - inner_];
    const std::size_t q = std::size_t(n_ - 1), f = c / (q * q), r = c % (q * q);
    const int i = int(r % q), j = int(r / q), face = int(f);
    return {{texelId(n_, face, i, j), texelId(n_, face, i + 1, j), texelId(n_, face, i + 1, j + 1),
             texelId(n_, face, i, j + 1)},
            false, face, true};
  }

 private:
  int n_;
  std::size_t inner_;
  std::vector<Cell> seams_;
};

}  // namespace shadowvol::cube

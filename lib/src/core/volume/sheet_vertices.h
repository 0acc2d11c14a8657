// Stage 3 of the volume builder: the sheet's vertices, one per texel that a kept triangle uses,
// numbered in texel order (row-major from texel (0, 0)), and the cap's boundary texels: used
// texels whose fan of triangles is not complete. Read from the quad codes alone.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "volume/quad_codes.h"

namespace shadowvol::volume {

/// Which texels the kept triangles use, from the codes (four masked loads per texel).
class TexelUse {
 public:
  TexelUse(const QuadGrid& grid, const QuadCodes& codes);
  /// The corner-used bits (code bits 3..6) meeting at texel (i, j); nonzero = used.
  std::uint8_t mask(int i, int j) const {
    return (grid_.at(i, j) & kUsedA) | (grid_.at(i - 1, j) & kUsedB) | (grid_.at(i - 1, j - 1) & kUsedC) |
           (grid_.at(i, j - 1) & kUsedD);
  }
  /// All four quads exist and keep every triangle holding the texel.
  bool completeFan(int i, int j) const {
    return ((kCornerCovered[grid_.at(i, j)] & 1) & (kCornerCovered[grid_.at(i - 1, j)] >> 1) &
            (kCornerCovered[grid_.at(i - 1, j - 1)] >> 2) & (kCornerCovered[grid_.at(i, j - 1)] >> 3)) != 0;
  }
  /// A used texel with an incomplete fan (always a far texel: a triangle with a non-far corner is
  /// always kept, and texels off the border ring have all four quads).
  bool isBoundary(int i, int j) const { return mask(i, j) != 0 && !completeFan(i, j); }
  /// used[i] of row j for i in the returned span [b, e) (other entries are not written).
  std::pair<int, int> row(int j, std::uint8_t* used) const;
  const QuadGrid& grid() const { return grid_; }

 private:
  QuadGrid grid_;
  const QuadCodes& codes_;
  std::vector<std::uint8_t> zeroRow_;
};

struct SheetVertices {
  struct Boundary {
    int i = 0;
    std::uint32_t local = 0;  ///< index among the used texels of its row
  };
  std::vector<std::uint64_t> rowVerts;             ///< h + 1 prefix sums: the first vertex of texel row j
  std::vector<std::vector<Boundary>> rowBoundary;  ///< per texel row, in order of i
  std::uint64_t count() const { return rowVerts.back(); }
};

/// Stage 3: vertex counts per texel row and (findBoundary) the boundary texels, row-parallel.
/// With refinement there are none: every far texel is then unused (a quad with far and non-far
/// corners is refined), and a non-far texel's fan may be incomplete by design.
SheetVertices countSheetVertices(const TexelUse& use, bool findBoundary = true);

/// Vertex indices of n texels: consecutive from `first` for used ones, `none` for the others;
/// returns the next free index.
std::uint32_t numberRow(const std::uint8_t* __restrict used, std::uint32_t* __restrict idx, int n, std::uint32_t first,
                        std::uint32_t none);

}  // namespace shadowvol::volume

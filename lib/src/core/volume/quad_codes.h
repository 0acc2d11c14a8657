// Stage 2 of the volume builder: one code byte per quad (grid cell): its diagonal (triangulation.h)
// and which of its two triangles the mesh keeps (the exact cap drops triangles lying on the far
// plane), plus the corners its kept triangles use. Later stages read the codes alone.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "shadowvol/triangulation.h"
#include "volume/build_buffers.h"
#include "volume/grid_unprojector.h"
#include "volume/sheet_depths.h"

namespace shadowvol::volume {

// Code bits: the diagonal and which of its two triangles the mesh keeps; kRefined marks a quad
// with a boundary edge (refinement), whose triangles come from refined_cells.h instead (its keep
// bits are clear, its used bits are its non-far corners).
inline constexpr std::uint8_t kFlip = 1, kKeep0 = 2, kKeep1 = 4, kRefined = 128;
constexpr std::uint8_t keepBit(int t) { return t == 0 ? kKeep0 : kKeep1; }

// Corners 0..3 = A (i, j), B (i + 1, j), C (i + 1, j + 1), D (i, j + 1) of quad (i, j).
inline constexpr int kCornerDi[4] = {0, 1, 1, 0};
inline constexpr int kCornerDj[4] = {0, 0, 1, 1};
// kTriCorners[flip][t]: fixed (B-D): ABD, BCD; flipped (A-C): ABC, ACD (triangulation.h).
inline constexpr int kTriCorners[2][2][3] = {{{0, 1, 3}, {1, 2, 3}}, {{0, 1, 2}, {0, 2, 3}}};

// Per quad code (its low 3 bits), as 4-bit masks over the corners: used = held by a kept
// triangle; covered = every triangle of the quad holding it is kept.
struct CornerTables {
  std::uint8_t used[256] = {}, covered[256] = {};
  constexpr CornerTables() {
    for (int q = 0; q < 256; ++q) {
      const int f = q & kFlip;
      int u = 0, uncovered = 0;
      for (int t = 0; t < 2; ++t)
        for (int c : kTriCorners[f][t]) {
          if (q & keepBit(t)) u |= 1 << c;
          else uncovered |= 1 << c;
        }
      used[q] = std::uint8_t(u);
      covered[q] = std::uint8_t(15 & ~uncovered);
    }
  }
};
inline constexpr CornerTables kCornerTables;
// The code byte also holds the used corners of its low bits in bits 3..6, so that a texel's use is
// four masked loads: A of quad (i, j), B of (i - 1, j), C of (i - 1, j - 1), D of (i, j - 1).
inline constexpr int kUsedShift = 3;
inline constexpr std::uint8_t kUsedA = 1 << kUsedShift, kUsedB = 2 << kUsedShift, kUsedC = 4 << kUsedShift,
                              kUsedD = 8 << kUsedShift;
inline constexpr const std::uint8_t* kCornerUsed = kCornerTables.used;
inline constexpr const std::uint8_t* kCornerCovered = kCornerTables.covered;

/// Read access to the codes of a qw x qh quad grid; quads outside it read as 0 (nothing kept).
struct QuadGrid {
  int qw = 0, qh = 0;
  const std::uint8_t* code = nullptr;
  std::uint8_t at(int qi, int qj) const {
    return (qi < 0 || qj < 0 || qi >= qw || qj >= qh) ? std::uint8_t(0) : code[std::size_t(qj) * qw + qi];
  }
  bool kept(int qi, int qj, int t) const { return (at(qi, qj) & keepBit(t)) != 0; }
  // Triangle of quad (qi, qj) holding its right (B-C) or left (D-A) edge.
  int rightTri(int qi, int qj) const { return (at(qi, qj) & kFlip) ? 0 : 1; }
  int leftTri(int qi, int qj) const { return (at(qi, qj) & kFlip) ? 1 : 0; }
  /// Is the triangle across edge k (from corner k to corner k + 1) of triangle t of quad (qi, qj) kept?
  bool neighbourKept(int qi, int qj, int t, int k) const;
};

struct QuadCodeOptions {
  bool exact = true;    ///< exact cap: triangles with three far corners are dropped
  bool perfect = true;  ///< the diagonal by flipDiagonal, else B-D everywhere
  const std::uint8_t* splitBits = nullptr;  ///< refinement: per texel, bit 0 / 1 = its edge along
                                            ///< +i / +j is a boundary edge (findBoundaryEdges);
                                            ///< kHiddenQuadBit: the quad it is the lower-left corner of
                                            ///< is refined without a boundary side
  bool hiddenQuads = false;                 ///< kHiddenQuadBit may be set (on any quad, far ones too:
                                            ///< hidden or crease quads)
};

/// splitBits' bit for a quad refined for a hidden surface (hidden_quads.h) or a crease
/// (crease_quads.h) alone: the sub-grid samples it though no boundary edge touches it.
inline constexpr std::uint8_t kHiddenQuadBit = 4;

/// What stage 2 found, per quad row.
struct QuadCodes {
  std::vector<std::pair<int, int>> rowSpan;  ///< quad row qj: no nonzero code outside [first, second)
  std::vector<std::uint64_t> rowTriOffset;   ///< qh + 1 prefix sums: the first sheet triangle of row qj
  std::size_t flipped = 0;                   ///< quads that took the A-C diagonal
  std::size_t dropped = 0;                   ///< quads that keep no triangle (refined quads aside)
  std::size_t refined = 0;                   ///< quads with a boundary edge or hidden (kRefined)
  std::uint64_t sheetTriangles() const { return rowTriOffset.back(); }
};

/// Stage 2: the code of every quad of the map into `code` (qw * qh bytes, row-major), two rolling
/// texel rows per task (sheet depths, far flags, light-view points for the diagonal rule).
/// Throws InputError (validateDepths) for a NaN or negative stored depth.
QuadCodes computeQuadCodes(const SheetDepths& sheet, const GridUnprojector& unproject, const QuadCodeOptions& options,
                           Scratch<std::uint8_t>& code);

}  // namespace shadowvol::volume

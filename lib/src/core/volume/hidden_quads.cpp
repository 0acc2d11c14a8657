#include "volume/hidden_quads.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadowvol/boundary_edges.h"
#include "shadowvol/nearer_surfaces.h"
#include "volume/chord_offsets.h"
#include "volume/quad_codes.h"

namespace shadowvol::volume {

std::vector<std::uint32_t> findHiddenQuads(const SheetDepths& sheet, const NearerSurfaceOracle& search,
                                           int subdivisions, std::uint8_t* splitBits, std::size_t* rims) {
  const DepthMap& map = sheet.map();
  const SheetDepthRule& rule = sheet.rule();
  const int w = map.width, qw = w - 1, qh = map.height - 1;
  constexpr float kNone = -std::numeric_limits<float>::infinity();
  const TexelFootprint footprint = TexelFootprint::of(map);
  std::vector<float> limit(std::size_t(qw) * std::size_t(qh), kNone), rimLimit(limit.size(), kNone);
  // Row-parallel, each block rolling two rows of samples (chordSampleRow: +inf where far or on the
  // ring) down the map; the captured depth is the sample less the bias.
  tbb::parallel_for(tbb::blocked_range<int>(0, qh), [&](const tbb::blocked_range<int>& rows) {
    const auto n = static_cast<std::size_t>(w);
    std::vector<double> lowerRow(n), upperRow(n);
    chordSampleRow(sheet, rows.begin(), upperRow.data());
    for (int qj = rows.begin(); qj != rows.end(); ++qj) {
      std::swap(lowerRow, upperRow);
      chordSampleRow(sheet, qj + 1, upperRow.data());
      const std::uint8_t* lower = splitBits + std::size_t(qj) * w;
      const std::uint8_t* upper = lower + w;
      for (int qi = 0; qi < qw; ++qi) {
        if ((lower[qi] & 3) | (lower[qi + 1] & 2) | (upper[qi] & 1)) continue;  // refined already
        const double c[4] = {lowerRow[std::size_t(qi)] - rule.bias, lowerRow[std::size_t(qi) + 1] - rule.bias,
                             upperRow[std::size_t(qi)] - rule.bias, upperRow[std::size_t(qi) + 1] - rule.bias};
        const double m = std::min({c[0], c[1], c[2], c[3]}), far = std::max({c[0], c[1], c[2], c[3]});
        const std::size_t q = std::size_t(qj) * qw + qi;
        limit[q] = float(std::isinf(m) ? rule.farSnap - rule.bias : m - kJumpFootprints * footprint.at(m) / subdivisions);
        // A rim behind the farthest corner by more than a discontinuity is hidden behind what it records.
        if (!std::isinf(far)) rimLimit[q] = float(far + kJumpFootprints * footprint.at(far));
      }
    }
  });
  std::vector<std::uint8_t> flags(limit.size(), 0);
  search(map, limit, rimLimit, flags);
  std::vector<std::uint32_t> hidden;
  for (std::size_t q = 0; q < flags.size(); ++q) {
    if (!flags[q] || limit[q] == kNone) continue;
    if (rims && flags[q] == kRimFlag) ++*rims;
    hidden.push_back(std::uint32_t(q));
    splitBits[(q / std::size_t(qw)) * std::size_t(w) + q % std::size_t(qw)] |= kHiddenQuadBit;
  }
  return hidden;
}

}  // namespace shadowvol::volume

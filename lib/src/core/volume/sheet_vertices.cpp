#include "volume/sheet_vertices.h"

#include <algorithm>
#include <cstring>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace shadowvol::volume {
namespace {

// Row kernels as free functions with restrict pointers and loop bounds by value: inside a lambda
// a byte store may alias the captured sizes, which stops the compiler from vectorising.

// The corner-used bits (code bits 3..6) meeting at texels [b, e) of a row (0 <= b < e <= qw + 1),
// from the codes of the quad rows above (cur) and below (prev) it.
void usedBits(const std::uint8_t* __restrict cur, const std::uint8_t* __restrict prev, std::uint8_t* __restrict used,
              int qw, int b, int e, std::uint8_t ma, std::uint8_t mb, std::uint8_t mc, std::uint8_t md) {
  if (b == 0) used[b++] = std::uint8_t((cur[0] & ma) | (prev[0] & md));
  const int interiorEnd = std::min(e, qw);
  for (int i = b; i < interiorEnd; ++i)
    used[i] = std::uint8_t((cur[i] & ma) | (cur[i - 1] & mb) | (prev[i - 1] & mc) | (prev[i] & md));
  if (e == qw + 1 && b <= qw) used[qw] = std::uint8_t((cur[qw - 1] & mb) | (prev[qw - 1] & mc));
}

// Number of nonzero bytes among n.
std::uint32_t countNonzero(const std::uint8_t* __restrict p, int n) {
  std::uint32_t k = 0;
  for (int i = 0; i < n; ++i) k += p[i] != 0;
  return k;
}

// candidate[i] = 1 for the used texels i in [b, e) (0 <= b < e <= qw + 1) of a row whose four
// quads do not all keep both triangles (mask = the two keep bits), else 0: the only texels whose
// fan can be incomplete. Missing quads at the ends (i = 0, i = qw) count as not kept.
void notAllKept(const std::uint8_t* __restrict cur, const std::uint8_t* __restrict prev,
                const std::uint8_t* __restrict used, std::uint8_t* __restrict candidate, int qw, int b, int e,
                std::uint8_t mask) {
  if (b == 0) candidate[b] = used[b] != 0, ++b;
  const int interiorEnd = std::min(e, qw);
  for (int i = b; i < interiorEnd; ++i)
    candidate[i] = std::uint8_t((used[i] != 0) & ((cur[i] & cur[i - 1] & prev[i - 1] & prev[i] & mask) != mask));
  if (e == qw + 1 && b <= qw) candidate[qw] = used[qw] != 0;
}

}  // namespace

std::uint32_t numberRow(const std::uint8_t* __restrict used, std::uint32_t* __restrict idx, int n, std::uint32_t first,
                        std::uint32_t none) {
  std::uint32_t k = first;
  for (int i = 0; i < n; ++i) {
    const std::uint32_t u = used[i] != 0;
    idx[i] = u ? k : none;
    k += u;
  }
  return k;
}

TexelUse::TexelUse(const QuadGrid& grid, const QuadCodes& codes)
    : grid_(grid), codes_(codes), zeroRow_(std::size_t(grid.qw), 0) {}

std::pair<int, int> TexelUse::row(int j, std::uint8_t* used) const {
  const int qw = grid_.qw, qh = grid_.qh;
  // Texels of row j that can be used: those of the quad spans of the quad rows above and below.
  std::pair<int, int> span{qw + 1, 0};
  for (int qj : {j - 1, j}) {
    if (qj < 0 || qj >= qh || codes_.rowSpan[qj].first >= codes_.rowSpan[qj].second) continue;
    span.first = std::min(span.first, codes_.rowSpan[qj].first);
    span.second = std::max(span.second, codes_.rowSpan[qj].second + 1);
  }
  if (span.first >= span.second) return {0, 0};
  const std::uint8_t* cur = j < qh ? grid_.code + std::size_t(j) * qw : zeroRow_.data();
  const std::uint8_t* prev = j > 0 ? grid_.code + std::size_t(j - 1) * qw : zeroRow_.data();
  usedBits(cur, prev, used, qw, span.first, span.second, kUsedA, kUsedB, kUsedC, kUsedD);
  return span;
}

SheetVertices countSheetVertices(const TexelUse& use, bool findBoundary) {
  const QuadGrid& grid = use.grid();
  const int qw = grid.qw, qh = grid.qh, w = qw + 1, h = qh + 1;
  const std::vector<std::uint8_t> zeroRow(std::size_t(qw), 0);
  SheetVertices result;
  result.rowBoundary.resize(h);
  result.rowVerts.assign(std::size_t(h) + 1, 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 16), [&](const tbb::blocked_range<int>& rows) {
    std::vector<std::uint8_t> used(w), candidate(w);
    for (int j = rows.begin(); j != rows.end(); ++j) {
      const auto [b, e] = use.row(j, used.data());
      result.rowVerts[j + 1] = countNonzero(used.data() + b, e - b);
      if (b == e || !findBoundary) continue;
      const std::uint8_t* cur = j < qh ? grid.code + std::size_t(j) * qw : zeroRow.data();
      const std::uint8_t* prev = j > 0 ? grid.code + std::size_t(j - 1) * qw : zeroRow.data();
      notAllKept(cur, prev, used.data(), candidate.data(), qw, b, e, kKeep0 | kKeep1);
      std::uint32_t local = 0;
      int counted = b;
      for (int i = b; i < e;) {
        const void* hit = std::memchr(candidate.data() + i, 1, std::size_t(e - i));
        if (!hit) break;
        i = int(static_cast<const std::uint8_t*>(hit) - candidate.data());
        if (!use.completeFan(i, j)) {
          local += countNonzero(used.data() + counted, i - counted);
          counted = i;
          result.rowBoundary[j].push_back({i, local});
        }
        ++i;
      }
    }
  });
  for (int j = 0; j < h; ++j) result.rowVerts[j + 1] += result.rowVerts[j];
  return result;
}

}  // namespace shadowvol::volume

#include "volume/quad_codes.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <string.h>  // memrchr
#include <tuple>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace shadowvol::volume {
namespace {

// flip[qi] = flipDiagonal(A, B, C, D) of the quads qi in [qb, qe) between two rows of light-view
// points (SoA: lower row xl, yl, zl; upper row xh, yh, zh). On x86-64 with GCC an AVX2 clone is
// chosen at load time where the CPU has it: the loop vectorises 4-wide there (2-wide SSE2 does
// not pay). The clone enables AVX2 only, not FMA, so it evaluates the same IEEE operations in the
// same order as the scalar code: the same flips on every machine.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
__attribute__((target_clones("avx2", "default")))
#endif
void flipRow(int qb, int qe, const double* __restrict xl, const double* __restrict yl, const double* __restrict zl,
             const double* __restrict xh, const double* __restrict yh, const double* __restrict zh,
             std::uint8_t* __restrict flip) {
  for (int qi = qb; qi < qe; ++qi)
    flip[qi] = flipDiagonal({xl[qi], yl[qi], zl[qi]}, {xl[qi + 1], yl[qi + 1], zl[qi + 1]},
                            {xh[qi + 1], yh[qi + 1], zh[qi + 1]}, {xh[qi], yh[qi], zh[qi]});
}

// The interior texels of a row whose stored depth is short of the far plane lie in [b, e): the
// first and last such texel (b = w - 1, e = 1 when there is none).
std::pair<int, int> shortSpan(const std::uint8_t* shortOfFar, int w) {
  int b = w - 1, e = 1;
  if (const void* p = std::memchr(shortOfFar + 1, 1, std::size_t(w - 2))) {
    b = int(static_cast<const std::uint8_t*>(p) - shortOfFar);
#if defined(__GLIBC__)
    e = 1 + int(static_cast<const std::uint8_t*>(memrchr(shortOfFar + 1, 1, std::size_t(w - 2))) - shortOfFar);
#else
    e = w - 1;
    while (!shortOfFar[e - 1]) --e;
#endif
  }
  return {b, e};
}

}  // namespace

bool QuadGrid::neighbourKept(int qi, int qj, int t, int k) const {
  const bool flip = (at(qi, qj) & kFlip) != 0;
  if (!flip) {
    if (t == 0) {  // A B D
      if (k == 0) return kept(qi, qj - 1, 1);
      if (k == 1) return kept(qi, qj, 1);
      return kept(qi - 1, qj, rightTri(qi - 1, qj));
    }
    // B C D
    if (k == 0) return kept(qi + 1, qj, leftTri(qi + 1, qj));
    if (k == 1) return kept(qi, qj + 1, 0);
    return kept(qi, qj, 0);
  }
  if (t == 0) {  // A B C
    if (k == 0) return kept(qi, qj - 1, 1);
    if (k == 1) return kept(qi + 1, qj, leftTri(qi + 1, qj));
    return kept(qi, qj, 1);
  }
  // A C D
  if (k == 0) return kept(qi, qj, 0);
  if (k == 1) return kept(qi, qj + 1, 0);
  return kept(qi - 1, qj, rightTri(qi - 1, qj));
}

QuadCodes computeQuadCodes(const SheetDepths& sheet, const GridUnprojector& unproject, const QuadCodeOptions& options,
                           Scratch<std::uint8_t>& code) {
  const DepthMap& map = sheet.map();
  const SheetDepthRule& rule = sheet.rule();
  const int w = map.width, h = map.height, qw = w - 1, qh = h - 1;
  const bool exact = options.exact, perfect = options.perfect;
  const double farPlane = rule.farPlane;
  sizeBuffer(code, std::size_t(qw) * qh);
  QuadCodes result;
  result.rowSpan.resize(qh);
  std::vector<std::uint32_t> rowFlips(qh), rowDropped(qh), rowTris(qh), rowRefined(qh, 0);
  // codeFor[flip][far mask of the corners A B C D as bits 0..3]: the whole code byte.
  std::uint8_t codeFor[2][16];
  for (int f = 0; f < 2; ++f)
    for (int m = 0; m < 16; ++m) {
      std::uint8_t q = std::uint8_t(f);
      for (int t = 0; t < 2; ++t) {
        const int* cs = kTriCorners[f][t];
        const bool allFar = (m >> cs[0] & 1) && (m >> cs[1] & 1) && (m >> cs[2] & 1);
        if (!exact || !allFar) q |= keepBit(t);
      }
      codeFor[f][m] = std::uint8_t(q | kCornerUsed[q] << kUsedShift);
    }
  const std::uint32_t farSnapBits = floatBitsAtOrAbove(rule.farSnap);  // stored d < farSnap: bits < these
  std::atomic<bool> badTexel{false};  // a NaN or negative stored depth: validateDepths names it

  tbb::parallel_for(tbb::blocked_range<int>(0, qh, 8), [&](const tbb::blocked_range<int>& rows) {
    // Per texel row: sheet depths, far flags, the span of non-far texels and (perfect only) the
    // light-view points, unprojected only over the columns some non-all-far quad needs.
    struct Row {
      std::vector<double> depth, x, y, z;
      std::vector<std::uint8_t> far;
      int j = -1;
      int first = 0, last = -1;  // non-far texels lie in [first, last]
      int pBegin = 0, pEnd = 0;  // points computed on [pBegin, pEnd)
      int dBegin = 0, dEnd = 0;  // depths written on [dBegin, dEnd) (far elsewhere)
    };
    Row lo, hi;
    for (Row* r : {&lo, &hi}) {
      r->depth.resize(w);
      r->far.resize(w);
      if (perfect) r->x.resize(w), r->y.resize(w), r->z.resize(w);
    }
    std::vector<std::uint8_t> flip(perfect ? qw : 0);
    std::vector<std::uint8_t> shortOfFar(w);  // stored depth short of the far plane (scanDepthRow)
    bool bad = false;
    auto fillRow = [&](int j, Row& r) {
      r.j = j;
      r.pBegin = r.pEnd = 0;
      double* d = r.depth.data();
      std::uint8_t* far = r.far.data();
      const float* src = map.depth.data() + std::size_t(j) * w;
      // Every stored depth is checked (a materialised grid was checked when it was made).
      if (!sheet.materialised()) bad |= scanDepthRow(src, shortOfFar.data(), w, farSnapBits);
      if (sheet.materialised() || j == 0 || j == h - 1) {
        sheet.row(j, d, bad);
        farFlags(d, far, w, farPlane);
        r.dBegin = 0, r.dEnd = w;
      } else {
        // Depths only where a stored depth is short of the far plane; every other texel is far.
        const auto [b, e] = shortSpan(shortOfFar.data(), w);
        std::memset(far, 1, std::size_t(w));
        if (b < e) {
          sheetDepthSpan(src, d, b, e, rule);
          farFlags(d + b, far + b, e - b, farPlane);
        }
        r.dBegin = b, r.dEnd = e;
      }
      std::tie(r.first, r.last) = nearSpan(far, w);
    };
    auto points = [&](Row& r, int b, int e) {  // make the points of [b, e) available
      if (b < r.dBegin) std::fill(r.depth.begin() + b, r.depth.begin() + r.dBegin, farPlane), r.dBegin = b;
      if (e > r.dEnd) std::fill(r.depth.begin() + r.dEnd, r.depth.begin() + e, farPlane), r.dEnd = e;
      if (r.pEnd <= r.pBegin) r.pBegin = r.pEnd = b;
      if (b < r.pBegin) unproject.lightViewPoints(r.j, b, r.pBegin, r.depth.data(), r.x.data(), r.y.data(), r.z.data());
      if (e > r.pEnd) unproject.lightViewPoints(r.j, r.pEnd, e, r.depth.data(), r.x.data(), r.y.data(), r.z.data());
      r.pBegin = std::min(r.pBegin, b), r.pEnd = std::max(r.pEnd, e);
    };
    fillRow(rows.begin(), hi);
    for (int qj = rows.begin(); qj != rows.end(); ++qj) {
      std::swap(lo, hi);
      fillRow(qj + 1, hi);
      std::uint8_t* out = code.data() + std::size_t(qj) * qw;
      // Quads with a non-far corner: [qb, qe). With the quad cap every quad is kept.
      int qb = 0, qe = qw;
      if (exact) {
        qb = std::max(0, std::min(lo.first, hi.first) - 1);
        qe = std::min(qw, std::max(lo.last, hi.last) + 1);
      }
      if (perfect && qb < qe) {
        points(lo, qb, qe + 1);
        points(hi, qb, qe + 1);
        flipRow(qb, qe, lo.x.data(), lo.y.data(), lo.z.data(), hi.x.data(), hi.y.data(), hi.z.data(), flip.data());
      }
      std::fill(out, out + std::max(qb, 0), std::uint8_t(0));
      if (qe > qb) std::fill(out + qe, out + qw, std::uint8_t(0));
      else std::fill(out, out + qw, std::uint8_t(0));
      std::uint32_t flips = 0, dropped = qw - std::max(qe - qb, 0), tris = 0;
      const std::uint8_t* farLo = lo.far.data();
      const std::uint8_t* farHi = hi.far.data();
      for (int qi = qb; qi < qe; ++qi) {
        const int farMask = farLo[qi] | farLo[qi + 1] << 1 | farHi[qi + 1] << 2 | farHi[qi] << 3;
        const int f = perfect ? flip[qi] : 0;
        const std::uint8_t q = (exact && farMask == 15) ? std::uint8_t(0) : codeFor[f][farMask];
        flips += q & kFlip;
        dropped += (q & (kKeep0 | kKeep1)) == 0;
        tris += ((q & kKeep0) != 0) + ((q & kKeep1) != 0);
        out[qi] = q;
      }
      int spanB = qb < qe ? qb : qw, spanE = qb < qe ? qe : 0;
      if (options.splitBits) {
        // Quads with a boundary side (always in [qb, qe)); hidden quads may be anywhere.
        const int mb = options.hiddenQuads ? 0 : qb, me = options.hiddenQuads ? qw : qe;
        const std::uint8_t* lower = options.splitBits + std::size_t(qj) * w;
        const std::uint8_t* upper = lower + w;
        std::uint32_t refined = 0;
        for (int qi = mb; qi < me; ++qi) {
          if (!((lower[qi] & (3 | kHiddenQuadBit)) | (lower[qi + 1] & 2) | (upper[qi] & 1))) continue;
          spanB = std::min(spanB, qi), spanE = std::max(spanE, qi + 1);
          const std::uint8_t q = out[qi];
          const int nonFar = 15 & ~(farLo[qi] | farLo[qi + 1] << 1 | farHi[qi + 1] << 2 | farHi[qi] << 3);
          flips -= q & kFlip;
          dropped -= (q & (kKeep0 | kKeep1)) == 0;
          tris -= ((q & kKeep0) != 0) + ((q & kKeep1) != 0);
          out[qi] = std::uint8_t(kRefined | nonFar << kUsedShift);
          ++refined;
        }
        rowRefined[qj] = refined;
      }
      rowFlips[qj] = flips;
      rowDropped[qj] = dropped;
      rowTris[qj] = tris;
      result.rowSpan[qj] = spanB < spanE ? std::pair<int, int>{spanB, spanE} : std::pair<int, int>{0, 0};
    }
    if (bad) badTexel.store(true, std::memory_order_relaxed);
  });
  if (badTexel.load()) validateDepths(map);  // throws, naming the first bad texel
  result.rowTriOffset.assign(std::size_t(qh) + 1, 0);
  for (int qj = 0; qj < qh; ++qj) {
    result.flipped += rowFlips[qj];
    result.dropped += rowDropped[qj];
    result.refined += rowRefined[qj];
    result.rowTriOffset[qj + 1] = result.rowTriOffset[qj] + rowTris[qj];
  }
  return result;
}

}  // namespace shadowvol::volume

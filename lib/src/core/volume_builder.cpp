#include "shadowvol/volume_builder.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <string.h>  // memrchr
#include <limits>
#include <memory>
#include <sstream>
#include <tuple>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/vec4.hpp>
#if defined(__linux__)
#include <sys/mman.h>
#endif
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include "shadowvol/check.h"
#include "shadowvol/default_init_allocator.h"
#include "shadowvol/depth_blur.h"
#include "shadowvol/error.h"
#include "shadowvol/far_cap.h"

namespace shadowvol {

const char* toString(FarCap c) { return c == FarCap::Exact ? "exact" : "quad"; }

bool parseFarCap(const std::string& text, FarCap& c) {
  if (text == "exact") c = FarCap::Exact;
  else if (text == "quad") c = FarCap::Quad;
  else return false;
  return true;
}

namespace {

// defaultBias from the map's metadata: light view and projection, size, far plane, capture.
double defaultBiasOf(const glm::dmat4& view, const glm::dmat4& projection, int width, int height, double farPlane,
                     CaptureMode capture) {
  if (capture != CaptureMode::Front) return 0.0;
  // Texel footprint at the far plane (the largest over the map for a spot light; constant for a
  // directional one): the depth change across one texel of a receiver tilted 45 degrees.
  const TexelUnprojector unproject(view, projection, width, height);
  const double w2 = 0.5 * (width - 1), h2 = 0.5 * (height - 1);
  const glm::dvec3 c = unproject.lightViewPoint(w2, h2, farPlane);
  const double footprint = std::max(glm::length(unproject.lightViewPoint(w2 + 1.0, h2, farPlane) - c),
                                    glm::length(unproject.lightViewPoint(w2, h2 + 1.0, farPlane) - c));
  // Float depth precision: 4 ulps of a float at the far plane (2^-23 relative per ulp).
  const double precision = 4.0 * farPlane * std::ldexp(1.0, -23);
  return footprint + precision;
}

}  // namespace

double defaultBias(const DepthMap& map) {
  return defaultBiasOf(map.lightView, map.lightProjection, map.width, map.height, map.farPlane, map.capture);
}

double defaultBias(const Light& light, int width, int height, CaptureMode capture) {
  return defaultBiasOf(lightView(light), lightProjection(light, double(width) / double(height)), width, height,
                       light.farPlane, capture);
}

namespace {

using Clock = std::chrono::steady_clock;
using Tri = std::array<std::uint32_t, 3>;
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// Per-quad code: the diagonal and which of its two triangles the mesh keeps.
constexpr std::uint8_t kFlip = 1, kKeep0 = 2, kKeep1 = 4;
constexpr std::uint8_t keepBit(int t) { return t == 0 ? kKeep0 : kKeep1; }

// Corners 0..3 = A (i, j), B (i + 1, j), C (i + 1, j + 1), D (i, j + 1) of quad (i, j).
constexpr int kCornerDi[4] = {0, 1, 1, 0};
constexpr int kCornerDj[4] = {0, 0, 1, 1};
// kTriCorners[flip][t]: fixed (B-D): ABD, BCD; flipped (A-C): ABC, ACD (triangulation.h).
constexpr int kTriCorners[2][2][3] = {{{0, 1, 3}, {1, 2, 3}}, {{0, 1, 2}, {0, 2, 3}}};

// Per quad code (its low 3 bits), as 4-bit masks over the corners: kCornerUsed = held by a kept
// triangle; kCornerCovered = every triangle of the quad holding it is kept.
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
constexpr CornerTables kCornerTables;
// The code byte also holds kCornerUsed (of its low bits) in bits 3..6, so that a texel's use is
// four masked loads: A of quad (i, j), B of (i - 1, j), C of (i - 1, j - 1), D of (i, j - 1).
constexpr int kUsedShift = 3;
constexpr std::uint8_t kUsedA = 1 << kUsedShift, kUsedB = 2 << kUsedShift, kUsedC = 4 << kUsedShift,
                       kUsedD = 8 << kUsedShift;
constexpr const std::uint8_t* kCornerUsed = kCornerTables.used;
constexpr const std::uint8_t* kCornerCovered = kCornerTables.covered;

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

  // Is the triangle across edge k (from corner k to corner k + 1) of triangle t of quad (qi, qj) kept?
  bool neighbourKept(int qi, int qj, int t, int k) const {
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
};

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

// In place, for i in [b, e): (x, y, z)[i] = m * (x, y, z, 1)[i], with glm's operation order for
// mat4 * vec4 ((m0 x + m1 y) + (m2 z + m3)), so the result equals glm's to the bit. Clones as flipRow.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
__attribute__((target_clones("avx2", "default")))
#endif
void transformRow(const glm::dmat4& m, int b, int e, double* __restrict x, double* __restrict y, double* __restrict z) {
  const double m00 = m[0][0], m01 = m[0][1], m02 = m[0][2], m10 = m[1][0], m11 = m[1][1], m12 = m[1][2];
  const double m20 = m[2][0], m21 = m[2][1], m22 = m[2][2], m30 = m[3][0], m31 = m[3][1], m32 = m[3][2];
  for (int i = b; i < e; ++i) {
    const double lx = x[i], ly = y[i], lz = z[i];
    x[i] = (m00 * lx + m10 * ly) + (m20 * lz + m30 * 1.0);
    y[i] = (m01 * lx + m11 * ly) + (m21 * lz + m31 * 1.0);
    z[i] = (m02 * lx + m12 * ly) + (m22 * lz + m32 * 1.0);
  }
}

// Row kernels of the builder, as free functions with restrict pointers and loop bounds by value:
// inside the builder's lambdas a byte store may alias the captured sizes, which stops the
// compiler from vectorising.

// Sheet depths (steps 1 and 3 of volume_builder.h, branch-free) of texels [b, e) of one interior
// row from the stored depths src; returns true when a stored depth is NaN or negative.
bool sheetDepthSpan(const float* __restrict src, double* __restrict d, int b, int e, double bias, double nearPlane,
                    double farPlane, double farSnap) {
  bool bad = false;
  for (int i = b; i < e; ++i) {
    const double raw = src[i];
    bad |= !(raw >= 0.0);
    const double c = std::clamp(raw + bias, nearPlane, farPlane);
    d[i] = (raw < farSnap && c < farSnap) ? c : farPlane;
  }
  return bad;
}

// One pass over n stored depths, on their bits (integer compares vectorise; float compares do not
// under GCC's default trapping-math): below[i] = 1 where the depth is less than the float whose
// bits are `limit` (for valid depths, which are >= 0 or +inf, the order of the magnitude bits is
// the order of the values; -0 counts as 0); returns true when a depth is NaN or negative
// (rejected by buildVolume).
bool scanDepthRow(const float* __restrict src, std::uint8_t* __restrict below, int n, std::uint32_t limit) {
  std::uint32_t bad = 0;
  for (int i = 0; i < n; ++i) {
    std::uint32_t u;
    std::memcpy(&u, src + i, sizeof u);
    bad |= std::uint32_t(u > 0x7F800000u) & std::uint32_t(u != 0x80000000u);  // NaN or < -0
    below[i] = (u & 0x7FFFFFFFu) < limit;
  }
  return bad != 0;
}

// Bits of the smallest float f with double(f) >= x (x > 0): for every float d, double(d) < x
// exactly when d < f.
std::uint32_t floatBitsAtOrAbove(double x) {
  float f = float(x);
  if (double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  std::uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

// far[i] = (d[i] == farPlane) for i in [0, n), compared as bits (the same for these values: d is
// never NaN and farPlane > 0; integer compares vectorise, double ones do not under trapping math;
// 64-bit integer compares need more than SSE2, hence the AVX2 clone as for flipRow).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
__attribute__((target_clones("avx2", "default")))
#endif
void farFlags(const double* __restrict d, std::uint8_t* __restrict far, int n, double farPlane) {
  std::uint64_t farBits;
  std::memcpy(&farBits, &farPlane, sizeof farBits);
  for (int i = 0; i < n; ++i) {
    std::uint64_t u;
    std::memcpy(&u, d + i, sizeof u);
    far[i] = u == farBits;
  }
}

// The first and last i in [0, n) with far[i] == 0 (n and -1 when there is none).
std::pair<int, int> nearSpan(const std::uint8_t* far, int n) {
  const void* first = std::memchr(far, 0, std::size_t(n));
  if (!first) return {n, -1};
#if defined(__GLIBC__)
  const void* last = memrchr(far, 0, std::size_t(n));
#else
  const std::uint8_t* last = far + n - 1;
  while (*last) --last;
#endif
  return {int(static_cast<const std::uint8_t*>(first) - far), int(static_cast<const std::uint8_t*>(last) - far)};
}

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

// Vertex indices of n texels: consecutive from `first` for used ones, `none` for the others;
// returns the next free index.
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

// GridUnprojector's separable projection terms, by value for the row loop below.
struct SeparableProjection {
  double p20, p21, p30, p31, p23, p33, inv00, inv11;
};

// Light-view points of texels [b, e) of one row (normalised x per column, y of the row) at
// light-view depths d, into x, y, z. A free function with restrict pointers and the terms by
// value: as a member loop every store might alias the members, and nothing vectorised. Clones as
// flipRow.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
__attribute__((target_clones("avx2", "default")))
#endif
void lightViewRow(const double* __restrict xn, double yn, int b, int e, const double* __restrict d, double* __restrict x,
                  double* __restrict y, double* __restrict z, SeparableProjection p) {
  for (int i = b; i < e; ++i) {
    const double zi = -d[i], wc = p.p23 * zi + p.p33;
    x[i] = (xn[i] * wc - p.p20 * zi - p.p30) * p.inv00;
    y[i] = (yn * wc - p.p21 * zi - p.p31) * p.inv11;
    z[i] = zi;
  }
}

// Texel-centre unprojection for whole grids: TexelUnprojector's result, with the projection solved
// per axis when the matrix allows it (glm's perspective and orthographic matrices: x and y do not
// mix, clip w depends on view z only), else TexelUnprojector itself. Agrees with it to a few ulps
// (it multiplies by 1 / P00 and 1 / P11 instead of dividing: divisions were a tenth of the build).
class GridUnprojector {
 public:
  explicit GridUnprojector(const DepthMap& map) : reference_(map) {
    const glm::dmat4& p = map.lightProjection;  // column-major: p[col][row]
    separable_ = p[1][0] == 0.0 && p[0][1] == 0.0 && p[0][3] == 0.0 && p[1][3] == 0.0 && p[0][0] != 0.0 &&
                 p[1][1] != 0.0;
    p00_ = p[0][0], p11_ = p[1][1], p20_ = p[2][0], p21_ = p[2][1], p30_ = p[3][0], p31_ = p[3][1];
    p23_ = p[2][3], p33_ = p[3][3];
    inv00_ = 1.0 / p00_, inv11_ = 1.0 / p11_;
    xn_.resize(std::size_t(map.width));
    yn_.resize(std::size_t(map.height));
    for (int i = 0; i < map.width; ++i) xn_[std::size_t(i)] = (i + 0.5) / double(map.width) * 2.0 - 1.0;
    for (int j = 0; j < map.height; ++j) yn_[std::size_t(j)] = (j + 0.5) / double(map.height) * 2.0 - 1.0;
    const glm::dmat4 inv = glm::inverse(map.lightView);
    invView_ = inv;
  }
  glm::dvec3 lightViewPoint(int i, int j, double d) const {
    if (!separable_) return reference_.lightViewPoint(i, j, d);
    const double z = -d, wc = p23_ * z + p33_;
    return {(xn_[std::size_t(i)] * wc - p20_ * z - p30_) * inv00_, (yn_[std::size_t(j)] * wc - p21_ * z - p31_) * inv11_,
            z};
  }
  // lightViewPoint(i, j, d[i]) for i in [begin, end), into x, y, z (a loop that vectorises).
  void lightViewPoints(int j, int begin, int end, const double* d, double* x, double* y, double* z) const {
    if (!separable_)
      return perTexel(j, begin, end, d, x, y, z, [&](int i, double di) { return reference_.lightViewPoint(i, j, di); });
    lightViewRow(xn_.data(), yn_[std::size_t(j)], begin, end, d, x, y, z, {p20_, p21_, p30_, p31_, p23_, p33_, inv00_, inv11_});
  }
  // worldPoint(i, j, d[i]) for i in [begin, end), into x, y, z.
  void worldPoints(int j, int begin, int end, const double* d, double* x, double* y, double* z) const {
    if (!separable_)
      return perTexel(j, begin, end, d, x, y, z, [&](int i, double di) { return reference_.worldPoint(i, j, di); });
    lightViewPoints(j, begin, end, d, x, y, z);
    transformRow(invView_, begin, end, x, y, z);
  }
  glm::dvec3 worldPoint(int i, int j, double d) const {
    if (!separable_) return reference_.worldPoint(i, j, d);
    return glm::dvec3(invView_ * glm::dvec4(lightViewPoint(i, j, d), 1.0));
  }

 private:
  // The non-separable fallback: point(i, d[i]) one texel at a time, into x, y, z.
  template <class Point>
  static void perTexel(int, int begin, int end, const double* d, double* x, double* y, double* z, Point point) {
    for (int i = begin; i < end; ++i) {
      const glm::dvec3 p = point(i, d[i]);
      x[i] = p.x, y[i] = p.y, z[i] = p.z;
    }
  }

  TexelUnprojector reference_;
  bool separable_ = false;
  double p00_, p11_, p20_, p21_, p30_, p31_, p23_, p33_, inv00_, inv11_;
  std::vector<double> xn_, yn_;
  glm::dmat4 invView_;
};

// Sizes a buffer to n elements with room for `capacity`. When it must grow, the old contents are
// dropped (never copied) and Linux is asked for transparent huge pages before the first touch:
// at 1024^2 the 4 KiB page faults of fresh buffers cost about as much as the build itself. Only a
// hint (no effect where THP is off or on other systems). Contents as resize(n): left unwritten for
// a DefaultInitAllocator vector (Scratch, VolumeMesh), so the first touch, and its page faults,
// happen in the parallel pass that fills it; a buffer reused by VolumeBuilder has no faults.
template <class V>
void sizeBuffer(V& v, std::size_t n, std::size_t capacity = 0) {
  using T = typename V::value_type;
  capacity = std::max(capacity, n);
  if (v.capacity() < capacity) {
    V fresh;
    fresh.reserve(capacity);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    constexpr std::uintptr_t kHuge = std::uintptr_t(2) << 20;
    if (capacity * sizeof(T) >= 2 * kHuge) {
      const auto begin = (reinterpret_cast<std::uintptr_t>(fresh.data()) + kHuge - 1) & ~(kHuge - 1);
      const auto end = (reinterpret_cast<std::uintptr_t>(fresh.data()) + fresh.capacity() * sizeof(T)) & ~(kHuge - 1);
      if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
    }
#endif
    v.swap(fresh);
  }
  v.resize(n);
}

// Grid-sized scratch that every pass overwrites in full before reading: no zero-fill.
template <class T>
using Scratch = std::vector<T, DefaultInitAllocator<T>>;

// Cheap checks of the map's metadata and of the options, before anything else.
void validateMapAndOptions(const DepthMap& map, const VolumeBuildOptions& options) {
  SV_CHECK_GT(map.width, 0);
  SV_CHECK_GT(map.height, 0);
  SV_CHECK_EQ(map.depth.size(), std::size_t(map.width) * std::size_t(map.height));
  SV_CHECK_GT(map.farPlane, map.nearPlane);
  SV_CHECK_GE(map.nearPlane, 0.0);
  auto finite = [](const char* name, double v) {
    if (!std::isfinite(v)) {
      std::ostringstream value;
      value << v;
      throw InputError("volume options", name, value.str(), "must be a finite number of world units");
    }
  };
  finite("blur offset", options.blurOffset);
  if (options.bias) finite("bias", *options.bias);
}

// Throws InputError naming the first texel (row-major from texel (0, 0)) holding NaN or a
// negative depth. The builder's passes flag such texels as they read them and call this only then.
void validateDepths(const DepthMap& map) {
  for (int j = 0; j < map.height; ++j)
    for (int i = 0; i < map.width; ++i) {
      const float d = map.at(i, j);
      if (std::isnan(d) || d < 0.0f) {
        std::ostringstream field, value;
        field << "depth of texel (" << i << ", " << j << ")";
        value << d;
        throw InputError("depth map", field.str(), value.str(),
                         "depths must be non-negative light-view distances (world units) or +inf for no hit");
      }
    }
}

}  // namespace

// Grid-sized scratch kept by a VolumeBuilder between builds.
struct VolumeBuilder::Scratch {
  shadowvol::Scratch<double> blurred;
  shadowvol::Scratch<std::uint8_t> code;
  shadowvol::Scratch<std::uint32_t> quadTri;
};

VolumeBuilder::VolumeBuilder() : scratch_(std::make_unique<Scratch>()) {}
VolumeBuilder::~VolumeBuilder() = default;
VolumeBuilder::VolumeBuilder(VolumeBuilder&&) noexcept = default;
VolumeBuilder& VolumeBuilder::operator=(VolumeBuilder&&) noexcept = default;

VolumeBuildResult buildVolume(const DepthMap& map, const VolumeBuildOptions& options) {
  VolumeBuilder builder;
  VolumeBuildResult result;
  builder.build(map, options, result);
  return result;
}

void VolumeBuilder::build(const DepthMap& map, const VolumeBuildOptions& options, VolumeBuildResult& result) {
  result.mesh.positions.clear();
  result.mesh.triangles.clear();
  result.stats = {};
  try {
    buildInto(map, options, result);
  } catch (...) {
    result.mesh.positions.clear();
    result.mesh.triangles.clear();
    result.stats = {};
    throw;
  }
}

void VolumeBuilder::buildInto(const DepthMap& map, const VolumeBuildOptions& options, VolumeBuildResult& result) {
  const auto tStart = Clock::now();
  validateMapAndOptions(map, options);
  VolumeBuildStats& stats = result.stats;
  const double bias = options.bias.value_or(defaultBias(map));
  stats.biasUsed = bias;

  const int w = map.width, h = map.height;
  if (w < 2 || h < 2) {
    validateDepths(map);
    stats.msTotal = msSince(tStart);
    return;  // no quad: an empty volume
  }
  const int qw = w - 1, qh = h - 1;
  const std::size_t texels = std::size_t(w) * h, quadCount = std::size_t(qw) * qh;
  SV_CHECK_LT(3 * std::uint64_t(texels), std::uint64_t(kNone));  // sheet + pinch copies + cap vertices
  stats.quads = quadCount;
  const double farPlane = map.farPlane, nearPlane = map.nearPlane;
  const bool exact = options.cap == FarCap::Exact;
  const bool perfect = options.triangulation == Triangulation::Perfect;
  // Set when a texel holds NaN or a negative depth; validateDepths then names the first one.
  std::atomic<bool> badTexel{false};

  // Sheet depth of texel (i, j) without blur (steps 1 and 3 of volume_builder.h) from its stored
  // depth `raw`, one texel at a time (the row loops use sheetDepthSpan, which gives the same values).
  auto sheetDepth = [&](int i, int j, double raw) {
    if (i == 0 || j == 0 || i == w - 1 || j == h - 1 || isFarDepth(raw, farPlane)) return farPlane;
    const double d = std::clamp(raw + bias, nearPlane, farPlane);
    return isFarDepth(d, farPlane) ? farPlane : d;
  };

  // --- Blur (only with options.blur): every texel's sheet depth, once, in double. Without blur
  // the sheet depth is cheap and computed where it is needed (no grid-sized scratch). ---
  auto t0 = Clock::now();
  auto& blurred = scratch_->blurred;
  if (options.blur) {
    sizeBuffer(blurred, texels);
    tbb::parallel_for(tbb::blocked_range<int>(0, h, 8), [&](const tbb::blocked_range<int>& rows) {
      bool bad = false;
      BlurRowScratch scratch;
      std::vector<double> row(w);
      std::vector<std::uint8_t> below(w);
      for (int j = rows.begin(); j != rows.end(); ++j) {
        const float* src = map.depth.data() + std::size_t(j) * w;
        bad |= scanDepthRow(src, below.data(), w, floatBitsAtOrAbove(farPlane * (1.0 - kFarSnap)));
        double* out = blurred.data() + std::size_t(j) * w;
        if (j == 0 || j == h - 1) {
          std::fill_n(out, w, farPlane);
          continue;
        }
        // blurredDepth of the valid texels, between the first and last (the others are far).
        int b = w, e = 0;
        if (const void* p = std::memchr(below.data(), 1, std::size_t(w))) {
          b = int(static_cast<const std::uint8_t*>(p) - below.data());
          e = w;
          while (!below[e - 1]) --e;
          blurRow(map, j, row.data(), scratch, b, e);
        }
        for (int i = 0; i < w; ++i) {
          double d = farPlane;
          if (!(i == 0 || i == w - 1 || i < b || i >= e || isFarDepth(src[i], farPlane))) {
            d = std::clamp(row[i] + options.blurOffset + bias, nearPlane, farPlane);
            if (isFarDepth(d, farPlane)) d = farPlane;
          }
          out[i] = d;
        }
      }
      if (bad) badTexel.store(true, std::memory_order_relaxed);
    });
    if (badTexel.load()) validateDepths(map);  // throws, naming the first bad texel
  }
  if (options.blur) stats.msBlur = msSince(t0);
  auto depthAt = [&](int i, int j) {
    const std::size_t t = std::size_t(j) * w + i;
    return options.blur ? blurred[t] : sheetDepth(i, j, map.depth[t]);
  };

  // --- Pass A: per quad, the diagonal and which triangles are kept (one code byte). Two rolling
  // rows of depths (and of light-view points for the perfect rule) per task, not per quad. ---
  t0 = Clock::now();
  const GridUnprojector unproject(map);
  auto& code = scratch_->code;
  sizeBuffer(code, quadCount);
  std::vector<std::uint32_t> rowFlips(qh), rowDropped(qh), rowTris(qh + 1, 0);
  std::vector<std::pair<int, int>> rowSpan(qh);  // per quad row: no nonzero code outside [first, second)
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
  const double farSnap = farPlane * (1.0 - kFarSnap);  // isFarDepth(d) == !(d < farSnap)
  const std::uint32_t farSnapBits = floatBitsAtOrAbove(farSnap);  // stored d < farSnap: bits < these
  // Sheet depths of texel row j (steps 1-3 of volume_builder.h) into d[0, w); `bad` is set when
  // a stored depth is NaN or negative. Branch-free: the same values as sheetDepth.
  // Sheet depths of texels [b, e) of row j (steps 1-3 of volume_builder.h) into d; `bad` is set
  // when a stored depth is NaN or negative. The same values as sheetDepth.
  auto sheetDepthRow = [&](int j, double* d, bool& bad, int b = 0, int e = -1) {
    if (e < 0) e = w;
    const std::size_t row = std::size_t(j) * w;
    if (j == 0 || j == h - 1) {
      std::fill(d + b, d + e, farPlane);
    } else if (options.blur) {
      std::copy(blurred.begin() + std::ptrdiff_t(row + b), blurred.begin() + std::ptrdiff_t(row + e), d + b);
    } else {
      bad |= sheetDepthSpan(map.depth.data() + row, d, b, e, bias, nearPlane, farPlane, farSnap);
      d[0] = d[w - 1] = farPlane;  // the ring (outside [b, e) is never read)
    }
  };
  tbb::parallel_for(tbb::blocked_range<int>(0, qh, 8), [&](const tbb::blocked_range<int>& rows) {
    // Per texel row: sheet depths, far flags, the span of non-far texels and (perfect only) the
    // light-view points, unprojected only over the columns some non-all-far quad needs.
    struct Row {
      std::vector<double> depth, x, y, z;
      std::vector<std::uint8_t> far;
      int j = -1;
      int first = 0, last = -1;     // non-far texels lie in [first, last]
      int pBegin = 0, pEnd = 0;     // points computed on [pBegin, pEnd)
      int dBegin = 0, dEnd = 0;     // depths written on [dBegin, dEnd) (far elsewhere)
    };
    Row lo, hi;
    for (Row* r : {&lo, &hi}) {
      r->depth.resize(w);
      r->far.resize(w);
      if (perfect) r->x.resize(w), r->y.resize(w), r->z.resize(w);
    }
    std::vector<std::uint8_t> flip(perfect ? qw : 0);
    std::vector<std::uint8_t> short_(w);  // stored depth short of the far plane (scanDepthRow)
    bool bad = false;
    auto fillRow = [&](int j, Row& r) {
      r.j = j;
      r.pBegin = r.pEnd = 0;
      double* d = r.depth.data();
      std::uint8_t* far = r.far.data();
      const float* src = map.depth.data() + std::size_t(j) * w;
      // Every stored depth is checked (the blur pass checks its own).
      if (!options.blur) bad |= scanDepthRow(src, short_.data(), w, farSnapBits);
      if (options.blur || j == 0 || j == h - 1) {
        sheetDepthRow(j, d, bad);
        farFlags(d, far, w, farPlane);
        r.dBegin = 0, r.dEnd = w;
      } else {
        // Depths only where a stored depth is short of the far plane (between the first and last
        // such interior texel); every other texel is far.
        int b = w - 1, e = 1;  // interior texels short of the far plane lie in [b, e)
        if (const void* p = std::memchr(short_.data() + 1, 1, std::size_t(w - 2))) {
          b = int(static_cast<const std::uint8_t*>(p) - short_.data());
#if defined(__GLIBC__)
          e = 1 + int(static_cast<const std::uint8_t*>(memrchr(short_.data() + 1, 1, std::size_t(w - 2))) - short_.data());
#else
          e = w - 1;
          while (!short_[e - 1]) --e;
#endif
        }
        std::memset(far, 1, std::size_t(w));
        if (b < e) {
          sheetDepthSpan(src, d, b, e, bias, nearPlane, farPlane, farSnap);
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
      rowFlips[qj] = flips;
      rowDropped[qj] = dropped;
      rowTris[qj + 1] = tris;
      rowSpan[qj] = qb < qe ? std::pair<int, int>{qb, qe} : std::pair<int, int>{0, 0};
    }
    if (bad) badTexel.store(true, std::memory_order_relaxed);
  });
  if (badTexel.load()) validateDepths(map);  // throws, naming the first bad texel
  const QuadGrid grid{qw, qh, code.data()};
  for (int qj = 0; qj < qh; ++qj) {
    stats.flippedQuads += rowFlips[qj];
    stats.droppedQuads += rowDropped[qj];
  }

  // Vertices: one per texel used by a kept triangle, numbered in texel order. A texel is used when
  // one of its four quads keeps a triangle holding it; its fan is complete when all four quads
  // exist and keep every triangle holding it (a far texel with an incomplete fan is a boundary
  // vertex of the cap).
  auto usedMask = [&](int i, int j) {
    return (grid.at(i, j) & kUsedA) | (grid.at(i - 1, j) & kUsedB) | (grid.at(i - 1, j - 1) & kUsedC) |
           (grid.at(i, j - 1) & kUsedD);
  };
  // usedMask of every texel of row j, nonzero = used (branch-free in the interior).
  const std::vector<std::uint8_t> zeroRow(std::size_t(qw), 0);
  // Texels of row j that can be used: those of the quads spans of the quad rows above and below.
  auto usedSpan = [&](int j) {
    std::pair<int, int> span{w, 0};
    for (int qj : {j - 1, j}) {
      if (qj < 0 || qj >= qh || rowSpan[qj].first >= rowSpan[qj].second) continue;
      span.first = std::min(span.first, rowSpan[qj].first);
      span.second = std::max(span.second, rowSpan[qj].second + 1);
    }
    return span.first < span.second ? span : std::pair<int, int>{0, 0};
  };
  // used[i] for i in the returned span [b, e) (other entries are not written).
  auto usedRow = [&](int j, std::uint8_t* used) {
    const auto span = usedSpan(j);
    if (span.first < span.second) {
      const std::uint8_t* cur = j < qh ? code.data() + std::size_t(j) * qw : zeroRow.data();
      const std::uint8_t* prev = j > 0 ? code.data() + std::size_t(j - 1) * qw : zeroRow.data();
      usedBits(cur, prev, used, qw, span.first, span.second, kUsedA, kUsedB, kUsedC, kUsedD);
    }
    return span;
  };
  auto completeFan = [&](int i, int j) {
    return ((kCornerCovered[grid.at(i, j)] & 1) & (kCornerCovered[grid.at(i - 1, j)] >> 1) &
            (kCornerCovered[grid.at(i - 1, j - 1)] >> 2) & (kCornerCovered[grid.at(i, j - 1)] >> 3)) != 0;
  };
  // A used texel with an incomplete fan is far: a triangle with a non-far corner is always kept,
  // and texels off the border ring have all four quads.
  auto isBoundary = [&](int i, int j) { return usedMask(i, j) != 0 && !completeFan(i, j); };
  // --- Vertex counts per row and the boundary texels (used, with an incomplete fan; all far). ---
  struct Boundary {
    int i = 0;
    std::uint32_t local = 0;  // index among the used texels of its row
  };
  std::vector<std::vector<Boundary>> rowBoundary(h);
  std::vector<std::uint64_t> rowVerts(h + 1, 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 16), [&](const tbb::blocked_range<int>& rows) {
    std::vector<std::uint8_t> used(w), candidate(w);
    for (int j = rows.begin(); j != rows.end(); ++j) {
      const auto [b, e] = usedRow(j, used.data());
      rowVerts[j + 1] = countNonzero(used.data() + b, e - b);
      if (b == e) continue;
      const std::uint8_t* cur = j < qh ? code.data() + std::size_t(j) * qw : zeroRow.data();
      const std::uint8_t* prev = j > 0 ? code.data() + std::size_t(j - 1) * qw : zeroRow.data();
      notAllKept(cur, prev, used.data(), candidate.data(), qw, b, e, kKeep0 | kKeep1);
      std::uint32_t local = 0;
      int counted = b;
      for (int i = b; i < e;) {
        const void* hit = std::memchr(candidate.data() + i, 1, std::size_t(e - i));
        if (!hit) break;
        i = int(static_cast<const std::uint8_t*>(hit) - candidate.data());
        if (!completeFan(i, j)) {
          local += countNonzero(used.data() + counted, i - counted);
          counted = i;
          rowBoundary[j].push_back({i, local});
        }
        ++i;
      }
    }
  });
  for (int j = 0; j < h; ++j) rowVerts[j + 1] += rowVerts[j];
  std::vector<std::uint64_t> rowTriOffset(qh + 1, 0);
  for (int qj = 0; qj < qh; ++qj) rowTriOffset[qj + 1] = rowTriOffset[qj] + rowTris[qj + 1];
  const std::uint64_t sheetTriangles = rowTriOffset[qh];

  const auto tRuns = Clock::now();
  // --- Pinches and cuts, from the codes alone. A far vertex is a boundary vertex when its fan of
  // triangles has a gap (a dropped triangle or the grid border). An edge between two far boundary
  // vertices with kept triangles on both sides (a "slit": the sheet touches the far plane along it)
  // is cut open, so the cap cannot reuse it. Each boundary vertex then gets one vertex per run of
  // its fan between gaps and cuts: regions touching at a point or along a cut are split apart and
  // the closed mesh stays a 2-manifold. Far vertices without a gap stay single (sheet only).
  // Copies are numbered after the sheet's vertices, in texel order, then run order. ---
  struct Slot {
    bool kept;
    std::uint32_t quad;      // quad index
    std::uint8_t t, k;       // triangle of the quad, position of the vertex in it
    std::uint8_t run;        // kept slots: 0 = the original vertex, r = copy r - 1
    std::size_t ccwTexel;    // texel at the far end of the slot's counter-clockwise edge
  };
  struct Fan {
    std::uint32_t id = 0, firstCopy = 0;
    int n = 0;
    Slot slots[8];
  };
  // The up to 6 triangle slots around texel (i, j), counter-clockwise from +i; a missing quad is
  // one gap slot.
  auto collectSlots = [&](int i, int j, Fan& fan) {
    int n = 0;
    const int quads[4][3] = {{i, j, 0}, {i - 1, j, 1}, {i - 1, j - 1, 2}, {i, j - 1, 3}};  // NE, NW, SW, SE
    for (const auto& [qi, qj, corner] : quads) {
      if (qi < 0 || qj < 0 || qi >= qw || qj >= qh) {
        fan.slots[n++] = {false, 0, 0, 0, 0, 0};
        continue;
      }
      const std::size_t qIndex = std::size_t(qj) * qw + qi;
      const std::uint8_t q = code[qIndex];
      const int f = q & kFlip;
      int order[2] = {0, 1};  // counter-clockwise order of the quad's triangles around this corner
      if ((corner == 1 && !f) || (corner == 2 && f)) std::swap(order[0], order[1]);
      for (int t : order) {
        const int* cs = kTriCorners[f][t];
        const int k = cs[0] == corner ? 0 : cs[1] == corner ? 1 : cs[2] == corner ? 2 : -1;
        if (k < 0) continue;
        const int ccw = cs[(k + 2) % 3];
        fan.slots[n++] = {(q & keepBit(t)) != 0, std::uint32_t(qIndex), std::uint8_t(t), std::uint8_t(k), 0,
                          std::size_t(qj + kCornerDj[ccw]) * w + qi + kCornerDi[ccw]};
      }
    }
    fan.n = n;
  };
  auto texelBoundary = [&](std::size_t t) { return isBoundary(int(t % std::size_t(w)), int(t / std::size_t(w))); };
  std::vector<std::vector<Fan>> rowFans(h);
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 32), [&](const tbb::blocked_range<int>& rows) {
    for (int j = rows.begin(); j != rows.end(); ++j) {
      rowFans[j].resize(rowBoundary[j].size());
      for (std::size_t b = 0; b < rowBoundary[j].size(); ++b) {
        Fan& fan = rowFans[j][b];
        collectSlots(rowBoundary[j][b].i, j, fan);
        fan.id = std::uint32_t(rowVerts[j] + rowBoundary[j][b].local);
        int gap = 0;
        while (fan.slots[gap].kept) ++gap;
        int fans = 0;
        for (int s = 1; s <= fan.n; ++s) {
          Slot& slot = fan.slots[(gap + s) % fan.n];
          const Slot& prev = fan.slots[(gap + s - 1) % fan.n];
          if (!slot.kept) continue;
          const bool cut = prev.kept && texelBoundary(prev.ccwTexel);
          if (!prev.kept || cut) ++fans;  // a run starts here
          slot.run = std::uint8_t(fans - 1);
        }
        fan.firstCopy = std::uint32_t(fans - 1);  // the number of copies, until numbered below
      }
    }
  });
  std::uint32_t copies = 0;
  for (auto& fans : rowFans)
    for (Fan& fan : fans) {
      const std::uint32_t n = fan.firstCopy;
      fan.firstCopy = std::uint32_t(rowVerts[h]) + copies;
      copies += n;
    }
  stats.splitVertices = copies;
  auto fanAt = [&](int i, int j) -> const Fan& {
    const auto& list = rowBoundary[j];
    const auto it = std::lower_bound(list.begin(), list.end(), i, [](const Boundary& b, int x) { return b.i < x; });
    SV_CHECK(it != list.end() && it->i == i);
    return rowFans[j][std::size_t(it - list.begin())];
  };
  auto slotId = [](const Fan& fan, const Slot& slot) { return slot.run == 0 ? fan.id : fan.firstCopy + slot.run - 1u; };

  // Cap edges: the edges of kept triangles between two far vertices with no kept triangle across
  // (or cut open). Both ends are boundary vertices, so the edges are found from the boundary
  // fans, each once, from its first vertex; then put in (quad, triangle, edge) order.
  std::vector<std::vector<std::pair<std::uint64_t, CapEdge>>> rowKeyed(h);
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 32), [&](const tbb::blocked_range<int>& rows) {
    for (int j0 = rows.begin(); j0 != rows.end(); ++j0)
      for (std::size_t b = 0; b < rowBoundary[j0].size(); ++b) {
        const int i0 = rowBoundary[j0][b].i;
        const Fan& fan = rowFans[j0][b];
        for (int s = 0; s < fan.n; ++s) {
          const Slot& slot = fan.slots[s];
          if (!slot.kept) continue;
          const int qi = int(slot.quad % std::uint32_t(qw)), qj = int(slot.quad / std::uint32_t(qw));
          const int* cs = kTriCorners[code[slot.quad] & kFlip][slot.t];
          const int c1 = cs[(slot.k + 1) % 3];
          const int i1 = qi + kCornerDi[c1], j1 = qj + kCornerDj[c1];
          if (depthAt(i1, j1) != farPlane) continue;
          const bool cut = isBoundary(i1, j1);
          if (!cut && grid.neighbourKept(qi, qj, slot.t, slot.k)) continue;
          const Fan& other = fanAt(i1, j1);  // the same triangle, at its next corner
          const Slot* end = nullptr;
          for (int o = 0; o < other.n && !end; ++o)
            if (other.slots[o].kept && other.slots[o].quad == slot.quad && other.slots[o].t == slot.t) end = &other.slots[o];
          SV_CHECK(end != nullptr);
          rowKeyed[j0].push_back({(std::uint64_t(slot.quad) * 2 + slot.t) * 3 + slot.k,
                                  {slotId(fan, slot), slotId(other, *end), {i0, j0}, {i1, j1}}});
        }
      }
  });
  std::vector<std::pair<std::uint64_t, CapEdge>> keyed;
  for (auto& row : rowKeyed) keyed.insert(keyed.end(), row.begin(), row.end());
  std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<CapEdge> edges;
  edges.reserve(keyed.size());
  for (const auto& [key, edge] : keyed) edges.push_back(edge);
  const double msEdges = msSince(tRuns);

  // The flattened cap needs only the edges: triangulated while pass B runs.
  const bool flatCap = !exact || options.flattenCap;
  std::vector<std::array<std::uint32_t, 3>> cap;
  double msCapTask = 0.0;
  tbb::task_group capTask;
  if (flatCap)
    capTask.run([&] {
      const auto tc = Clock::now();
      cap = triangulateCapLoops(edges);
      msCapTask = msSince(tc);
    });

  // --- Pass B: vertex indices (two rolling rows per task), positions, sheet triangles and the
  // index of each quad's first triangle. ---
  VolumeMesh& mesh = result.mesh;
  // Room for the cap too (a flattened cap has about as many triangles as boundary edges), so that
  // appending it rarely reallocates.
  sizeBuffer(mesh.positions, rowVerts[h] + copies);
  sizeBuffer(mesh.triangles, sheetTriangles, sheetTriangles + sheetTriangles / 4 + 4 * std::size_t(w + h) + 64);
  auto& quadTri = scratch_->quadTri;  // index of each quad's first kept triangle (kept quads only)
  sizeBuffer(quadTri, quadCount);
  try {
    tbb::parallel_for(tbb::blocked_range<int>(0, qh, 8), [&](const tbb::blocked_range<int>& rows) {
      std::vector<std::uint32_t> idxLo(w), idxHi(w);
      std::vector<std::uint8_t> used(w);
      std::vector<double> depth(w), x(w), y(w), z(w);
      bool bad = false;  // already reported by pass A
      // Vertex indices of row j over its used span (entries outside it are stale and never read:
      // the triangles of a quad row lie within its span).
      auto vertexRow = [&](int j, std::vector<std::uint32_t>& idx) {
        const auto [b, e] = usedRow(j, used.data());
        numberRow(used.data() + b, idx.data() + b, e - b, std::uint32_t(rowVerts[j]), kNone);
        return std::pair<int, int>{b, e};
      };
      auto emitRow = [&](int j, const std::vector<std::uint32_t>& idx, std::pair<int, int> span) {
        if (rowVerts[j + 1] == rowVerts[j]) return;
        auto [b, e] = span;
        while (idx[b] == kNone) ++b;
        while (idx[e - 1] == kNone) --e;
        sheetDepthRow(j, depth.data(), bad, b, e);
        unproject.worldPoints(j, b, e, depth.data(), x.data(), y.data(), z.data());
        for (int i = b; i < e; ++i)
          if (idx[i] != kNone) mesh.positions[idx[i]] = {x[i], y[i], z[i]};
      };
      std::pair<int, int> spanLo, spanHi = vertexRow(rows.begin(), idxHi);
      for (int qj = rows.begin(); qj != rows.end(); ++qj) {
        std::swap(idxLo, idxHi);
        spanLo = spanHi;
        spanHi = vertexRow(qj + 1, idxHi);
        emitRow(qj, idxLo, spanLo);
        if (qj + 1 == qh) emitRow(qj + 1, idxHi, spanHi);
        std::size_t next = rowTriOffset[qj];
        const std::uint8_t* rowCode = code.data() + std::size_t(qj) * qw;
        const auto [qb, qe] = rowSpan[qj];
        for (int qi = qb; qi < qe; ++qi) {
          const std::size_t qIndex = std::size_t(qj) * qw + qi;
          if (qi + 8 <= qe) {  // runs of dropped quads (code 0), 8 at a time
            std::uint64_t eight;
            std::memcpy(&eight, rowCode + qi, 8);
            if (eight == 0) {  // quadTri of a dropped quad is never read
              qi += 7;
              continue;
            }
          }
          const std::uint8_t q = rowCode[qi];
          quadTri[qIndex] = std::uint32_t(next);
          const int f = q & kFlip;
          const std::uint32_t corner[4] = {idxLo[qi], idxLo[qi + 1], idxHi[qi + 1], idxHi[qi]};
          for (int t = 0; t < 2; ++t) {
            if (!(q & keepBit(t))) continue;
            const int* cs = kTriCorners[f][t];
            mesh.triangles[next++] = {corner[cs[0]], corner[cs[1]], corner[cs[2]]};
          }
        }
      }
    });
  } catch (...) {
    capTask.wait();
    throw;
  }
  // Pinch copies: their positions, and the triangles of their runs.
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 32), [&](const tbb::blocked_range<int>& rows) {
    for (int j = rows.begin(); j != rows.end(); ++j)
      for (const Fan& fan : rowFans[j])
        for (int s = 0; s < fan.n; ++s) {
          const Slot& slot = fan.slots[s];
          if (!slot.kept || slot.run == 0) continue;
          mesh.positions[fan.firstCopy + slot.run - 1u] = mesh.positions[fan.id];
          const std::uint8_t q = code[slot.quad];
          mesh.triangles[quadTri[slot.quad] + ((slot.t == 1 && (q & kKeep0)) ? 1u : 0u)][slot.k] = slotId(fan, slot);
        }
  });
  stats.msSheet = msSince(t0) - msEdges;

  // --- Phase 3: far cap. ---
  t0 = Clock::now();
  stats.capTrianglesBefore = sheetTriangles;
  if (flatCap) {
    capTask.wait();
    for (const Tri& c : cap) mesh.triangles.push_back({c[0], c[2], c[1]});  // faces away from the light
    stats.capTrianglesAfter = cap.size();
  } else {
    // Unflattened: the mirror image of every kept sheet triangle on the far plane. Boundary vertices
    // are shared with the sheet (the sheet triangle already names the right pinch copy); every other
    // texel gets one far-plane cap vertex.
    std::vector<std::uint8_t> onBoundary(mesh.positions.size(), 0);
    for (const CapEdge& e : edges) onBoundary[e.from] = onBoundary[e.to] = 1;
    std::vector<std::uint32_t> capVertex(texels, kNone);
    for (int qj = 0; qj < qh; ++qj)
      for (int qi = 0; qi < qw; ++qi) {
        const std::size_t qIndex = std::size_t(qj) * qw + qi;
        const std::uint8_t q = code[qIndex];
        const int f = q & kFlip;
        for (int t = 0; t < 2; ++t) {
          if (!(q & keepBit(t))) continue;
          const Tri sheet = mesh.triangles[quadTri[qIndex] + ((t == 1 && (q & kKeep0)) ? 1u : 0u)];
          Tri cap{};
          for (int k = 0; k < 3; ++k) {
            if (onBoundary[sheet[k]]) {
              cap[k] = sheet[k];
              continue;
            }
            const int corner = kTriCorners[f][t][k];
            const int i = qi + kCornerDi[corner], j = qj + kCornerDj[corner];
            std::uint32_t& v = capVertex[std::size_t(j) * w + i];
            if (v == kNone) {
              v = std::uint32_t(mesh.positions.size());
              mesh.positions.push_back(unproject.worldPoint(i, j, farPlane));
            }
            cap[k] = v;
          }
          mesh.triangles.push_back({cap[0], cap[2], cap[1]});
        }
      }
    stats.capTrianglesAfter = sheetTriangles;
  }
  stats.msCap = msSince(t0) + msEdges + msCapTask;  // the cap's own work, partly run during pass B
  stats.msTotal = msSince(tStart);
}

}  // namespace shadowvol

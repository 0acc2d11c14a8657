#include "volume/grid_unprojector.h"

#include <glm/matrix.hpp>
#include <glm/vec4.hpp>

namespace shadowvol::volume {
namespace {

// GridUnprojector's separable projection terms, by value for the row loop below.
struct SeparableProjection {
  double p20, p21, p30, p31, p23, p33, inv00, inv11;
};

// Light-view points of texels [b, e) of one row (normalised x per column, y of the row) at
// light-view depths d, into x, y, z. A free function with restrict pointers and the terms by
// value: as a member loop every store might alias the members, and nothing vectorised. On x86-64
// with GCC an AVX2 clone is chosen at load time (AVX2 without FMA: the same IEEE operations in the
// same order as the portable code, so the same points on every machine).
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

// The non-separable fallback: point(i, d[i]) one texel at a time, into x, y, z.
template <class Point>
void perTexel(int begin, int end, const double* d, double* x, double* y, double* z, Point point) {
  for (int i = begin; i < end; ++i) {
    const glm::dvec3 p = point(i, d[i]);
    x[i] = p.x, y[i] = p.y, z[i] = p.z;
  }
}

}  // namespace

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

GridUnprojector::GridUnprojector(const DepthMap& map) : reference_(map) {
  const glm::dmat4& p = map.lightProjection;  // column-major: p[col][row]
  separable_ = p[1][0] == 0.0 && p[0][1] == 0.0 && p[0][3] == 0.0 && p[1][3] == 0.0 && p[0][0] != 0.0 && p[1][1] != 0.0;
  p00_ = p[0][0], p11_ = p[1][1], p20_ = p[2][0], p21_ = p[2][1], p30_ = p[3][0], p31_ = p[3][1];
  p23_ = p[2][3], p33_ = p[3][3];
  inv00_ = 1.0 / p00_, inv11_ = 1.0 / p11_;
  xn_.resize(std::size_t(map.width));
  yn_.resize(std::size_t(map.height));
  for (int i = 0; i < map.width; ++i) xn_[std::size_t(i)] = (i + 0.5) / double(map.width) * 2.0 - 1.0;
  for (int j = 0; j < map.height; ++j) yn_[std::size_t(j)] = (j + 0.5) / double(map.height) * 2.0 - 1.0;
  invView_ = glm::inverse(map.lightView);
}

glm::dvec3 GridUnprojector::lightViewPoint(int i, int j, double d) const {
  if (!separable_) return reference_.lightViewPoint(i, j, d);
  const double z = -d, wc = p23_ * z + p33_;
  return {(xn_[std::size_t(i)] * wc - p20_ * z - p30_) * inv00_, (yn_[std::size_t(j)] * wc - p21_ * z - p31_) * inv11_, z};
}

void GridUnprojector::lightViewPoints(int j, int begin, int end, const double* d, double* x, double* y, double* z) const {
  if (!separable_)
    return perTexel(begin, end, d, x, y, z, [&](int i, double di) { return reference_.lightViewPoint(i, j, di); });
  lightViewRow(xn_.data(), yn_[std::size_t(j)], begin, end, d, x, y, z,
               {p20_, p21_, p30_, p31_, p23_, p33_, inv00_, inv11_});
}

void GridUnprojector::worldPoints(int j, int begin, int end, const double* d, double* x, double* y, double* z) const {
  if (!separable_)
    return perTexel(begin, end, d, x, y, z, [&](int i, double di) { return reference_.worldPoint(i, j, di); });
  lightViewPoints(j, begin, end, d, x, y, z);
  transformRow(invView_, begin, end, x, y, z);
}

glm::dvec3 GridUnprojector::worldPoint(int i, int j, double d) const {
  if (!separable_) return reference_.worldPoint(i, j, d);
  return glm::dvec3(invView_ * glm::dvec4(lightViewPoint(i, j, d), 1.0));
}

}  // namespace shadowvol::volume

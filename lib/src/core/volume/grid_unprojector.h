// Texel-centre unprojection for whole grids (the builder's positions and diagonal rule), in
// double precision: TexelUnprojector's result, with the projection solved per axis when the
// matrix allows it, as vectorised row loops.
#pragma once

#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "shadowvol/depth_map.h"

namespace shadowvol::volume {

/// In place, for i in [b, e): (x, y, z)[i] = m * (x, y, z, 1)[i], in glm's operation order for
/// mat4 * vec4 ((m0 x + m1 y) + (m2 z + m3)), so the result equals glm's to the bit.
void transformRow(const glm::dmat4& m, int b, int e, double* __restrict x, double* __restrict y, double* __restrict z);

/// TexelUnprojector's points for integer texel centres, with the projection solved per axis when
/// the matrix allows it (glm's perspective and orthographic matrices: x and y do not mix, clip w
/// depends on view z only), else TexelUnprojector itself. Agrees with it to a few ulps (it
/// multiplies by 1 / P00 and 1 / P11 instead of dividing: divisions were a tenth of the build).
class GridUnprojector {
 public:
  explicit GridUnprojector(const DepthMap& map);

  /// Light-view point of texel (i, j) at light-view depth d.
  glm::dvec3 lightViewPoint(int i, int j, double d) const;
  /// lightViewPoint(i, j, d[i]) for i in [begin, end), into x, y, z (a loop that vectorises).
  void lightViewPoints(int j, int begin, int end, const double* d, double* x, double* y, double* z) const;
  /// World points of the same, into x, y, z.
  void worldPoints(int j, int begin, int end, const double* d, double* x, double* y, double* z) const;
  glm::dvec3 worldPoint(int i, int j, double d) const;

 private:
  TexelUnprojector reference_;
  bool separable_ = false;
  double p00_, p11_, p20_, p21_, p30_, p31_, p23_, p33_, inv00_, inv11_;
  std::vector<double> xn_, yn_;
  glm::dmat4 invView_;
};

}  // namespace shadowvol::volume

#include "shadowvol/dual_paraboloid.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "shadowvol/check.h"
#include "shadowvol/error.h"
#include "shadowvol/volume_builder.h"

namespace shadowvol {

int dualParaboloidSide(int cubeFaceSide) {
  SV_CHECK_GT(cubeFaceSide, 0);
  return std::max(1, int(std::lround(double(cubeFaceSide) * std::sqrt(3.0))));
}

DualParaboloid makeDualParaboloid(const Light& point, const Bounds3& sceneBounds, int side) {
  if (point.type != LightType::Point)
    throw InputError("light", "type", toString(point.type), "dual-paraboloid maps are a point light's");
  SV_CHECK_GT(side, 0);
  SV_CHECK_GT(point.farPlane, point.nearPlane);
  DualParaboloid dp;
  dp.position = point.position;
  dp.side = side;
  dp.nearDistance = point.nearPlane;
  dp.farDistance = point.farPlane * std::sqrt(3.0);
  glm::dvec3 axis{0.0, -1.0, 0.0};
  if (!sceneBounds.empty()) {
    const glm::dvec3 toCentre = sceneBounds.center() - point.position;
    const double length = glm::length(toCentre);
    if (std::isfinite(length) && length > 1e-9) axis = toCentre / length;
  }
  Light view;  // lightUp's rule for a view along the axis
  view.direction = axis;
  const glm::dvec3 up = lightUp(view);
  const glm::dvec3 y = glm::normalize(up - glm::dot(up, axis) * axis);
  const glm::dvec3 x = glm::cross(y, axis);
  // Rows x, y, axis: glm is column-major, so the matrix is the transpose of the columns x, y, axis.
  dp.toFront = glm::transpose(glm::dmat3(x, y, axis));
  return dp;
}

double dualParaboloidDefaultBias(const Light& point, int cubeFaceSide, CaptureMode capture) {
  const int coarse = std::max(1, dualParaboloidSide(cubeFaceSide) / 2);
  return defaultBias(point, coarse, coarse, capture);
}

glm::dvec3 paraboloidFrameOffset(const DualParaboloid& dp, int hemisphere, const glm::dvec3& worldOffset) {
  const glm::dvec3 f = dp.toFront * worldOffset;
  return hemisphere == 0 ? f : glm::dvec3(f.x, -f.y, -f.z);
}

ParaboloidPoint paraboloidProject(const DualParaboloid& dp, const glm::dvec3& worldPoint) {
  const glm::dvec3 offset = worldPoint - dp.position;
  ParaboloidPoint p;
  p.distance = glm::length(offset);
  if (!(p.distance > 0.0)) return p;  // the light itself: front centre
  p.hemisphere = (dp.toFront * offset).z >= 0.0 ? 0 : 1;
  const glm::dvec3 d = paraboloidFrameOffset(dp, p.hemisphere, offset) / p.distance;
  p.xy = glm::dvec2(d.x, d.y) / (1.0 + d.z);
  return p;
}

glm::dvec3 paraboloidDirection(const DualParaboloid& dp, int hemisphere, const glm::dvec2& xy) {
  const double r2 = glm::dot(xy, xy);
  glm::dvec3 d = glm::dvec3(2.0 * xy.x, 2.0 * xy.y, 1.0 - r2) / (1.0 + r2);
  if (hemisphere != 0) d = glm::dvec3(d.x, -d.y, -d.z);  // the back frame's turn is its own inverse
  return glm::transpose(dp.toFront) * d;
}

glm::dvec2 paraboloidTexelCentre(int side, double i, double j) {
  return glm::dvec2((i + 0.5) / side * 2.0 - 1.0, (j + 0.5) / side * 2.0 - 1.0);
}

double paraboloidStoredDepth(const DualParaboloid& dp, double distance) {
  return 1.0 - (distance - dp.nearDistance) / (dp.farDistance - dp.nearDistance);
}

namespace {

// Solid angle of the rectangle [x0, x1] x [y0, y1] of a paraboloid map: the integral of the
// stereographic area element 4 / (1 + r^2)^2, by the midpoint rule on 16 x 16 sub-cells (a
// texel's element varies by under 1 % across it at side 8 and up, so the rule is far finer).
double paraboloidRectSolidAngle(double x0, double y0, double x1, double y1) {
  constexpr int kSteps = 16;
  const double dx = (x1 - x0) / kSteps, dy = (y1 - y0) / kSteps;
  double sum = 0.0;
  for (int a = 0; a < kSteps; ++a)
    for (int b = 0; b < kSteps; ++b) {
      const double x = x0 + (a + 0.5) * dx, y = y0 + (b + 0.5) * dy, q = 1.0 + x * x + y * y;
      sum += 4.0 / (q * q);
    }
  return sum * dx * dy;
}

// Solid angle of the rectangle [x0, x1] x [y0, y1] of the plane z = 1 seen from the origin
// (exact: F(x, y) = atan(x y / sqrt(1 + x^2 + y^2)) at the corners).
double planeRectSolidAngle(double x0, double y0, double x1, double y1) {
  auto f = [](double x, double y) { return std::atan(x * y / std::sqrt(1.0 + x * x + y * y)); };
  return f(x1, y1) - f(x0, y1) - f(x1, y0) + f(x0, y0);
}

}  // namespace

TexelSolidAngles paraboloidTexelSolidAngles(int side) {
  SV_CHECK_GT(side, 0);
  const double t = 2.0 / side;
  // The largest texel is the one nearest the centre (the element falls with r); the smallest the
  // one wholly inside the disc whose farthest corner is farthest out.
  int nearest = 0, outmost = -1;
  double nearestR = 1e300, outmostR = -1.0;
  std::size_t used = 0;
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const glm::dvec2 c = paraboloidTexelCentre(side, i, j);
      const double r = glm::length(c);
      if (r <= 1.0) ++used;
      const double far = std::hypot(std::abs(c.x) + t / 2, std::abs(c.y) + t / 2);
      if (r < nearestR) nearestR = r, nearest = j * side + i;
      if (far <= 1.0 && far > outmostR) outmostR = far, outmost = j * side + i;
    }
  auto texel = [&](int k) {
    const double x0 = (k % side) * t - 1.0, y0 = (k / side) * t - 1.0;
    return paraboloidRectSolidAngle(x0, y0, x0 + t, y0 + t);
  };
  TexelSolidAngles s;
  s.largest = texel(nearest);
  s.smallest = outmost >= 0 ? texel(outmost) : s.largest;
  s.usedFraction = double(used) / (double(side) * double(side));
  return s;
}

TexelSolidAngles cubeTexelSolidAngles(int cubeFaceSide) {
  SV_CHECK_GT(cubeFaceSide, 0);
  const double t = 2.0 / cubeFaceSide;
  const int mid = cubeFaceSide / 2;  // a texel at (or next to) the face's centre
  TexelSolidAngles s;
  const double x0 = mid * t - 1.0;
  s.largest = planeRectSolidAngle(x0, x0, x0 + t, x0 + t);
  s.smallest = planeRectSolidAngle(1.0 - t, 1.0 - t, 1.0, 1.0);
  s.usedFraction = 1.0;
  return s;
}

}  // namespace shadowvol

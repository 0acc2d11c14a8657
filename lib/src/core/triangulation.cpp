#include "shadowvol/triangulation.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace shadowvol {

const char* toString(Triangulation t) { return t == Triangulation::Fixed ? "fixed" : "perfect"; }

bool parseTriangulation(const std::string& text, Triangulation& t) {
  if (text == "fixed") t = Triangulation::Fixed;
  else if (text == "perfect") t = Triangulation::Perfect;
  else return false;
  return true;
}

bool flipDiagonal(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
  // Twice the areas of the triangles opposite each corner (the factor 2 cancels in comparisons).
  const double aA = glm::length(glm::cross(c - b, d - b));
  const double aB = glm::length(glm::cross(c - a, d - a));
  const double aC = glm::length(glm::cross(b - a, d - a));
  const double aD = glm::length(glm::cross(b - a, c - a));
  const double sixV = std::abs(glm::dot(b - a, glm::cross(c - a, d - a)));
  const double l2 = std::max({glm::dot(b - a, b - a), glm::dot(c - a, c - a), glm::dot(d - a, d - a),
                              glm::dot(c - b, c - b), glm::dot(d - b, d - b), glm::dot(d - c, d - c)});
  const double l = std::sqrt(l2);
  if (!(sixV > kPlanarTolerance * l2 * l)) return false;  // planar, degenerate (or non-finite input)
  return (aB < aC && aB < aA) || (aD < aC && aD < aA);
}

}  // namespace shadowvol

// Where a straight path in a light's image plane leaves one triangle of the scene: the geometry of
// refinement's snap (crossing_snap.h), written once for every SurfaceEndOracle (depth_oracle.h:
// the Embree oracle, analytic test scenes); shaders/silhouette_rays.comp mirrors it in float.
//
// The light's projection maps the half-space in front of a spot light's apex plane (all of space
// for a directional light) to the image plane projectively, so a triangle there maps to a
// triangle, and a straight path from a point inside it leaves it once, through the first side it
// crosses outwards (Cyrus-Beck clipping).
#pragma once

#include <array>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shadowvol/depth_map.h"

namespace shadowvol {

/// The triangle `corners` (the map's coordinates, as its rays) and the path from -> to (texel
/// coordinates): the fraction t >= 0 of the way from -> to at which the path leaves the triangle's
/// image (it may exceed 1), or NaN when there is none to give: from == to, a corner at or behind a
/// spot light's apex plane (light-view depth <= 1e-9 of the far plane), or a triangle whose image
/// has (almost) no area (edge-on to the light: its area below 1e-12 of its squared longest side).
/// A `from` just outside the image (float rounding of the ray that found the triangle) exits at 0.
double triangleExit(const DepthMap& map, const std::array<glm::dvec3, 3>& corners, glm::dvec2 from, glm::dvec2 to);

/// The light-view depth at which the light ray through texel point `at` (texel coordinates of the
/// map `unproject` is of) meets the plane of the triangle `corners` (the map's coordinates): the
/// depth that triangle shows there, also outside it. NaN when the ray runs (almost) in the plane
/// (below 1e-12 of the normal's length per unit of ray) or meets it at no positive depth.
double triangleDepthAt(const TexelUnprojector& unproject, const std::array<glm::dvec3, 3>& corners, glm::dvec2 at);

}  // namespace shadowvol

// A point light's dual-paraboloid shadow map (Heidrich and Seidel 1998; Brabec, Annen and Seidel
// 2002; the tutorial in shared/reference): the directions around the light split into two
// hemispheres, each mapped onto a disc by the paraboloid projection, stored in one square map per
// hemisphere. The baseline beside the cube shadow map (cube_map.h) at the same texel count.
//
// Frame. The front hemisphere looks from the light toward the centre of the scene's bounds (the
// tutorial's "toward the lit objects"), world -Y when that centre is within 1e-9 of the light;
// its x and y axes complete a right-handed frame with the up rule of lightUp (world +Y, or -Z
// when the axis is within 2.6 degrees of +-Y). The back hemisphere is that frame turned half a
// turn about its x axis, (x, -y, -axis), a rotation, so a triangle keeps its winding in both maps.
//
// Projection. A world point p with offset o = p - light and unit direction d = o / |o| in a
// hemisphere's frame (d.z >= 0 in its own) maps to xy = d.xy / (1 + d.z), inside the unit disc;
// the inverse is d = (2x, 2y, 1 - r^2) / (1 + r^2) with r = |xy| (the stereographic projection).
// Texel (i, j) of a side x side map has its centre at xy = (i + 0.5) / side * 2 - 1 (j likewise;
// depth_map.h's order, row 0 at the bottom). Stored: the reversed normalised distance
// 1 - (|o| - near) / (far - near) with near = the light's near and far = its far times sqrt(3)
// (the farthest point of its far cube), so the map compares as the other shadow maps, GEQUAL.
//
// Mirrored in shaders/paraboloid.glsl; the GL tests check the map the GPU draws against
// paraboloidDirection.
#pragma once

#include <cstddef>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shadowvol/depth_map.h"
#include "shadowvol/light.h"
#include "shadowvol/triangle_mesh.h"

namespace shadowvol {

/// The side of each paraboloid map that spends the texels of a cube map of `cubeFaceSide`^2 per
/// face: round(cubeFaceSide * sqrt(3)), so 2 side^2 ~ 6 cubeFaceSide^2. Only the disc of each map
/// is used (pi / 4 of its texels).
int dualParaboloidSide(int cubeFaceSide);

struct DualParaboloid {
  glm::dvec3 position{0.0};  ///< the light's, world
  glm::dmat3 toFront{1.0};   ///< world offset -> front frame (columns of the transpose: x, y, axis)
  double nearDistance = 0.0, farDistance = 1.0;  ///< the stored range, world units
  int side = 1;              ///< texels per map side
};

/// The frame and range of a point light (type Point, planes fitted) over `sceneBounds`, with maps
/// of `side` texels a side. Throws InputError naming the light for another type.
DualParaboloid makeDualParaboloid(const Light& point, const Bounds3& sceneBounds, int side);

/// The widest angle (radians, seen from the light) a triangle's edge may span after the light
/// pass's subdivision (RenderOptions::paraboloidSubdivision): a straight edge in the disc then
/// departs from its true arc by at most about angle^2 side / 16 texels (0.28 at side 443).
inline constexpr double kParaboloidSubdivisionAngle = 0.1;

/// The default shadow-map bias of the maps for a cube face side of `cubeFaceSide`: that of a cube
/// face (defaultBias) whose texels are as coarse as the maps' coarsest (at a disc's centre, 4 /
/// side radians: a face of side / 2 texels).
double dualParaboloidDefaultBias(const Light& point, int cubeFaceSide, CaptureMode capture);

/// World offset -> hemisphere h's frame (0 front, 1 back).
glm::dvec3 paraboloidFrameOffset(const DualParaboloid& dp, int hemisphere, const glm::dvec3& worldOffset);

struct ParaboloidPoint {
  int hemisphere = 0;       ///< 0 front (frame z >= 0; ties there), 1 back
  glm::dvec2 xy{0.0};       ///< in the unit disc
  double distance = 0.0;    ///< |offset|, world units
};

/// Where a world point falls. The light's own position maps to the front map's centre at distance 0.
ParaboloidPoint paraboloidProject(const DualParaboloid& dp, const glm::dvec3& worldPoint);

/// The world unit direction of hemisphere h's point xy (|xy| <= 1; beyond, the direction past
/// the rim, into the other hemisphere).
glm::dvec3 paraboloidDirection(const DualParaboloid& dp, int hemisphere, const glm::dvec2& xy);

/// xy of texel (i, j)'s centre (fractional i, j allowed).
glm::dvec2 paraboloidTexelCentre(int side, double i, double j);

/// The stored value of a distance: 1 - (distance - near) / (far - near).
double paraboloidStoredDepth(const DualParaboloid& dp, double distance);

/// How unevenly a map spends its texels: the solid angles (steradians) of its smallest and
/// largest texel, over the texels that lie wholly in the used region (the disc of each
/// paraboloid map; every texel of a cube face), and the fraction of the allocated texels whose
/// centre lies in it.
struct TexelSolidAngles {
  double smallest = 0.0, largest = 0.0;
  double usedFraction = 0.0;
};
TexelSolidAngles paraboloidTexelSolidAngles(int side);
TexelSolidAngles cubeTexelSolidAngles(int cubeFaceSide);

}  // namespace shadowvol

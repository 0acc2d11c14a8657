// Internal to the scene fitting: the depth range of the part of a box that a view can see. Far
// planes fitted to a whole box reach as deep as its farthest corner, even when that corner lies
// far outside the frustum (a spot light over a wide ground: the corners of a 2e6-unit ground are
// 3e5 deep, the ground the light sees is 4 deep), and every wall of the volume then runs that far,
// which costs precision wherever it is rasterised or ray-cast.
#pragma once

#include <optional>
#include <span>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>

#include "shadowvol/camera.h"
#include "shadowvol/light.h"
#include "shadowvol/triangle_mesh.h"

namespace shadowvol::detail {

/// A view's frustum, without near and far planes: in view space (looking down -z), the pyramid
/// |x| <= tanX * depth, |y| <= tanY * depth with its apex at the origin (perspective), or the
/// prism |x| <= halfX, |y| <= halfY (orthographic; tanX and tanY then hold halfX and halfY).
struct ViewFrustum {
  glm::dmat4 view{1.0};  ///< world -> view
  double tanX = 1.0, tanY = 1.0;
  bool orthographic = false;
};

/// The frustum of a light (square map: aspect 1) and of a camera (its image's aspect).
ViewFrustum lightFrustum(const Light& light, double aspect = 1.0);
ViewFrustum cameraFrustum(const Camera& camera);

/// The vertices of box b intersected with the frustum, in view space: each box face clipped by
/// the frustum's four side planes in double, plus the apex when it lies inside the box (every
/// vertex of the intersection is among them, so their convex hull is the intersection). Empty
/// when they do not meet.
std::vector<glm::dvec3> boxPartInFrustum(const Bounds3& b, const ViewFrustum& f);

/// Smallest and largest view depth (-z) over box b intersected with the frustum, computed exactly
/// (each box face clipped by the frustum's four side planes, in double; the apex counts when it
/// lies inside the box); nullopt when they do not meet.
std::optional<std::pair<double, double>> depthRangeInFrustum(const Bounds3& b, const ViewFrustum& f);

/// The same over several boxes (a scene's objects, each in its own): the union of their ranges,
/// nullopt when the frustum meets none. Tighter than the range of the one box around them all
/// where the view sees the space between them (a low spot light beside a ground plane, over
/// which the scene's box reaches up to the light: a probe's fitted near plane of 0.02 where the
/// nearest part of any object the light sees, the ground's, is 2.5 away).
std::optional<std::pair<double, double>> depthRangeInFrustum(std::span<const Bounds3> boxes, const ViewFrustum& f);

}  // namespace shadowvol::detail

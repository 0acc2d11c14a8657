// Whether a mesh lies wholly outside a view's clip volume (internal to the core: the capture
// warnings' light frustum and the scene loader's camera view).
#pragma once

#include <glm/mat4x4.hpp>

#include <string>
#include <vector>

#include "shadowvol/scene.h"
#include "shadowvol/triangle_mesh.h"

namespace shadowvol::detail {

/// True when `mesh` lies wholly outside the clip volume of `worldToClip` (an OpenGL projection
/// times a view: -w <= x, y, z <= w inside): every vertex beyond one and the same plane (the mesh,
/// inside the convex hull of its vertices, then lies outside), or else no triangle keeps a part
/// inside when clipped against the six planes in homogeneous coordinates (linear in the world
/// position, so vertices behind the view's apex are clipped correctly too). False for an empty mesh
/// (nothing to judge).
bool outsideClipVolume(const glm::dmat4& worldToClip, const TriangleMesh& mesh);

/// The warning for a view that holds none of `objects` (each outsideClipVolume), naming the view
/// (`what`, such as "inside the light's frustum"), its near and far planes and `consequence`; empty when
/// some object may lie inside.
std::string emptyViewWarning(const glm::dmat4& worldToClip, const std::vector<SceneObject>& objects,
                             const std::string& what, double nearPlane, double farPlane,
                             const std::string& consequence);

}  // namespace shadowvol::detail

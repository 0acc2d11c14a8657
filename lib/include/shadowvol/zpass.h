// When a depth-map shadow volume may be counted with z-pass and no far cap (docs/gpu.md,
// "Z-pass where it is safe"). Decided on the CPU from the light, the camera and the volume
// options alone, conservatively, so the GPU path needs no read-back for it.
//
// Z-pass counts the volume's faces between the camera's near plane and the visible surface: the
// winding number of the surface point P less that of the point Q where its camera ray crosses the
// near plane. That is the right count when every Q lies outside the volume. The volume lies in
// the light's frustum, no nearer to the light than its near plane (every sheet depth is a captured
// depth, at least the near plane, pushed away by bias), and the far cap lies on its far plane. A
// segment Q -> P whose two ends are nearer to the light than its far plane never reaches that
// plane (light-view depth is linear along it), so it cannot cross the cap: the cap can be left
// out. The P beyond the far plane lie outside the light's frustum, which lights nothing there.
#pragma once

#include <string>

#include "shadowvol/camera.h"
#include "shadowvol/light.h"
#include "shadowvol/volume_builder.h"

namespace shadowvol {

struct ZPassSafety {
  bool safe = false;
  std::string reason;  ///< why not (empty when safe)
};

/// Safe when the four corners of the camera's near rectangle (world space, in double) all lie
/// beyond one side plane of the light's frustum, or all nearer to the light than its near plane
/// less any pull of the options (a negative blur offset or bias), and all nearer than its far
/// plane. `lightAspect` is the depth map's W / H.
ZPassSafety zPassSafety(const Light& light, double lightAspect, const Camera& camera, const VolumeBuildOptions& options);

}  // namespace shadowvol

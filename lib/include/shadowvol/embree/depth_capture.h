// CPU depth capture by ray casting with Embree 3: the no-GPU way to get a light's DepthMap.
#pragma once

#include "shadowvol/cube_map.h"
#include "shadowvol/depth_map.h"
#include "shadowvol/scene.h"

namespace shadowvol {

/// One ray per texel centre (see depth_map.h), from the light (spot: from the apex; directional:
/// from the plane through Light::position, along the direction), limited to [near, far].
/// Modes, for closed meshes and for single-sided geometry (an open plane, a lone quad):
///  - Front: the first surface hit, whatever its facing.
///  - Back: the first surface whose geometric normal faces away from the light (the light sees
///    its back side), as the GPU does with front-face culling. A single-sided surface facing the
///    light (a ground plane lit from above) is skipped, so it casts no shadow and receives none
///    from itself; the texel is kNoHit unless a back face lies behind it.
///  - Midpoint: the mean of the first and second surface hit (any facing). With only one surface
///    on the ray, the second is the far plane (as the GPU's cleared second layer).
///  - Entry: the first surface (any facing) up to the first back face, and kNoHit where Back has
///    none: front capture's depth on what back capture records. A closed occluder's lit side
///    without the lit receivers facing the light (an open ground plane), so the volume's sheet
///    covers the occluders only, as with back capture (one ray per texel, which records the nearest
///    front face it meets before it ends on the first back face). A face lit nearly
///    edge-on (cosine with the ray below kEntryGrazingCos, depth_map.h) is passed over, so the
///    back face behind it is recorded there.
/// Parallel over rows (TBB) and deterministic: each texel is computed independently. A size that
/// checkDepthMapSize refuses (below 2 or above kMaxDepthMapSide a side, or more than half of the
/// machine's memory) is an InputError naming it.
/// A point light's scene is an InputError here (it has six maps: captureCubeEmbree).
/// `guard` > 0: the map of guardedLight(scene.light, width, height, guard), (width + 2 guard) x
/// (height + 2 guard) texels, the given size's texels and a band of `guard` more on every side
/// (kVolumeGuardTexels for a volume: light.h); both sizes checked as above.
DepthMap captureDepthEmbree(const Scene& scene, int width, int height, CaptureMode mode, int guard = 0);

/// A point light's cube map (cube_map.h): each face as captureDepthEmbree captures that face's
/// spot light (cubeFaceLight), with one BVH for the six. The scene's light must be a point light.
CubeDepthMap captureCubeEmbree(const Scene& scene, int n, CaptureMode mode);

}  // namespace shadowvol

// Which surface a light's depth map should record for a scene: the rule behind the command
// line's `--capture auto` (its default; README "Capture modes").
#pragma once

#include <string>
#include <vector>

#include "shadowvol/depth_map.h"
#include "shadowvol/scene.h"

namespace shadowvol {

/// The names of `scene`'s open mesh objects: of type "mesh" and not closed, neither as stored nor
/// once vertices at equal positions are welded (triangle_adjacency.h's isClosedSurface; a
/// non-manifold mesh counts as open). Back capture lets light through their openings: a sheet
/// facing the light has no back face for the map to record. In the order of scene.objects.
std::vector<std::string> openMeshObjects(const Scene& scene);

/// What a depth map is for, which decides the capture `--capture auto` takes on closed meshes.
enum class CaptureUse {
  ShadowMap,      ///< compared with each pixel's light depth: back capture needs no bias
  Volume,         ///< an unrefined hybrid volume's sheet: back capture (entry's second pass did not pay)
  RefinedVolume,  ///< a refined hybrid volume's sheet: entry capture measured best
  OneLayer,       ///< read as one layer (the GPU's silhouette walk, dual-paraboloid maps): back capture
};

/// The use of a hybrid volume's map with `refineSteps` bisection steps: RefinedVolume when > 0.
inline CaptureUse volumeUse(int refineSteps) {
  return refineSteps > 0 ? CaptureUse::RefinedVolume : CaptureUse::Volume;
}

struct CaptureChoice {
  CaptureMode mode = CaptureMode::Back;
  std::vector<std::string> openMeshes;  ///< why front was chosen: openMeshObjects(scene)
  bool deepSpot = false;                ///< back rather than entry for a refined volume: a deep spot light
  /// One sentence: what was chosen and why, naming the open objects (at most three, then a count).
  std::string reason;
};

/// Front capture (the nearest surface, with its documented bias) when a mesh object is open. When
/// every mesh is closed: entry capture for a refined volume (its sheet on the occluders' lit sides;
/// against the sharp exact reference, with the sub-grid at 128², it misclassified fewer pixels than
/// back capture on 16 of 22 closed-mesh scenes and as many on 3, and meets the 128² goal where back
/// capture misses it: docs/results/capture-auto-entry), else back capture (no bias; the thesis's
/// default): for a shadow map (entry's lit-side depths need front's bias, up to 9 times back
/// capture's error on those scenes), for an unrefined volume (entry lowered its error on 17 of 22
/// at 256² but cost 1.10 to 1.51 times the default render's frame on llvmpipe, its second light
/// pass), and for one-layer uses, which cannot take entry's two layers. Generated objects (plane,
/// sphere, box, cylinder, hemisphere, tree) do not decide: their shapes are known, a plane is a
/// receiver. Midpoint capture, which also records open meshes, is never chosen: it costs a second
/// depth layer. Deterministic: the same scene gives the same choice.
///
/// A refined volume under a spot light (any of the scene's: the capture is every light's) whose far
/// plane lies more than kMaxEntryFarOverNear times as far as its near plane (fitted to the nearest
/// geometry, or given; a near of 0, unfitted, does not count) takes back capture too:
/// entry's bias, a texel's footprint at the far plane (defaultBias), spans more than that many
/// texels at the nearest casters and hides the shadows they cast close to themselves (a fourteenth
/// probe's 160-degree spot: 273 wrong pixels at 256² against back capture's 46; measured in README
/// "`--capture auto`", where the ratio sits between 4.67, entry as good or better, and 8.85, entry worse). Point
/// lights keep entry capture: the room scene is as accurate either way (README).
CaptureChoice chooseCapture(const Scene& scene, CaptureUse use);

/// The far / near ratio of a spot light above which a refined volume takes back capture.
inline constexpr double kMaxEntryFarOverNear = 8.0;

}  // namespace shadowvol

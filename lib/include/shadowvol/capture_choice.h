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

struct CaptureChoice {
  CaptureMode mode = CaptureMode::Back;
  std::vector<std::string> openMeshes;  ///< why front was chosen: openMeshObjects(scene)
  /// One sentence: what was chosen and why, naming the open objects (at most three, then a count).
  std::string reason;
};

/// Back capture (no bias; the thesis's default) when every mesh object is closed, front capture
/// (the nearest surface, with its documented bias) when one is open. Generated objects (plane,
/// sphere, box, cylinder, hemisphere, tree) do not decide: their shapes are known, a plane is a
/// receiver. Midpoint capture, which also records open meshes, is never chosen: it costs a second
/// depth layer. Deterministic: the same scene gives the same choice.
CaptureChoice chooseCapture(const Scene& scene);

}  // namespace shadowvol

#include "shadowvol/capture_choice.h"

#include <cstdio>

#include "shadowvol/triangle_adjacency.h"

namespace shadowvol {

std::vector<std::string> openMeshObjects(const Scene& scene) {
  std::vector<std::string> open;
  for (const auto& o : scene.objects)
    if (o.type == "mesh" && !isClosedSurface(o.mesh)) open.push_back(o.name);
  return open;
}

CaptureChoice chooseCapture(const Scene& scene, CaptureUse use) {
  CaptureChoice c;
  c.openMeshes = openMeshObjects(scene);
  if (c.openMeshes.empty()) {
    // The deepest spot light (the capture is every light's): an unfitted near plane of 0 says nothing.
    double deepest = 0.0;
    std::size_t which = 0;
    for (std::size_t k = 0; k < scene.lightCount(); ++k)
      if (const Light& l = scene.lightAt(k); l.type == LightType::Spot && l.nearPlane > 0.0 &&
                                             l.farPlane / l.nearPlane > deepest)
        deepest = l.farPlane / l.nearPlane, which = k;
    c.deepSpot = use == CaptureUse::RefinedVolume && deepest > kMaxEntryFarOverNear;
    const bool entry = use == CaptureUse::RefinedVolume && !c.deepSpot;
    c.mode = entry ? CaptureMode::Entry : CaptureMode::Back;
    if (entry)
      c.reason = "entry capture: no mesh object is open, and the map is a refined volume's";
    else if (c.deepSpot) {
      char ratio[32];
      std::snprintf(ratio, sizeof ratio, "%.3g", deepest);
      const std::string light = scene.lightCount() > 1 ? "spot light " + std::to_string(which) + "'s" : "spot light's";
      c.reason = "back capture: no mesh object is open, and the " + light + " far plane lies " + ratio +
                 " times as far as its near plane: entry capture's bias, a texel at the far plane, would hide the "
                 "shadows the nearest casters cast close to themselves";
    } else {
      c.reason = "back capture: no mesh object is open";
    }
    return c;
  }
  c.mode = CaptureMode::Front;
  constexpr std::size_t kNamed = 3;
  std::string names;
  for (std::size_t k = 0; k < c.openMeshes.size() && k < kNamed; ++k)
    names += (k ? ", \"" : "\"") + c.openMeshes[k] + "\"";
  if (c.openMeshes.size() > kNamed) names += " and " + std::to_string(c.openMeshes.size() - kNamed) + " more";
  c.reason = "front capture: the open mesh" + std::string(c.openMeshes.size() > 1 ? "es " : " ") + names +
             " would let light through under back capture";
  return c;
}

}  // namespace shadowvol

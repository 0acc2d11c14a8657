#include "shadowvol/capture_warnings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/vec4.hpp>

#include "shadowvol/capture_choice.h"
#include "shadowvol/cube_map.h"
#include "clip_volume.h"

namespace shadowvol {
namespace {

// The vertices of `mesh` that lie inside the light's window (texel coordinates in the map, in front of
// a spot light's apex plane) but nearer to the light than its near plane, which clips them.
std::size_t nearClipped(const DepthMap& probe, const glm::dmat4& toClip, const TriangleMesh& mesh) {
  std::size_t count = 0;
  for (const auto& p : mesh.positions) {
    const glm::dvec4 c = toClip * glm::dvec4(glm::dvec3(p), 1.0);
    if (!(c.w > 0.0)) continue;
    const glm::dvec2 t = probe.texelOf(glm::dvec3(p));
    if (!(t.x >= -0.5 && t.y >= -0.5 && t.x <= probe.width - 0.5 && t.y <= probe.height - 0.5)) continue;
    const double depth = probe.viewDepthOf(glm::dvec3(p));
    if (depth >= 0.0 && depth < probe.nearPlane) ++count;
  }
  return count;
}

// A point light's cube sees every direction; what it misses is what lies inside its near cube
// (the largest |coordinate| of the offset from it below near, cube_map.h). The check of objects
// between texel centres is one map's and is not made per cube face.
void pointLightWarnings(const Scene& scene, std::vector<std::string>& out) {
  const Light& l = scene.light;
  for (const auto& o : scene.objects) {
    std::size_t clipped = 0;
    for (const auto& p : o.mesh.positions) clipped += cubeDepth(glm::dvec3(p) - l.position) < l.nearPlane;
    if (clipped == 0) continue;
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "%zu of the %zu vertices of object \"%s\" lie inside the point light's near cube (%.6g world "
                  "units each way): the light does not see them, so what they occlude is lit (give /light/near)",
                  clipped, o.mesh.positions.size(), o.name.c_str(), l.nearPlane);
    out.push_back(buf);
  }
}

}  // namespace

std::vector<std::string> captureWarnings(const Scene& scene, int width, int height, CaptureMode capture,
                                         int hiddenSearchGrid) {
  std::vector<std::string> out;
  if (capture == CaptureMode::Back) {
    const std::vector<std::string> open = openMeshObjects(scene);
    if (!open.empty()) {
      std::string names;
      for (const auto& n : open) names += (names.empty() ? "\"" : ", \"") + n + "\"";
      out.push_back("back capture lets light through the openings of the open mesh" + std::string(open.size() > 1 ? "es " : " ") +
                    names + ": their shadows leak; front or midpoint capture (--capture front|midpoint) records them");
    }
  }
  if (scene.light.type == LightType::Point) {
    pointLightWarnings(scene, out);
    return out;
  }
  const DepthMap probe = makeDepthMap(scene.light, width, height, capture);
  const glm::dmat4 toClip = probe.lightProjection * probe.lightView;
  const std::size_t before = out.size();
  for (const auto& o : scene.objects) {
    if (o.mesh.positions.empty()) continue;
    if (const std::size_t clipped = nearClipped(probe, toClip, o.mesh)) {
      char buf[480];
      std::snprintf(buf, sizeof buf,
                    "%zu of the %zu vertices of object \"%s\" lie nearer to the light than its near plane (%.6g "
                    "world units): the light does not see them, so what they occlude is lit (give /light/near, or "
                    "check the scene for an outlier vertex that stretches the fitted planes)",
                    clipped, o.mesh.positions.size(), o.name.c_str(), probe.nearPlane);
      out.push_back(buf);
    }
    glm::dvec2 lo(1e300), hi(-1e300);
    bool judged = true;
    for (const auto& p : o.mesh.positions) {
      const glm::dvec4 c = toClip * glm::dvec4(glm::dvec3(p), 1.0);
      if (!(c.w > 0.0)) {
        judged = false;  // behind a spot light's apex plane
        break;
      }
      const glm::dvec2 t = probe.texelOf(glm::dvec3(p));
      lo = glm::min(lo, t), hi = glm::max(hi, t);
    }
    if (!judged) continue;
    // Entirely outside the map: not this check's business (the frustum does not light it).
    if (hi.x < -0.5 || hi.y < -0.5 || lo.x > width - 0.5 || lo.y > height - 0.5) continue;
    // A texel centre (integer coordinates), or a node of the sub-grid that searches for hidden
    // surfaces (multiples of 1/S), inside [lo, hi] on both axes?
    const double s = std::max(1, hiddenSearchGrid);
    const bool coversX = std::floor(hi.x * s) >= std::ceil(lo.x * s), coversY = std::floor(hi.y * s) >= std::ceil(lo.y * s);
    if (coversX && coversY) continue;
    const double span = std::max(1e-9, std::min(hi.x - lo.x, hi.y - lo.y));
    const double need = std::ceil(std::max(width, height) / (span * s));
    char remedy[160];
    if (need <= kMaxDepthMapSide)
      std::snprintf(remedy, sizeof remedy, "a map of about %.0f x %.0f or more would catch it", need, need);
    else  // an object seen edge-on, or far smaller than the light's window
      std::snprintf(remedy, sizeof remedy,
                    "no map up to %d x %d would catch it: the light sees it edge-on or it is far smaller than the "
                    "light's frustum",
                    kMaxDepthMapSide, kMaxDepthMapSide);
    char grid[96] = "";
    if (hiddenSearchGrid > 1)
      std::snprintf(grid, sizeof grid, " and no node of the %d x %d sub-grid that searches for it", hiddenSearchGrid,
                    hiddenSearchGrid);
    char buf[560];
    std::snprintf(buf, sizeof buf,
                  "object \"%s\" spans %.2g x %.2g texels of the %d x %d light map and covers no texel centre%s: it "
                  "casts no shadow at this resolution (%s)",
                  o.name.c_str(), hi.x - lo.x, hi.y - lo.y, width, height, grid, remedy);
    out.push_back(buf);
  }
  // Nothing in the frustum at all, and no object named above as clipped by the near plane.
  if (out.size() == before) {
    std::string w = detail::emptyViewWarning(toClip, scene.objects, "inside the light's frustum", probe.nearPlane,
                                             probe.farPlane,
                                             "the depth map sees nothing, the volume is empty and nothing is shadowed "
                                             "(check where the light points, and /light/near and /light/far)");
    if (!w.empty()) out.push_back(std::move(w));
  }
  return out;
}

}  // namespace shadowvol

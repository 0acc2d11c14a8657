#include "shadowvol/capture_warnings.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "shadowvol/capture_choice.h"
#include "shadowvol/cube_map.h"
#include "clip_volume.h"

namespace shadowvol {
namespace {

// A W x H map of `light` for its matrices and planes only: no depths (texelOf and viewDepthOf read
// none), so judging a 16384^2 map, or six cube faces per object, allocates nothing.
DepthMap probeMap(const Light& light, int width, int height, CaptureMode capture) {
  DepthMap map = makeDepthMap(light, 1, 1, capture);
  map.width = width, map.height = height;
  map.lightProjection = lightProjection(light, double(width) / double(height));
  return map;
}

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

// Whether some triangle of `mesh` has area in the map's texel plane (its image is not a segment or
// a point): a mesh seen exactly edge-on, or one of zero-area triangles only, covers nothing. Judged
// by the sine of the image's angle at a corner (over 1e-9), not by its area in texels, which a
// triangle far smaller than a texel lacks however squarely it is seen (a probe's finding: a
// sphere under a directional window of 1e12 was said to have no area).
bool hasAreaInView(const DepthMap& probe, const TriangleMesh& mesh) {
  for (const auto& t : mesh.triangles) {
    const glm::dvec2 a = probe.texelOf(glm::dvec3(mesh.positions[t[0]])),
                     b = probe.texelOf(glm::dvec3(mesh.positions[t[1]])),
                     c = probe.texelOf(glm::dvec3(mesh.positions[t[2]]));
    const double cross = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (std::abs(cross) > 1e-9 * glm::length(b - a) * glm::length(c - a)) return true;
  }
  return false;
}

// Whether a node (multiples of 1 / s in texel coordinates) in the box [lo, hi] lies inside the image
// of a triangle of `mesh` (edges included; every vertex in front of the light): each triangle's
// nodes, those inside its own image's box, are tested, so a long thin object along a diagonal (its
// box over many nodes, its image between them: a rod) is judged by its image, as a small one is (a
// twenty-second probe's sphere beside a 179-degree spot's apex spanned 1.3 texels around a texel
// corner, its box over four centres, its disk over none, and went unwarned). The first node inside
// ends the search; after kMaxNodeTests tests without one (huge slivers over a fine map) the object
// is taken as covered, so the check stays bounded.
bool coversNode(const DepthMap& probe, const TriangleMesh& mesh, glm::dvec2 lo, glm::dvec2 hi, double s) {
  constexpr double kMaxNodeTests = 1 << 22;
  if (std::floor(hi.x * s) < std::ceil(lo.x * s) || std::floor(hi.y * s) < std::ceil(lo.y * s)) return false;
  const auto side = [](glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); };
  double tests = 0.0;
  for (const auto& t : mesh.triangles) {
    const glm::dvec2 a = probe.texelOf(glm::dvec3(mesh.positions[t[0]]));
    const glm::dvec2 b = probe.texelOf(glm::dvec3(mesh.positions[t[1]]));
    const glm::dvec2 c = probe.texelOf(glm::dvec3(mesh.positions[t[2]]));
    const glm::dvec2 tlo = glm::max(lo, glm::min(a, glm::min(b, c))), thi = glm::min(hi, glm::max(a, glm::max(b, c)));
    const double i0 = std::ceil(tlo.x * s), i1 = std::floor(thi.x * s), j0 = std::ceil(tlo.y * s), j1 = std::floor(thi.y * s);
    if (i1 < i0 || j1 < j0) continue;
    for (double i = i0; i <= i1; ++i)
      for (double j = j0; j <= j1; ++j) {
        const glm::dvec2 p(i / s, j / s);
        const double u = side(a, b, p), v = side(b, c, p), w = side(c, a, p);
        if ((u >= 0 && v >= 0 && w >= 0) || (u <= 0 && v <= 0 && w <= 0)) return true;
        if (++tests > kMaxNodeTests) return true;
      }
  }
  return false;
}

// The warning for an object of `probe`'s map (its light, W x H) that covers no texel centre, nor
// a node of the S x S sub-grid that searches for hidden surfaces (S = hiddenSearchGrid > 1), or
// whose triangles have no area in the light's view (the remedy names maps up to maxSide a side);
// "" when it covers one, lies wholly outside
// the map (the frustum does not light it: not this check's business) or partly behind a spot
// light's apex plane (not judged).
std::string coverageWarning(const DepthMap& probe, const SceneObject& o, int hiddenSearchGrid,
                            const std::string& mapName = "light map", int maxSide = kMaxWindowSide) {
  const glm::dmat4 toClip = probe.lightProjection * probe.lightView;
  const int width = probe.width, height = probe.height;
  glm::dvec2 lo(1e300), hi(-1e300);
  for (const auto& p : o.mesh.positions) {
    const glm::dvec4 c = toClip * glm::dvec4(glm::dvec3(p), 1.0);
    if (!(c.w > 0.0)) return "";
    const glm::dvec2 t = probe.texelOf(glm::dvec3(p));
    lo = glm::min(lo, t), hi = glm::max(hi, t);
  }
  if (hi.x < -0.5 || hi.y < -0.5 || lo.x > width - 0.5 || lo.y > height - 0.5) return "";
  // A texel centre (integer coordinates), or a sub-grid node (multiples of 1/S), inside [lo, hi]
  // on both axes, and a triangle with area to hold it?
  const double s = std::max(1, hiddenSearchGrid);
  const bool area = hasAreaInView(probe, o.mesh);
  if (area && coversNode(probe, o.mesh, lo, hi, s)) return "";
  if (!area)
    return "object \"" + o.name + "\" has no area in the light's view (its triangles are seen exactly edge-on, or " +
           "have zero area): it casts no shadow, whatever the resolution";
  const double span = std::max(1e-9, std::min(hi.x - lo.x, hi.y - lo.y));
  double need = std::ceil(std::max(width, height) / (span * s));
  if (span * s >= 1.0)  // its box spans nodes that its image misses: a finer map than this one, at least
    need = std::max(need, 2.0 * std::max(width, height));
  char remedy[160];
  if (need <= maxSide)
    std::snprintf(remedy, sizeof remedy, "a map of about %.0f x %.0f or more would catch it", need, need);
  else  // far smaller than the light's window
    std::snprintf(remedy, sizeof remedy,
                  "no map up to %d x %d would catch it: the light sees it edge-on or it is far smaller than the "
                  "light's frustum",
                  maxSide, maxSide);
  char grid[96] = "";
  if (hiddenSearchGrid > 1)
    std::snprintf(grid, sizeof grid, " and no node of the %d x %d sub-grid that searches for it", hiddenSearchGrid,
                  hiddenSearchGrid);
  char buf[560];
  std::snprintf(buf, sizeof buf,
                "object \"%s\" spans %.2g x %.2g texels of the %d x %d %s and covers no texel centre%s: it "
                "casts no shadow at this resolution (%s)",
                o.name.c_str(), hi.x - lo.x, hi.y - lo.y, width, height, mapName.c_str(), grid, remedy);
  return buf;
}

// The most objects a warning of one kind names; the rest are counted in one more line (a probe's
// 30,000 small boxes gave 12,534 lines, one per box that covers no texel centre).
constexpr std::size_t kMaxNamedObjects = 20;

// Appends `named` (one warning per object) to `out`, the first kMaxNamedObjects of them, and one
// line counting the rest, which `what` describes ("cover no texel centre").
void appendCapped(std::vector<std::string>& out, std::vector<std::string> named, const char* what) {
  const std::size_t shown = std::min(named.size(), kMaxNamedObjects);
  out.insert(out.end(), std::make_move_iterator(named.begin()), std::make_move_iterator(named.begin() + std::ptrdiff_t(shown)));
  if (named.size() > shown)
    out.push_back("... and " + std::to_string(named.size() - shown) + " more objects " + what + " (the first " +
                  std::to_string(shown) + " are named above)");
}

// A point light's cube sees every direction; what it misses is what lies inside its near cube
// (the largest |coordinate| of the offset from it below near, cube_map.h), and an object between
// the texel centres of the N x N face that holds all of it (one over several faces is larger than
// a texel of any of them, and is not judged).
void pointLightWarnings(const Scene& scene, int n, CaptureMode capture, int hiddenSearchGrid,
                        std::vector<std::string>& out) {
  const Light& l = scene.light;
  std::vector<std::string> uncovered, clippedObjects;
  for (const auto& o : scene.objects) {
    if (o.mesh.positions.empty()) continue;
    const int face = cubeLookup(glm::dvec3(o.mesh.positions[0]) - l.position, n).face;
    bool oneFace = true;
    for (const auto& p : o.mesh.positions) oneFace = oneFace && cubeLookup(glm::dvec3(p) - l.position, n).face == face;
    if (oneFace) {
      const DepthMap probe = probeMap(cubeFaceLight(l, face), n, n, capture);
      const std::string name = std::string(cubeFaceName(face)) + " face of the light's cube map";
      // The six faces are held to one map's limit together (cube_map.cpp).
      if (std::string w = coverageWarning(probe, o, hiddenSearchGrid, name, kMaxWindowSide / kCubeFaces); !w.empty())
        uncovered.push_back(std::move(w));
    }
    std::size_t clipped = 0;
    for (const auto& p : o.mesh.positions) clipped += cubeDepth(glm::dvec3(p) - l.position) < l.nearPlane;
    if (clipped == 0) continue;
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "%zu of the %zu vertices of object \"%s\" lie inside the point light's near cube (%.6g world "
                  "units each way): the light does not see them, so what they occlude is lit (give /light/near)",
                  clipped, o.mesh.positions.size(), o.name.c_str(), l.nearPlane);
    clippedObjects.push_back(buf);
  }
  appendCapped(out, std::move(clippedObjects), "have vertices inside the point light's near cube");
  appendCapped(out, std::move(uncovered), "cover no texel centre of their cube face");
}

}  // namespace

std::vector<std::string> captureWarnings(const Scene& scene, int width, int height, CaptureMode capture,
                                         int hiddenSearchGrid) {
  std::vector<std::string> out;
  if (needsBackFace(capture)) {
    const std::vector<std::string> open = openMeshObjects(scene);
    if (!open.empty()) {
      std::string names;
      for (const auto& n : open) names += (names.empty() ? "\"" : ", \"") + n + "\"";
      out.push_back(std::string(toString(capture)) + " capture lets light through the openings of the open mesh" +
                    std::string(open.size() > 1 ? "es " : " ") +
                    names + ": their shadows leak; front or midpoint capture (--capture front|midpoint) records them");
    }
  }
  if (scene.light.type == LightType::Point) {
    pointLightWarnings(scene, width, capture, hiddenSearchGrid, out);
    return out;
  }
  const DepthMap probe = probeMap(scene.light, width, height, capture);
  const glm::dmat4 toClip = probe.lightProjection * probe.lightView;
  const std::size_t before = out.size();
  std::vector<std::string> uncovered, clippedObjects;
  for (const auto& o : scene.objects) {
    if (o.mesh.positions.empty()) continue;
    if (const std::size_t clipped = nearClipped(probe, toClip, o.mesh)) {
      char buf[480];
      std::snprintf(buf, sizeof buf,
                    "%zu of the %zu vertices of object \"%s\" lie nearer to the light than its near plane (%.6g "
                    "world units): the light does not see them, so what they occlude is lit (give /light/near, or "
                    "check the scene for an outlier vertex that stretches the fitted planes)",
                    clipped, o.mesh.positions.size(), o.name.c_str(), probe.nearPlane);
      clippedObjects.push_back(buf);
    }
    if (std::string w = coverageWarning(probe, o, hiddenSearchGrid); !w.empty()) uncovered.push_back(std::move(w));
  }
  appendCapped(out, std::move(clippedObjects), "have vertices nearer to the light than its near plane");
  appendCapped(out, std::move(uncovered), "cover no texel centre");
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

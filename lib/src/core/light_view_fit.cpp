// fitLightToView and receiverTexelSize: the light's frustum narrowed to what the camera can see
// (the reference text on cascaded shadow maps calls it fitting to the view rather than to the
// scene). Everything is computed in the light's image plane: tangents x/-z, y/-z of light-view
// points for a spot light, light-view x and y for a directional one.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "frustum_depth_range.h"
#include "scene_fit_planes.h"
#include "shadowvol/eye_plane_split.h"
#include "shadowvol/cube_map.h"
#include "shadowvol/scene.h"

namespace shadowvol {
namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;

/// World points whose convex hull is the part of the scene's bounds inside the camera's frustum.
std::vector<glm::dvec3> cameraVisiblePart(const Scene& s) {
  const detail::ViewFrustum f = detail::cameraFrustum(s.camera);
  const glm::dmat4 toWorld = glm::inverse(f.view);
  std::vector<glm::dvec3> world;
  for (const glm::dvec3& p : detail::boxPartInFrustum(s.bounds(), f)) world.emplace_back(toWorld * glm::dvec4(p, 1.0));
  return world;
}

/// A light-view point in the light's image plane; nullopt at or behind a spot light's eye plane.
std::optional<glm::dvec2> imagePoint(const Light& l, const glm::dvec3& view) {
  if (l.type == LightType::Directional) return glm::dvec2(view.x, view.y);
  if (!(-view.z > 1e-12 * glm::length(view))) return std::nullopt;
  return glm::dvec2(view.x, view.y) / -view.z;
}

double cross(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

/// Convex hull, counter-clockwise (Andrew's monotone chain; ties by x then y, so deterministic).
std::vector<glm::dvec2> convexHull(std::vector<glm::dvec2> p) {
  std::sort(p.begin(), p.end(), [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<glm::dvec2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

/// The part of a convex polygon inside the square |x|, |y| <= h (Sutherland-Hodgman, 4 planes).
std::vector<glm::dvec2> clipToSquare(std::vector<glm::dvec2> poly, double h) {
  for (int k = 0; k < 4 && !poly.empty(); ++k) {
    auto side = [&](const glm::dvec2& p) { return (k < 2 ? p.x : p.y) * (k % 2 ? -1.0 : 1.0) - h; };
    std::vector<glm::dvec2> out;
    for (std::size_t a = 0; a < poly.size(); ++a) {
      const glm::dvec2 &p = poly[a], &q = poly[(a + 1) % poly.size()];
      const double sp = side(p), sq = side(q);
      if (sp <= 0.0) out.push_back(p);
      if ((sp < 0.0 && sq > 0.0) || (sp > 0.0 && sq < 0.0)) out.push_back(p + (sp / (sp - sq)) * (q - p));
    }
    poly = std::move(out);
  }
  return poly;
}

/// The light's window: tan(fov / 2) for a spot light, the half extent for a directional one.
double windowOf(const Light& l) {
  return l.type == LightType::Spot ? std::tan(0.5 * l.fovYDegrees / kDegrees) : l.halfExtent;
}

/// The camera-visible, lit part of the bounds in the light's image: a convex polygon inside the
/// light's window. Empty when the camera sees none of it; nullopt when it reaches behind a spot
/// light's eye plane (its image is unbounded there).
std::optional<std::vector<glm::dvec2>> litFootprint(const Scene& s) {
  const glm::dmat4 view = lightView(s.light);
  std::vector<glm::dvec2> image;
  for (const glm::dvec3& p : cameraVisiblePart(s)) {
    const auto q = imagePoint(s.light, glm::dvec3(view * glm::dvec4(p, 1.0)));
    if (!q) return std::nullopt;
    image.push_back(*q);
  }
  return clipToSquare(convexHull(std::move(image)), windowOf(s.light));
}

/// Largest |x| and |y| (tangents) of the footprint seen along a spot light's new axis.
double spotWindowAlong(const Light& before, const Light& after, const std::vector<glm::dvec2>& footprint) {
  const glm::dmat3 toAfter = glm::dmat3(lightView(after)) * glm::transpose(glm::dmat3(lightView(before)));
  double t = 0.0;
  for (const glm::dvec2& q : footprint) {
    const glm::dvec3 w = toAfter * glm::dvec3(q, -1.0);
    if (!(-w.z > 0.0)) return HUGE_VAL;
    t = std::max({t, std::abs(w.x) / -w.z, std::abs(w.y) / -w.z});
  }
  return t;
}

/// Whether the pyramid of half-window t along `after` lies inside the one of `before`.
bool spotInside(const Light& before, const Light& after, double t) {
  const glm::dmat3 toBefore = glm::dmat3(lightView(before)) * glm::transpose(glm::dmat3(lightView(after)));
  const double t0 = windowOf(before) * (1.0 + 1e-12);
  for (int k = 0; k < 4; ++k) {
    const glm::dvec3 w = toBefore * glm::dvec3(k & 1 ? t : -t, k & 2 ? t : -t, -1.0);
    if (!(-w.z > 0.0) || std::abs(w.x) > t0 * -w.z || std::abs(w.y) > t0 * -w.z) return false;
  }
  return true;
}

/// The spot light re-aimed at the footprint's bounding box and narrowed; if that pyramid would
/// leave the old one, narrowed around the old axis instead. Returns the new half-window tangent.
double fitSpot(Light& l, const std::vector<glm::dvec2>& footprint, double keep) {
  glm::dvec2 lo(HUGE_VAL), hi(-HUGE_VAL);
  for (const glm::dvec2& q : footprint) lo = glm::min(lo, q), hi = glm::max(hi, q);
  const Light before = l;
  Light aimed = l;
  const glm::dvec3 axisView = glm::normalize(glm::dvec3(0.5 * (lo + hi), -1.0));
  aimed.direction = glm::normalize(glm::transpose(glm::dmat3(lightView(before))) * axisView);
  const double tAimed = spotWindowAlong(before, aimed, footprint) * keep;
  const double tCentred = std::max({std::abs(lo.x), std::abs(hi.x), std::abs(lo.y), std::abs(hi.y)}) * keep;
  if (tAimed < tCentred && spotInside(before, aimed, tAimed)) {
    l = aimed;
    return tAimed;
  }
  return tCentred;
}

/// The directional window shifted to the footprint's bounding box and shrunk, inside the old one.
double fitDirectional(Light& l, const std::vector<glm::dvec2>& footprint, double keep) {
  glm::dvec2 lo(HUGE_VAL), hi(-HUGE_VAL);
  for (const glm::dvec2& q : footprint) lo = glm::min(lo, q), hi = glm::max(hi, q);
  const double h0 = l.halfExtent;
  const double h = std::min(h0, 0.5 * std::max(hi.x - lo.x, hi.y - lo.y) * keep);
  const glm::dvec2 c = glm::clamp(0.5 * (lo + hi), glm::dvec2(-(h0 - h)), glm::dvec2(h0 - h));
  l.position += glm::transpose(glm::dmat3(lightView(l))) * glm::dvec3(c, 0.0);
  return h;
}

std::string describeWindow(const Light& l, double before, double after) {
  char buf[200];
  if (l.type == LightType::Spot)
    std::snprintf(buf, sizeof buf, "spot light fitted to the view: opening %.4g -> %.4g degrees", before, after);
  else
    std::snprintf(buf, sizeof buf, "directional light fitted to the view: half extent %.6g -> %.6g", before, after);
  return buf;
}

}  // namespace

const char* toString(LightFit fit) { return nameIn(kLightFitNames, fit); }

bool parseLightFit(const std::string& text, LightFit& fit) { return parseIn(kLightFitNames, text, fit); }

LightFitResult fitLightToView(Scene& scene, int mapResolution) {
  LightFitResult r;
  Light& l = scene.light;
  if (l.type == LightType::Point) {
    r.note = "light not fitted to the view: a point light's six faces cover every direction";
    return r;
  }
  const bool spot = l.type == LightType::Spot;
  r.windowBefore = r.windowAfter = spot ? l.fovYDegrees : l.halfExtent;
  const auto footprint = litFootprint(scene);
  if (!footprint) {
    r.note = "light not fitted to the view: the part of the scene the camera sees reaches behind the spot light";
    return r;
  }
  if (footprint->size() < 3) {
    r.note = "light not fitted to the view: the camera sees none of the lit scene";
    return r;
  }
  // 2 texels to spare each side: the outermost ring of the map lies on the far plane.
  const int n = std::max(mapResolution, 8);
  const double keep = double(n) / double(n - 4);
  Light fitted = l;
  const double w = spot ? fitSpot(fitted, *footprint, keep) : fitDirectional(fitted, *footprint, keep);
  const double minWindow = spot ? std::tan(0.5 * 0.01 / kDegrees) : 1e-9 * std::max(l.halfExtent, 1e-300);
  if (!(w < 0.99 * windowOf(l)) || !(w > minWindow)) {
    r.note = "light not fitted to the view: what the camera sees fills the light's frustum already";
    return r;
  }
  r.reaimed = spot ? fitted.direction != l.direction : fitted.position != l.position;
  if (spot) fitted.fovYDegrees = 2.0 * std::atan(w) * kDegrees;
  else fitted.halfExtent = w;
  l = fitted;
  r.changed = true;
  r.windowAfter = spot ? l.fovYDegrees : l.halfExtent;
  detail::refitLightPlanes(scene);
  splitSceneAcrossEyePlanes(scene, kMaxSceneTriangles);
  r.note = describeWindow(l, r.windowBefore, r.windowAfter) + (r.reaimed ? (spot ? ", re-aimed" : ", shifted") : "");
  return r;
}

namespace {

std::optional<std::pair<double, double>> receiverTexelSizeOf(const Scene& scene, const Light& l, int mapResolution) {
  const glm::dmat4 view = lightView(l);
  const double window = windowOf(l);
  // Vertices of the camera-visible part inside the light's frustum, and of the lit part inside
  // the camera's: between them they reach the depths of the part both see.
  std::vector<double> depths;
  auto inLight = [&](const glm::dvec3& world) {
    const glm::dvec3 v(view * glm::dvec4(world, 1.0));
    const auto q = imagePoint(l, v);
    if (q && std::abs(q->x) <= window * (1 + 1e-9) && std::abs(q->y) <= window * (1 + 1e-9)) depths.push_back(-v.z);
  };
  for (const glm::dvec3& p : cameraVisiblePart(scene)) inLight(p);
  const detail::ViewFrustum lf = detail::lightFrustum(l);
  const detail::ViewFrustum cf = detail::cameraFrustum(scene.camera);
  const glm::dmat4 lightToWorld = glm::inverse(lf.view);
  for (const glm::dvec3& p : detail::boxPartInFrustum(scene.bounds(), lf)) {
    const glm::dvec3 c(cf.view * lightToWorld * glm::dvec4(p, 1.0));
    if (-c.z > 0.0 && std::abs(c.x) <= cf.tanX * -c.z * (1 + 1e-9) && std::abs(c.y) <= cf.tanY * -c.z * (1 + 1e-9))
      depths.push_back(-p.z);
  }
  if (depths.empty()) return std::nullopt;
  const double n = double(std::max(mapResolution, 1));
  if (l.type == LightType::Directional) return std::pair{2.0 * window / n, 2.0 * window / n};
  const auto [lo, hi] = std::minmax_element(depths.begin(), depths.end());
  return std::pair{2.0 * window * std::max(*lo, l.nearPlane) / n, 2.0 * window * std::min(*hi, l.farPlane) / n};
}

}  // namespace

std::optional<std::pair<double, double>> receiverTexelSize(const Scene& scene, int mapResolution) {
  if (scene.light.type != LightType::Point) return receiverTexelSizeOf(scene, scene.light, mapResolution);
  std::optional<std::pair<double, double>> r;  // a point light: over its six faces
  for (int f = 0; f < kCubeFaces; ++f)
    if (const auto t = receiverTexelSizeOf(scene, cubeFaceLight(scene.light, f), mapResolution))
      r = r ? std::pair{std::min(r->first, t->first), std::max(r->second, t->second)} : *t;
  return r;
}

}  // namespace shadowvol

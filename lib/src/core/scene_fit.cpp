// fitLightAndCamera: the light's and the camera's near and far planes from the scene (and a
// directional light's position and window), and given planes tightened to what the scene needs.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/squared_distance_3.h>
#include <glm/geometric.hpp>

#include "frustum_depth_range.h"
#include "scene_fit_planes.h"
#include "scene_fit_range.h"
#include "shadowvol/cube_map.h"
#include "shadowvol/scene.h"

namespace shadowvol {
namespace {

using detail::depthRange;

// Euclidean distance from p to the nearest triangle of the scene (CGAL's point-triangle distance
// in double; degenerate triangles count as their points and edges).
double nearestGeometry(const Scene& scene, const glm::dvec3& p) {
  using K = CGAL::Simple_cartesian<double>;
  const K::Point_3 q(p.x, p.y, p.z);
  double best = 1e300;
  for (const auto& o : scene.objects) {
    const auto& P = o.mesh.positions;
    auto pt = [&](std::uint32_t k) { return K::Point_3(P[k].x, P[k].y, P[k].z); };
    for (const auto& t : o.mesh.triangles) {
      const K::Triangle_3 tri(pt(t[0]), pt(t[1]), pt(t[2]));
      const double d2 = tri.is_degenerate()
                            ? std::min({CGAL::squared_distance(q, K::Segment_3(tri[0], tri[1])),
                                        CGAL::squared_distance(q, K::Segment_3(tri[1], tri[2])),
                                        CGAL::squared_distance(q, K::Segment_3(tri[0], tri[2]))})
                            : CGAL::squared_distance(q, tri);
      best = std::min(best, d2);
    }
  }
  return std::sqrt(best);
}

// The nearest view depth a frustum of vertical opening fovY and aspect can see of geometry at
// least `distance` away: distance times the cosine of the half-diagonal angle.
double nearestViewDepth(double distance, double fovYDegrees, double aspect) {
  const double t = std::tan(0.5 * fovYDegrees * std::numbers::pi / 180.0) * std::sqrt(1.0 + std::max(aspect, 1.0) * std::max(aspect, 1.0));
  return distance / std::sqrt(1.0 + t * t);
}

// The near plane of a perspective view whose far plane is `far` and whose view of the bounds
// starts at `boundsNear`. When the bounds reach (almost) behind the eye, the bounds say nothing:
// then 99 % of the nearest view depth of the actual geometry, kept to at most far * 1e-3 (the
// bounds' floor) and at least far * 1e-7 (float depth resolution).
double perspectiveNear(double boundsNear, double far, const Scene& scene, const glm::dvec3& eye, double fovY,
                       double aspect) {
  if (boundsNear >= far * 1e-3) return boundsNear;
  const double geometry = 0.99 * nearestViewDepth(nearestGeometry(scene, eye), fovY, aspect);
  return std::max(std::min({far * 1e-3, std::max(geometry, boundsNear)}), far * 1e-7);
}

// "0.0123 (given 1e+06)" for the notes, with as many digits as it takes to tell the two apart (a
// far plane pulled in by 20 units at 1e7 read "1e+07 (given 1e+07)").
std::string planeChange(double used, double given) {
  char buf[96];
  for (int digits = 6; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g (given %.*g)", digits, used, digits, given);
    char a[40], b[40];
    std::snprintf(a, sizeof a, "%.*g", digits, used);
    std::snprintf(b, sizeof b, "%.*g", digits, given);
    if (std::string_view(a) != std::string_view(b)) break;
  }
  return buf;
}

// The reason of every note of a moved plane but one (fitLightAndCamera appends it).
constexpr const char* kMovedInward = "moved to the scene's depth range; planes beyond it capture nothing more and only "
                                     "cost depth precision";

// A given far plane the fit moved, with the value it ended at, inserted at notes[at] (the far
// plane's note comes before the near plane's). A far pulled in to the scene's depth range can be
// pushed out again past a given near beyond the scene: the note names the plane used, and why.
void noteMovedFar(const char* pointer, double givenFar, double used, std::size_t at, std::vector<std::string>& notes) {
  if (!(givenFar > 0.0) || used == givenFar) return;
  std::string note = std::string(pointer) + ": " + planeChange(used, givenFar) + ": ";
  note += used > givenFar ? "moved out past the near plane, which it must exceed" : kMovedInward;
  notes.insert(notes.begin() + std::ptrdiff_t(at), std::move(note));
}

// A directional light's depth runs from the plane through its position, in float on the GPU and
// in Embree: a position further than this many radii before the scene's centre leaves fewer than
// about 2^15 float steps across the scene's depth (a thirteenth probe's light 1e7 units away, over a
// scene 20 deep: an empty volume, without a word). Its shadows do not depend on that distance.
constexpr double kMaxDirectionalDistanceRadii = 256.0;

// Moves a given directional light's position along its direction to where the fit would place it
// (1.1 radii before the bounds' centre) when it lies further back than kMaxDirectionalDistanceRadii.
// Given near and far planes are distances from the position: they move back by as much, so they
// stay where they were in the scene (a far plane that would then lie behind the position ends before
// the scene: the light is left for the check that refuses it). Notes what moved.
void moveFarDirectionalPosition(Light& l, const Bounds3& b, double radius, std::vector<std::string>& notes) {
  const double behind = glm::dot(b.center() - l.position, l.direction);
  if (l.fitPosition || !(behind > kMaxDirectionalDistanceRadii * radius)) return;
  const double shift = behind - 1.1 * radius;
  if (l.farPlane > 0.0 && !(l.farPlane - shift > 0.0)) return;
  const bool planes = l.nearPlane > 0.0 || l.farPlane > 0.0;
  l.position += l.direction * shift;
  if (l.farPlane > 0.0) l.farPlane -= shift;
  if (l.nearPlane > 0.0) l.nearPlane = std::max(l.nearPlane - shift, 0.0);  // behind the position: fitted
  char planesMoved[160] = "";
  if (planes)
    std::snprintf(planesMoved, sizeof planesMoved,
                  " (its given planes with it, where they were: near %.6g, far %.6g from there; 0 = fitted)",
                  l.nearPlane, l.farPlane);
  char buf[480];
  std::snprintf(buf, sizeof buf,
                "/light/position: moved %.6g units along the light's direction, to 1.1 radii before the scene's "
                "centre%s: a directional light's shadows do not depend on its distance, and float depth cannot "
                "resolve a scene %.3g deep %.3g away",
                shift, planesMoved, 2.0 * radius, behind);
  notes.push_back(buf);
}

// How far across its direction a given directional light may stand from the axis through the
// scene's centre, in scene radii, before the fit moves it onto that axis (its fitted window, centred
// on the position, is at most 0.1 % wider than it need be).
constexpr double kMaxDirectionalOffAxisRadii = 1e-3;

// Moves a given directional light's position across its direction onto the axis through the
// bounds' centre when its extent is left to the fit: the window is centred on the position, so a
// light off to the side got a window as wide as its offset (a probe's sun at [0, 1e5, 0] shining
// down at a slant over a scene 14 wide: an extent of 11,347 and an empty volume). Its shadows do not
// depend on where across its direction it stands; its distance along it, and so its given near and
// far planes, stay. A given extent is the user's window and keeps the position. Notes what moved.
void centreDirectionalWindow(Light& l, const Bounds3& b, double radius, std::vector<std::string>& notes) {
  if (l.fitPosition || l.halfExtent > 0.0) return;
  const glm::dvec3 toCentre = b.center() - l.position;
  const glm::dvec3 across = toCentre - l.direction * glm::dot(toCentre, l.direction);
  const double offset = glm::length(across);
  if (!(offset > kMaxDirectionalOffAxisRadii * radius)) return;
  const double before = detail::viewReach(b, lightView(l));
  l.position += across;
  const double after = detail::viewReach(b, lightView(l));
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "/light/position: moved %.6g units across the light's direction, onto the axis through the "
                "scene's centre: the fitted window (extent) is centred on the position, and would have been %.3g "
                "times as wide; a directional light's shadows do not depend on where across its direction it stands",
                offset, after > 0.0 ? before / after : 1.0);
  notes.push_back(buf);
}

void fitDirectionalWindow(Scene& scene, const Bounds3& b, double radius, std::vector<std::string>& notes) {
  Light& l = scene.light;
  if (l.fitPosition) l.position = b.center() - l.direction * (radius * 1.1);
  centreDirectionalWindow(l, b, radius, notes);
  moveFarDirectionalPosition(l, b, radius, notes);
  if (l.halfExtent > 0.0) return;
  l.halfExtent = detail::viewReach(b, lightView(l)) * 1.02;  // 2% margin: the far-plane border ring stays off the geometry
}

// The light planes are fitted to the frustum of a square map (every map the CLI makes). A map
// wider than tall (W > H) sees further out in x, where geometry may lie beyond the fitted far
// plane: such a capture needs the light's near and far given (scene.h, fitLightAndCamera).
constexpr double kFittedLightAspect = 1.0;

// The depth range of the part of the objects' boxes the view sees (frustum_depth_range.h), with a margin
// of 1 % of the smaller of that part's depth extent and the scene's radius (that extent taken as
// at least 1e-3 of the far side's depth and 1e-6 of the radius, so a part seen edge-on still gets
// one), and the far plane just past it; when the view sees none of the bounds, their whole
// range, 1 % of the radius, and a far plane at least 1e-3 of the radius deep.
struct FittedRange {
  double lo, hi, margin, far;
  bool seen;  ///< the view sees part of an object's box (else the range is the whole box's)
};
FittedRange seenRange(const Bounds3& b, const std::vector<Bounds3>& objects, const detail::ViewFrustum& f,
                      const glm::dvec3& eye, const glm::dvec3& axis, double radius) {
  if (const auto seen = detail::depthRangeInFrustum(objects, f)) {
    const auto [lo, hi] = *seen;
    const double extent = hi - std::max(lo, 0.0);
    const double margin = 0.01 * std::min(radius, std::max({extent, 1e-3 * std::max(hi, 0.0), 1e-6 * radius}));
    return {lo, hi, margin, std::max(hi, 0.0) + margin, true};
  }
  const auto [lo, hi] = depthRange(b, eye, axis);
  return {lo, hi, 0.01 * radius, std::max(hi, 1e-3 * radius) + 0.01 * radius, false};
}

// Each object's box: the views' depth ranges are taken over these (the part of each that the view
// sees), not over the scene's box, which also holds the space between them.
std::vector<Bounds3> objectBoxes(const Scene& scene) {
  std::vector<Bounds3> boxes;
  for (const auto& o : scene.objects) boxes.push_back(o.mesh.bounds());
  return boxes;
}

// What the scene needs: from just before the near side of the part of the objects' boxes the light sees
// to just past its far side (FittedRange's margin each way). A given plane outside that range is
// moved to it: it would capture nothing more, and only spend depth precision (README "Scene
// files", Light, has the measurement).
void fitLightPlanes(Scene& scene, const Bounds3& b, double radius, std::vector<std::string>& notes) {
  Light& l = scene.light;
  const auto [lo, hi, margin, far, seen] =
      seenRange(b, objectBoxes(scene), detail::lightFrustum(l, kFittedLightAspect), l.position, l.direction, radius);
  const double givenFar = l.farPlane;
  const std::size_t farNote = notes.size();
  if (l.farPlane == 0.0 || l.farPlane > far) l.farPlane = far;
  // A directional light's view starts at the plane through its position: a fitted near never
  // goes behind it (loadScene warns when that plane cuts the scene).
  const double near = l.type == LightType::Directional
                          ? std::max(lo - margin, 0.0)
                          : perspectiveNear(lo - margin, l.farPlane, scene, l.position, l.fovYDegrees, kFittedLightAspect);
  const bool raise = l.nearPlane > 0.0 && l.nearPlane < near && near < l.farPlane;
  if (raise) notes.push_back("/light/near: " + planeChange(near, l.nearPlane) + ": " + kMovedInward);
  if (l.nearPlane == 0.0 || raise) l.nearPlane = near;
  if (l.farPlane <= l.nearPlane) l.farPlane = l.nearPlane + radius;
  noteMovedFar("/light/far", givenFar, l.farPlane, farNote, notes);
}

// A point light: one near and far plane for its six faces (cube_map.h), each face fitted as the
// 90-degree spot light it is; far is the farthest face's far side, near the nearest face's near,
// over the faces that see part of the bounds.
void fitPointLightPlanes(Scene& scene, const Bounds3& b, double radius, std::vector<std::string>& notes) {
  Light& l = scene.light;
  double far = 0.0;
  std::vector<double> nearSides;
  const std::vector<Bounds3> objects = objectBoxes(scene);
  for (int f = 0; f < kCubeFaces; ++f) {
    const Light face = cubeFaceLight(l, f);
    const detail::ViewFrustum frustum = detail::lightFrustum(face, 1.0);
    const auto [lo, hi, margin, faceFar, seen] = seenRange(b, objects, frustum, face.position, face.direction, radius);
    if (!seen) continue;
    far = std::max(far, faceFar);
    nearSides.push_back(lo - margin);
  }
  if (nearSides.empty()) return;  // bounds with no extent: nothing to fit to
  const double givenFar = l.farPlane;
  const std::size_t farNote = notes.size();
  if (l.farPlane == 0.0 || l.farPlane > far) l.farPlane = far;
  double near = l.farPlane;
  for (double side : nearSides) near = std::min(near, perspectiveNear(side, l.farPlane, scene, l.position, 90.0, 1.0));
  const bool raise = l.nearPlane > 0.0 && l.nearPlane < near && near < l.farPlane;
  if (raise) notes.push_back("/light/near: " + planeChange(near, l.nearPlane) + ": " + kMovedInward);
  if (l.nearPlane == 0.0 || raise) l.nearPlane = near;
  if (l.farPlane <= l.nearPlane) l.farPlane = l.nearPlane + radius;
  noteMovedFar("/light/far", givenFar, l.farPlane, farNote, notes);
}

void fitCameraPlanes(Scene& scene, const Bounds3& b, double radius, std::vector<std::string>& notes) {
  Camera& c = scene.camera;
  const glm::dvec3 axis = glm::normalize(c.target - c.eye);
  const double aspect = double(c.width) / double(c.height);
  // The camera keeps the scene's box (one box: a near plane no deeper than the box's nearest seen
  // point): a deeper near plane would widen the near rectangle that z-pass needs outside every
  // volume (frame.h), for depth precision the camera's test does not lack.
  const std::vector<Bounds3> box{b};
  const auto [lo, hi, margin, far, seen] = seenRange(b, box, detail::cameraFrustum(c), c.eye, axis, radius);
  const double givenFar = c.farPlane;
  const std::size_t farNote = notes.size();
  if (c.farPlane <= 0.0 || c.farPlane > far) c.farPlane = far;
  const double near = perspectiveNear(lo - margin, c.farPlane, scene, c.eye, c.fovYDegrees, aspect);
  // A given near is raised only when the part of the scene the camera sees lies wholly in front of it.
  const bool raise = c.nearPlane > 0.0 && lo > 0.0 && c.nearPlane < near && near < c.farPlane;
  if (raise) notes.push_back("/camera/near: " + planeChange(near, c.nearPlane) + ": " + kMovedInward);
  if (c.nearPlane <= 0.0 || raise) c.nearPlane = near;
  if (c.farPlane <= c.nearPlane) c.farPlane = c.nearPlane * 2.0 + radius;
  noteMovedFar("/camera/far", givenFar, c.farPlane, farNote, notes);
}

}  // namespace

namespace detail {

void refitLightPlanes(Scene& scene) {
  const Bounds3 b = scene.bounds();
  if (b.empty()) return;
  std::vector<std::string> notes;  // the planes only move inwards here: nothing to report
  if (scene.light.type == LightType::Point) fitPointLightPlanes(scene, b, std::max(b.radius(), 1e-6), notes);
  else fitLightPlanes(scene, b, std::max(b.radius(), 1e-6), notes);
}

}  // namespace detail

std::vector<std::string> fitLightAndCamera(Scene& scene) {
  std::vector<std::string> notes;
  const Bounds3 b = scene.bounds();
  if (b.empty()) return notes;
  const double radius = std::max(b.radius(), 1e-6);
  scene.light.direction = glm::normalize(scene.light.direction);
  if (scene.light.type == LightType::Directional) fitDirectionalWindow(scene, b, radius, notes);
  if (scene.light.type == LightType::Point) fitPointLightPlanes(scene, b, radius, notes);
  else fitLightPlanes(scene, b, radius, notes);
  fitCameraPlanes(scene, b, radius, notes);
  for (auto& n : notes) n = scene.source + ": " + n;
  return notes;
}

}  // namespace shadowvol

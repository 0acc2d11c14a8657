// camera-in-volume: the eye in the sphere's shadow (z-pass counts from the eye differ from z-fail
// there, so validate skips that comparison), under a spot, a directional and a point light, the eye
// at a point light, and eyes at the shadow's boundary, where the near plane cuts the volume.
#include <cmath>

#include "stress_configs.h"
#include "stress_scenes.h"

namespace shadowvol::stress {
namespace {

using nlohmann::json;

json withCamera(json scene, Vec3 eye, Vec3 target, double nearPlane = 0) {
  scene["camera"] = {{"eye", toJson(eye)}, {"target", toJson(target)}, {"fov", 60}, {"width", 640}, {"height", 480}};
  if (nearPlane > 0) scene["camera"]["near"] = nearPlane;
  return scene;
}

/// Eyes on the spot light's axis through the sphere centre, between the sphere and the ground:
/// inside the umbra by a margin of many texels.
void addEyesInShadow(std::vector<StressConfig>& out) {
  const Vec3 axis = kSphereCentre - kSpotPosition;  // the ground (y = 0) is at t = 9 / 7
  const std::pair<const char*, Vec3> looks[] = {{"along", axis},
                                                {"ground", {2, -2, -3}},
                                                {"sphere", -1.0 * axis},
                                                {"level", {1, 0, 0.3}},
                                                {"side", {0.4, 1, 0.2}}};
  for (const double t : {1.15, 1.2, 1.26})
    for (const auto& [lookName, look] : looks) {
      const Vec3 eye = kSpotPosition + t * axis;
      StressConfig c =
          makeConfig("camera-in-volume", "eye-in-shadow-spot-t" + numberName(t) + "-" + lookName,
                     "eye in the sphere's shadow (spot axis at t = " + numberName(t) + "), looking " + lookName,
                     withCamera(defaultSpotScene(), eye, eye + look));
      c.eyeInside = true;
      c.quick = (t == 1.2 && (std::string(lookName) == "along" || std::string(lookName) == "level"));
      out.push_back(std::move(c));
    }
  // A point light at the spot light's place: the eye in the sphere's shadow on the same axis (the
  // cube volume of the -y face, refined on the GPU as six face volumes), and at the light itself.
  json point = defaultSpotScene();
  point["light"] = json{{"type", "point"}, {"position", toJson(kSpotPosition)}};
  for (const double t : {1.15, 1.2, 1.26})
    for (const auto& [lookName, look] : {looks[0], looks[3]}) {
      const Vec3 eye = kSpotPosition + t * axis;
      StressConfig c =
          makeConfig("camera-in-volume", "eye-in-shadow-point-t" + numberName(t) + "-" + lookName,
                     "eye in the sphere's shadow under a point light (t = " + numberName(t) + "), looking " + lookName,
                     withCamera(point, eye, eye + look));
      c.eyeInside = true;
      c.quick = t == 1.2 && std::string(lookName) == "level";
      out.push_back(std::move(c));
    }
  for (const auto& [lookName, look] : {looks[0], looks[1]}) {
    const Vec3 eye = kSpotPosition + 1e-3 * normalized(axis);
    out.push_back(makeConfig("camera-in-volume", std::string("eye-at-point-light-") + lookName,
                             std::string("eye 1e-3 from a point light, looking ") + lookName,
                             withCamera(point, eye, eye + look)));
  }
  json down = defaultSpotScene();
  down["light"] = {{"type", "directional"}, {"direction", {0, -1, 0}}};
  const Vec3 eyes[] = {{0, 0.5, 0}, {0.3, 0.9, 0.2}};
  const Vec3 looks2[] = {{1, 0, 0.5}, {0.5, -1, 0.2}, {-0.2, 1, 0.3}};
  for (int e = 0; e < 2; ++e)
    for (int l = 0; l < 3; ++l) {
      StressConfig c =
          makeConfig("camera-in-volume", "eye-in-shadow-dir-" + std::to_string(e) + "-" + std::to_string(l),
                     "eye under the sphere, directional light straight down, view " + std::to_string(l),
                     withCamera(down, eyes[e], eyes[e] + looks2[l]));
      c.eyeInside = true;
      c.quick = e == 0 && l == 0;
      out.push_back(std::move(c));
    }
}

/// Eyes at the boundary of the sphere's shadow cone, 1.2 sphere distances from the light, inside
/// (delta < 0) or outside by less than a texel; looking across the volume or along its boundary,
/// with a fitted near plane or one that lies inside the volume.
void addEyesAtBoundary(std::vector<StressConfig>& out) {
  const Vec3 axis = kSphereCentre - kSpotPosition;
  const double distance = std::sqrt(dot(axis, axis));
  const double t = 1.2;
  const double coneRadius = t * distance * std::tan(std::asin(kSphereRadius / distance));
  const Vec3 centre = kSpotPosition + t * axis;
  const Vec3 side = normalized(cross(axis, {0, 1, 0}));
  for (const double delta : {-1e-2, -1e-3, 0.0, 1e-3, 1e-2})
    for (const bool across : {true, false})
      for (const double nearPlane : {0.0, 0.5}) {
        const Vec3 eye = centre + (coneRadius + delta) * side;
        const Vec3 target = across ? centre : eye + axis;
        StressConfig c = makeConfig("camera-in-volume",
                                    "eye-at-boundary-d" + numberName(delta) + (across ? "-across" : "-along") +
                                        (nearPlane > 0 ? "-near" + numberName(nearPlane) : ""),
                                    "eye " + numberName(delta) + " off the shadow boundary, looking " +
                                        (across ? "across" : "along") + " the volume" +
                                        (nearPlane > 0 ? ", near " + numberName(nearPlane) : ""),
                                    withCamera(defaultSpotScene(), eye, target, nearPlane));
        c.quick = across && nearPlane > 0 && (delta == 0.0 || delta == -1e-2);
        out.push_back(std::move(c));
      }
  // Outside by 0.3, looking across: the near plane (0.6 or 1) lies inside the volume.
  for (const double nearPlane : {0.6, 1.0}) {
    const Vec3 eye = centre + (coneRadius + 0.3) * side;
    StressConfig c =
        makeConfig("camera-in-volume", "eye-outside-near-cuts-" + numberName(nearPlane),
                   "eye 0.3 outside the shadow, near plane " + numberName(nearPlane) + " inside the volume",
                   withCamera(defaultSpotScene(), eye, centre, nearPlane));
    c.eyeInside = false;
    c.quick = nearPlane == 1.0;
    out.push_back(std::move(c));
  }
}

}  // namespace

void addCameraInVolume(std::vector<StressConfig>& out) {
  addEyesInShadow(out);
  addEyesAtBoundary(out);
}

}  // namespace shadowvol::stress

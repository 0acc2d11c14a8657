// degenerate: thin, tiny, coincident and touching objects; light-inside: a light inside a closed
// object, or a directional light whose position plane cuts the scene.
#include "stress_configs.h"
#include "stress_scenes.h"

namespace shadowvol::stress {
namespace {

using nlohmann::json;

json ground() {
  return {{"type", "plane"}, {"name", "ground"}, {"size", 20}};
}

json box(const char* name, json size, Vec3 at) {
  return {{"type", "box"}, {"name", name}, {"size", std::move(size)}, {"transform", {{"translate", toJson(at)}}}};
}

json sphere(const char* name, double radius, Vec3 at) {
  return {{"type", "sphere"},
          {"name", name},
          {"radius", radius},
          {"detail", 4},
          {"transform", {{"translate", toJson(at)}}}};
}

/// The default spot or directional scene with `objects` in place of the ground and sphere.
json sceneWith(bool spot, json objects) {
  json s = spot ? defaultSpotScene() : defaultDirectionalScene();
  s["objects"] = std::move(objects);
  return s;
}

void addBoth(std::vector<StressConfig>& out, const std::string& name, const std::string& what, const json& objects,
             bool quickSpot = false, bool quickDirectional = false) {
  for (const bool spot : {true, false}) {
    StressConfig c = makeConfig("degenerate", name + (spot ? "-spot" : "-dir"),
                                what + (spot ? " (spot)" : " (directional)"), sceneWith(spot, objects));
    c.quick = spot ? quickSpot : quickDirectional;
    out.push_back(std::move(c));
  }
}

}  // namespace

void addDegenerate(std::vector<StressConfig>& out) {
  for (const double t : {1e-6, 1e-5, 1e-4}) {
    const std::string tn = numberName(t);
    addBoth(out, "thin-y-" + tn, "a 2 x " + tn + " x 2 plate at height 1.5",
            {ground(), box("plate", {2, t, 2}, {0, 1.5, 0})}, t == 1e-6, t == 1e-6);
    addBoth(out, "thin-x-" + tn, "a " + tn + " x 2 x 2 wall", {ground(), box("wall", {t, 2, 2}, {0, 1.5, 0})},
            t == 1e-6);
    addBoth(out, "thin-z-" + tn, "a 2 x 2 x " + tn + " wall", {ground(), box("wall", {2, 2, t}, {0, 1.5, 0})});
  }
  for (const double r : {1e-2, 1e-3, 1e-4, 1e-6})
    addBoth(out, "tiny-sphere-" + numberName(r), "a sphere of radius " + numberName(r),
            {ground(), sphere("speck", r, kSphereCentre)}, r == 1e-4);
  addBoth(out, "tiny-box-1e-4", "a box of side 1e-4", {ground(), box("speck", 1e-4, kSphereCentre)});
  json flat = sphere("disc", 1, kSphereCentre);
  flat["transform"]["scale"] = {1, 1e-6, 1};
  addBoth(out, "flattened-sphere", "a sphere scaled to 1e-6 in y", {ground(), flat});
  addBoth(out, "coincident-spheres", "two identical spheres in the same place",
          {ground(), sphere("a", 1, kSphereCentre), sphere("b", 1, kSphereCentre)}, true);
  addBoth(out, "coincident-boxes", "two identical boxes in the same place",
          {ground(), box("a", 1.5, {0, 2, 0}), box("b", 1.5, {0, 2, 0})});
  addBoth(out, "box-on-ground", "a box whose bottom face lies on the ground", {ground(), box("block", 1, {0, 0.5, 0})},
          true, true);
  addBoth(out, "stacked-boxes", "two boxes sharing a face",
          {ground(), box("a", 1, {0, 0.5, 0}), box("b", 1, {0, 1.5, 0})});
  addBoth(out, "sphere-on-ground", "a sphere touching the ground", {ground(), sphere("ball", 1, {0, 1, 0})});
  addBoth(out, "sphere-on-box", "a sphere resting on a box",
          {ground(), box("block", 1, {0, 0.5, 0}), sphere("ball", 0.5, {0, 1.5, 0})});
  addBoth(out, "touching-spheres", "two spheres touching at one point",
          {ground(), sphere("a", 1, {-1, 2, 0}), sphere("b", 1, {1, 2, 0})});
  addBoth(out, "double-ground", "two coincident ground planes",
          {ground(), json{{"type", "plane"}, {"name", "ground2"}, {"size", 20}}, sphere("ball", 1, kSphereCentre)},
          false, true);
  addBoth(out, "box-top-at-plane", "a raised plane lying on a box's top face",
          {ground(), box("block", 1, {0, 0.5, 0}),
           json{{"type", "plane"}, {"name", "shelf"}, {"size", 1}, {"transform", {{"translate", {0, 1, 0}}}}}});
}

void addLightInside(std::vector<StressConfig>& out) {
  auto add = [&out](const std::string& name, const std::string& what, json objects, json light, bool quick) {
    json s = defaultSpotScene();
    s["objects"] = std::move(objects);
    s["light"] = std::move(light);
    StressConfig c = makeConfig("light-inside", name, what, s);
    c.quick = quick;
    out.push_back(std::move(c));
  };
  const json spotDown = {{"type", "spot"}, {"position", toJson(kSphereCentre)}, {"direction", {0, -1, 0}}, {"fov", 90}};
  add("spot-in-sphere-centre", "spot light at the sphere's centre, pointing down",
      {ground(), sphere("shell", 1, kSphereCentre)}, spotDown, true);
  json offCentre = spotDown;
  offCentre["position"] = {0.3, 2.2, 0.1};
  offCentre["direction"] = {-0.2, -1, 0.1};
  add("spot-in-sphere-off-centre", "spot light inside the sphere, off its centre",
      {ground(), sphere("shell", 1, kSphereCentre)}, offCentre, false);
  add("spot-in-box", "spot light at the centre of a box", {ground(), box("room", 2, kSphereCentre)}, spotDown, true);
  json nearWall = spotDown;
  nearWall["position"] = {0.99, 2, 0};
  add("spot-in-box-near-wall", "spot light inside a box, 0.01 from a wall", {ground(), box("room", 2, kSphereCentre)},
      nearWall, false);
  add("spot-in-enclosing-sphere", "spot light (and camera) inside a sphere around the whole scene",
      {ground(), sphere("ball", 1, kSphereCentre), sphere("dome", 15, {0, 0, 0})}, defaultSpotScene()["light"], false);
  json onSurface = spotDown;
  onSurface["position"] = {0, 3, 0};
  add("spot-on-sphere-top", "spot light on the sphere's top, pointing down",
      {ground(), sphere("ball", 1, kSphereCentre)}, onSurface, false);
  onSurface["position"] = {0, 3.001, 0};
  add("spot-just-above-sphere", "spot light 0.001 above the sphere, pointing down",
      {ground(), sphere("ball", 1, kSphereCentre)}, onSurface, false);
  const std::pair<const char*, double> heights[] = {{"0", 0}, {"1", 1}, {"2", 2}, {"3", 3}};
  for (const auto& [hn, h] : heights) {
    const json light = {{"type", "directional"}, {"position", {0, h, 0}}, {"direction", {0, -1, 0}}};
    add(std::string("dir-plane-at-y") + hn, "directional light straight down from a plane at y = " + std::string(hn),
        {ground(), sphere("ball", 1, kSphereCentre)}, light, h == 2);
  }
  const json oblique = {
      {"type", "directional"}, {"position", toJson(kSphereCentre)}, {"direction", toJson(kSpotTarget - kSpotPosition)}};
  add("dir-plane-through-sphere-oblique", "oblique directional light from the sphere's centre",
      {ground(), sphere("ball", 1, kSphereCentre)}, oblique, true);
}

}  // namespace shadowvol::stress

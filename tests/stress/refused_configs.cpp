// refused: scenes with one bad field each. Every command must exit 1 naming the file and the field
// (its JSON pointer) and write nothing. Numbers JSON cannot hold as a double (1e400) and tokens
// that are not JSON (NaN) are written verbatim; they are located by the field's pointer or by
// the line and column of the malformed text.
#include <regex>

#include "stress_configs.h"
#include "stress_scenes.h"

namespace shadowvol::stress {
namespace {

using nlohmann::json;

/// Sets the value at `pointer` (a JSON pointer) in the default spot scene.
json spotWith(const std::string& pointer, json value) {
  json s = defaultSpotScene();
  s[json::json_pointer(pointer)] = std::move(value);
  return s;
}

json directionalWith(const std::string& pointer, json value) {
  json s = defaultDirectionalScene();
  s[json::json_pointer(pointer)] = std::move(value);
  return s;
}

/// The scene's text with the number at `pointer` spelled `token` (e.g. 1e400, NaN, -Infinity).
std::string textWith(json scene, const std::string& pointer, const std::string& token) {
  const std::string marker = "424242.125";
  scene[json::json_pointer(pointer)] = 424242.125;
  std::string text = scene.dump(2);
  return std::regex_replace(text, std::regex(marker), token, std::regex_constants::format_first_only);
}

}  // namespace

void addRefused(std::vector<StressConfig>& out) {
  auto add = [&out](const std::string& name, const std::string& what, json scene, std::vector<std::string> fields,
                    bool quick) {
    StressConfig c = makeConfig("refused", "refused-" + name, what, std::move(scene));
    c.refused = true;
    c.fields = std::move(fields);
    c.quick = quick;
    out.push_back(std::move(c));
  };
  // `field` is the pointer a message should name: `pointer` itself, or the array holding it.
  auto addText = [&](const std::string& name, const std::string& what, const json& scene, const std::string& pointer,
                     const std::string& field, const std::string& token, bool quick) {
    add(name, what, json(), {field, "line "}, quick);
    out.back().sceneText = textWith(scene, pointer, token);
  };
  add("dir-near-negative", "directional near -1", directionalWith("/light/near", -1), {"/light/near"}, true);
  add("spot-near-zero", "spot near 0", spotWith("/light/near", 0), {"/light/near"}, false);
  add("spot-near-negative", "spot near -0.5", spotWith("/light/near", -0.5), {"/light/near"}, false);
  json s = spotWith("/light/near", 5);
  s["light"]["far"] = 2;
  add("spot-near-above-far", "spot near 5, far 2", s, {"/light/far"}, true);
  s = directionalWith("/light/near", 5);
  s["light"]["far"] = 5;
  add("dir-near-equals-far", "directional near = far = 5", s, {"/light/far"}, false);
  add("spot-far-before-fitted-near", "spot far 0.5 before the fitted near", spotWith("/light/far", 0.5), {"/light/far"},
      false);
  for (const double fov : {179.0, 179.5, 180.0, 0.0, -10.0})
    add("spot-fov-" + numberName(fov), "spot fov " + numberName(fov), spotWith("/light/fov", fov), {"/light/fov"},
        fov == 179.0);
  s = spotWith("/light/direction", {0, 0, 0});
  s["light"].erase("target");
  add("spot-direction-zero", "spot direction [0, 0, 0]", s, {"/light/direction"}, true);
  add("dir-direction-zero", "directional direction [0, 0, 0]", directionalWith("/light/direction", {0, 0, 0}),
      {"/light/direction"}, false);
  add("spot-target-at-position", "spot target equals position", spotWith("/light/target", toJson(kSpotPosition)),
      {"/light/target"}, false);
  add("spot-up-parallel", "spot up along its direction", spotWith("/light/up", toJson(kSpotTarget - kSpotPosition)),
      {"/light/up"}, false);
  add("dir-extent-zero", "directional extent 0", directionalWith("/light/extent", 0), {"/light/extent"}, false);
  add("camera-target-at-eye", "camera target equals eye", spotWith("/camera/target", {0, 6, 11}), {"/camera/target"},
      true);
  add("camera-up-zero", "camera up [0, 0, 0]", spotWith("/camera/up", {0, 0, 0}), {"/camera/up"}, false);
  add("camera-up-parallel", "camera up along the view", spotWith("/camera/up", {0, -5, -11}), {"/camera/up"}, false);
  add("camera-fov-179", "camera fov 179", spotWith("/camera/fov", 179), {"/camera/fov"}, false);
  add("camera-near-zero", "camera near 0", spotWith("/camera/near", 0), {"/camera/near"}, false);
  s = spotWith("/camera/near", 10);
  s["camera"]["far"] = 1;
  add("camera-near-above-far", "camera near 10, far 1", s, {"/camera/far"}, true);
  add("camera-width-zero", "camera width 0", spotWith("/camera/width", 0), {"/camera/width"}, false);
  add("camera-height-huge", "camera height 20000", spotWith("/camera/height", 20000), {"/camera/height"}, false);
  add("sphere-radius-zero", "sphere radius 0", spotWith("/objects/1/radius", 0), {"/objects/1/radius"}, false);
  add("sphere-radius-negative", "sphere radius -1", spotWith("/objects/1/radius", -1), {"/objects/1/radius"}, false);
  add("scale-zero", "transform scale 0", spotWith("/objects/1/transform/scale", 0), {"/objects/1/transform/scale"},
      true);
  add("scale-axis-zero", "transform scale [1, 0, 1]", spotWith("/objects/1/transform/scale", {1, 0, 1}),
      {"/objects/1/transform/scale"}, false);
  s = defaultSpotScene();
  s["objects"][1]["transform"] = {{"matrix", {1, 0, 0, 0, 0, 0, 0, 2, 0, 0, 1, 0, 0, 0, 0, 1}}};
  add("matrix-singular", "a singular transform matrix", s, {"/objects/1/transform/matrix"}, false);
  add("box-size-zero", "box size [1, 0, 1]", spotWith("/objects/1", {{"type", "box"}, {"size", {1, 0, 1}}}),
      {"/objects/1/size"}, false);
  add("sphere-detail-9", "sphere detail 9", spotWith("/objects/1/detail", 9), {"/objects/1/detail"}, false);
  add("transform-overflows-float", "scale 1e30 of a sphere of radius 1e10 (beyond float)",
      spotWith("/objects/1/radius", 1e10), {"/objects/1/transform"}, false);
  out.back().scene["objects"][1]["transform"]["scale"] = 1e30;
  add("spot-position-1e300", "spot position x 1e300 (finite, far beyond any scene)",
      spotWith("/light/position", {1e300, 9, 2}), {"/light/position"}, false);
  add("camera-fov-1e-300", "camera fov 1e-300", spotWith("/camera/fov", 1e-300), {"/camera/fov"}, false);
  add("fov-wrong-type", "spot fov \"wide\"", spotWith("/light/fov", "wide"), {"/light/fov"}, false);
  add("unknown-field", "an unknown light field", spotWith("/light/colour", "red"), {"/light/colour"}, false);
  add("objects-empty", "no objects", spotWith("/objects", json::array()), {"/objects"}, false);
  addText("sphere-radius-1e400", "sphere radius 1e400 (overflows a double)", defaultSpotScene(), "/objects/1/radius",
          "/objects/1/radius", "1e400", true);
  addText("light-position-1e400", "spot position x 1e400", defaultSpotScene(), "/light/position/0", "/light/position",
          "1e400", false);
  addText("camera-far-minus-1e400", "camera far -1e400", defaultSpotScene(), "/camera/far", "/camera/far", "-1e400",
          false);
  addText("light-far-1e400", "directional far 1e400", defaultDirectionalScene(), "/light/far", "/light/far", "1e400",
          false);
  addText("translate-1e400", "translate y 1e400", defaultSpotScene(), "/objects/1/transform/translate/1",
          "/objects/1/transform/translate", "1e400", false);
  addText("fov-nan", "spot fov NaN (not JSON)", defaultSpotScene(), "/light/fov", "/light/fov", "NaN", true);
  addText("near-infinity", "spot near Infinity (not JSON)", defaultSpotScene(), "/light/near", "/light/near",
          "Infinity", false);
}

}  // namespace shadowvol::stress

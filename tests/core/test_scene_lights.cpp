// A scene with several lights (scene.h: Scene::light, otherLights, forEachLight): the `lights`
// array, its errors naming /lights/k, each light fitted and rebased like the one `light`, the
// light intensity, and the per-light helpers.
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "shadowvol/error.h"
#include "shadowvol/report_json.h"
#include "shadowvol/scene.h"

namespace shadowvol {
namespace {

std::string withLights(const std::string& lights) {
  return R"({"objects":[{"type":"plane","size":10},{"type":"box","transform":{"translate":[0,0.5,0]}}],"lights":)" +
         lights + R"(,"camera":{"eye":[0,4,8],"target":[0,0,0]}})";
}

constexpr const char* kSpot = R"({"type":"spot","position":[3,6,2],"target":[0,0,0],"fov":70,"intensity":0.5})";
constexpr const char* kPoint = R"({"type":"point","position":[-2,2,1]})";

void expectError(const std::string& text, const std::string& field, const std::string& words = "") {
  try {
    parseScene(text, "lights.json", ".");
    FAIL() << "no error for " << field;
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "lights.json");
    EXPECT_EQ(e.field(), field) << e.what();
    if (!words.empty()) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  }
}

TEST(SceneLights, ArrayGivesTheFirstLightAndTheOthersInOrder) {
  const Scene s = parseScene(withLights(std::string("[") + kSpot + "," + kPoint + "]"), "lights.json", ".").scene;
  ASSERT_EQ(s.lightCount(), 2u);
  EXPECT_TRUE(s.lightsArray);
  EXPECT_EQ(s.light.type, LightType::Spot);
  EXPECT_DOUBLE_EQ(s.light.intensity, 0.5);
  EXPECT_EQ(s.lightAt(1).type, LightType::Point);
  EXPECT_DOUBLE_EQ(s.lightAt(1).intensity, 1.0);
  EXPECT_EQ(s.lightPointer(0), "/lights/0");
  EXPECT_EQ(s.lightPointer(1), "/lights/1");
  // Each light is fitted as the one light of a file would be.
  for (std::size_t k = 0; k < 2; ++k) {
    const std::string one = k == 0 ? kSpot : kPoint;
    const Scene alone = parseScene(R"({"objects":[{"type":"plane","size":10},{"type":"box","transform":{"translate":[0,0.5,0]}}],"light":)" +
                                       one + R"(,"camera":{"eye":[0,4,8],"target":[0,0,0]}})",
                                   "one.json", ".")
                            .scene;
    EXPECT_NEAR(s.lightAt(k).nearPlane, alone.light.nearPlane, 1e-12) << k;
    EXPECT_NEAR(s.lightAt(k).farPlane, alone.light.farPlane, 1e-12) << k;
    EXPECT_EQ(alone.lightPointer(0), "/light");
  }
  const nlohmann::json j = describeScene(s);
  ASSERT_EQ(j["lights"].size(), 2u);
  EXPECT_EQ(j["lights"][1]["type"], "point");
  EXPECT_EQ(j["light"], j["lights"][0]);
  EXPECT_FALSE(describeScene(s.withOnlyLight(1)).contains("lights"));
}

TEST(SceneLights, ErrorsNameTheLightInTheArray) {
  expectError(withLights("[]"), "/lights", "1 to 16");
  expectError(withLights(R"({"type":"point","position":[0,2,0]})"), "/lights", "array");
  std::string many = "[";
  for (int k = 0; k < 17; ++k) many += std::string(k ? "," : "") + kPoint;
  expectError(withLights(many + "]"), "/lights", "17 lights");
  expectError(withLights(std::string("[") + kSpot + R"(,{"type":"spot","position":[0,5,0],"target":[0,0,0],"fov":0}])"),
              "/lights/1/fov");
  expectError(withLights(std::string("[") + kPoint + R"(,{"type":"point","position":[0,5,0],"intensity":-1}])"),
              "/lights/1/intensity", "-1");
  expectError(withLights(std::string("[") + kSpot + R"(,{"type":"point","position":[0,5,0],"near":0.5,"far":0.1}])"),
              "/lights/1/far");
  // Both forms at once, or neither.
  expectError(R"({"objects":[{"type":"box"}],"light":)" + std::string(kPoint) + R"(,"lights":[)" + kPoint +
                  R"(],"camera":{"eye":[0,0,5],"target":[0,0,0]}})",
              "/lights", "not both");
  expectError(R"({"objects":[{"type":"box"}],"camera":{"eye":[0,0,5],"target":[0,0,0]}})", "/light");
}

TEST(SceneLights, WarningsAndFitNotesNameTheirLight) {
  // The second light inside a closed sphere: the warning names /lights/1; a far plane given
  // beyond the scene is tightened with a note naming /lights/1/far.
  const SceneLoadResult r = parseScene(
      R"({"objects":[{"type":"plane","size":10},{"type":"sphere","name":"shell","radius":1,"transform":{"translate":[3,1.5,0]}}],
          "lights":[{"type":"spot","position":[0,6,0],"target":[0,0,0]},{"type":"point","position":[3,1.5,0],"far":500}],
          "camera":{"eye":[0,4,8],"target":[0,0,0]}})",
      "lights.json", ".");
  bool inside = false, far = false;
  for (const auto& w : r.warnings) {
    inside = inside || (w.find("/lights/1/position") != std::string::npos && w.find("shell") != std::string::npos);
    far = far || w.find("/lights/1/far") != std::string::npos;
  }
  EXPECT_TRUE(inside);
  EXPECT_TRUE(far);
}

// A probe's finding: a point light on a wall (a one-sided plane) had its near plane fitted down to
// far x 1e-7 without a word; its refined GPU volume then disagreed with its counts. Said now, naming
// the light; a light a little off the wall fits a near plane that keeps depth precision.
TEST(SceneLights, ALightOnASurfaceIsSaidToLoseDepthPrecision) {
  auto load = [](double z) {
    return parseScene(R"({"objects":[{"type":"plane","size":10},
          {"type":"plane","name":"wall","size":10,"transform":{"rotate":[90,0,0],"translate":[0,2,-4]}}],
          "lights":[{"type":"spot","position":[0,6,0],"target":[0,0,0]},{"type":"point","position":[0.3,2.5,)" +
                          std::to_string(z) + R"(]}], "camera":{"eye":[0,4,8],"target":[0,0,0]}})",
                      "lights.json", ".");
  };
  auto touches = [](const SceneLoadResult& r) {
    for (const auto& w : r.warnings)
      if (w.find("/lights/1/near") != std::string::npos && w.find("touches") != std::string::npos) return true;
    return false;
  };
  EXPECT_TRUE(touches(load(-4.0)));
  EXPECT_FALSE(touches(load(-3.5)));
}

TEST(SceneLights, ForEachLightSwapsEachInAndRestoresTheOrder) {
  Scene s = parseScene(withLights(std::string("[") + kSpot + "," + kPoint + "," + kPoint + "]"), "lights.json", ".").scene;
  s.otherLights[1].position.x = 7.0;  // tell the two points apart
  std::vector<LightType> seen;
  std::vector<double> xs;
  forEachLight(s, [&](std::size_t k) {
    seen.push_back(s.light.type);
    xs.push_back(s.light.position.x);
    EXPECT_EQ(s.lightCount(), 3u) << k;
  });
  EXPECT_EQ(seen, (std::vector<LightType>{LightType::Spot, LightType::Point, LightType::Point}));
  EXPECT_DOUBLE_EQ(xs[2], 7.0);
  EXPECT_EQ(s.light.type, LightType::Spot);
  EXPECT_THROW(forEachLight(s, [&](std::size_t k) {
                 if (k == 2) throw std::runtime_error("stop");
               }),
               std::runtime_error);
  EXPECT_EQ(s.light.type, LightType::Spot);
  EXPECT_DOUBLE_EQ(s.otherLights[1].position.x, 7.0);
  const Scene only = s.withOnlyLight(2);
  EXPECT_EQ(only.lightCount(), 1u);
  EXPECT_DOUBLE_EQ(only.light.position.x, 7.0);
  EXPECT_EQ(only.objects.size(), s.objects.size());
}

TEST(SceneLights, FarSceneRebasesEveryLight) {
  const std::string offset = R"(,"transform":{"translate":[1e6,0,1e6]})";
  const Scene s = parseScene(
      R"({"objects":[{"type":"plane","size":10)" + offset + R"(},{"type":"box")" + offset + R"(}],
          "lights":[{"type":"spot","position":[1000003,6,1000002],"target":[1e6,0,1e6]},{"type":"point","position":[999998,2,1000001]}],
          "camera":{"eye":[1e6,4,1000008],"target":[1e6,0,1e6]}})",
      "far.json", ".").scene;
  EXPECT_NEAR(s.light.position.x + s.origin.x, 1000003.0, 1e-9);
  EXPECT_NEAR(s.lightAt(1).position.x + s.origin.x, 999998.0, 1e-9);
  EXPECT_LT(std::abs(s.lightAt(1).position.x), 10.0);
}

}  // namespace
}  // namespace shadowvol

// chooseCapture (capture_choice.h): the rule behind --capture auto.
#include <gtest/gtest.h>

#include "shadowvol/capture_choice.h"
#include "shadowvol/frame.h"
#include "shadowvol/primitives.h"
#include "test_util.h"

namespace shadowvol {
namespace {

using test::sceneWith;

TriangleMesh openBowl() {
  TriangleMesh bowl = makeHemisphere(1.0, 16, 4);
  bowl.triangles.resize(bowl.triangles.size() / 2);  // open: half of it gone
  return bowl;
}

// Closed meshes: entry capture for a refined volume's map, back capture for an unrefined volume's,
// for a shadow map and for the maps read as one layer. The plane is open, but generated objects do
// not decide: a plane is a receiver.
TEST(CaptureChoice, ClosedMeshesGiveEntryForARefinedVolumeAndBackOtherwise) {
  const Scene s = sceneWith({SceneObject{"ground", "plane", makePlane(8.0, 8.0, 1)},
                             SceneObject{"ball", "mesh", makeIcoSphere(1.0, 2)},
                             SceneObject{"crate", "mesh", makeBox(1.0, 1.0, 1.0)}});
  for (CaptureUse use :
       {CaptureUse::ShadowMap, CaptureUse::Volume, CaptureUse::RefinedVolume, CaptureUse::OneLayer}) {
    const CaptureChoice c = chooseCapture(s, use);
    EXPECT_EQ(c.mode, use == CaptureUse::RefinedVolume ? CaptureMode::Entry : CaptureMode::Back) << int(use);
    EXPECT_TRUE(c.openMeshes.empty());
    EXPECT_NE(c.reason.find("no mesh object is open"), std::string::npos) << c.reason;
  }
}

// A refined volume under a spot light whose far plane lies more than 8 times as far as its near
// plane takes back capture: entry's bias, a texel at the far plane, would span more than 8 texels at
// the nearest casters (a fourteenth probe's 160-degree spot). A directional light's texel is one
// size at every depth.
TEST(CaptureChoice, ADeepSpotLightGivesBackForARefinedVolume) {
  Scene s = sceneWith({SceneObject{"ball", "mesh", makeIcoSphere(1.0, 2)}});
  s.light.type = LightType::Spot;
  s.light.fovYDegrees = 60.0;
  s.light.nearPlane = 1.0;
  s.light.farPlane = 7.9;
  EXPECT_EQ(chooseCapture(s, CaptureUse::RefinedVolume).mode, CaptureMode::Entry);
  s.light.farPlane = 8.1;
  const CaptureChoice deep = chooseCapture(s, CaptureUse::RefinedVolume);
  EXPECT_EQ(deep.mode, CaptureMode::Back);
  EXPECT_NE(deep.reason.find("far plane lies 8.1 times as far as its near plane"), std::string::npos) << deep.reason;
  EXPECT_EQ(chooseCapture(s, CaptureUse::Volume).reason, "back capture: no mesh object is open");
  EXPECT_TRUE(deep.deepSpot);
  // The capture is every light's: a deep spot light second decides too (a second reader's finding).
  Light spot = s.light;
  s.light.type = LightType::Directional;
  EXPECT_EQ(chooseCapture(s, CaptureUse::RefinedVolume).mode, CaptureMode::Entry);
  s.otherLights = {spot};
  const CaptureChoice second = chooseCapture(s, CaptureUse::RefinedVolume);
  EXPECT_EQ(second.mode, CaptureMode::Back);
  EXPECT_NE(second.reason.find("spot light 1's far plane"), std::string::npos) << second.reason;
  s.otherLights[0].nearPlane = 0.0;  // unfitted: says nothing
  EXPECT_EQ(chooseCapture(s, CaptureUse::RefinedVolume).mode, CaptureMode::Entry);
}

TEST(CaptureChoice, AnOpenMeshGivesFrontAndIsNamed) {
  const Scene s = sceneWith({SceneObject{"ground", "plane", makePlane(8.0, 8.0, 1)},
                             SceneObject{"ball", "mesh", makeIcoSphere(1.0, 2)},
                             SceneObject{"bowl", "mesh", openBowl()}});
  for (CaptureUse use : {CaptureUse::ShadowMap, CaptureUse::Volume, CaptureUse::OneLayer})
    EXPECT_EQ(chooseCapture(s, use).mode, CaptureMode::Front) << int(use);
  const CaptureChoice c = chooseCapture(s, CaptureUse::RefinedVolume);
  EXPECT_EQ(c.mode, CaptureMode::Front);
  EXPECT_EQ(c.openMeshes, std::vector<std::string>{"bowl"});
  EXPECT_NE(c.reason.find("\"bowl\""), std::string::npos) << c.reason;
  EXPECT_EQ(c.reason.find("ball"), std::string::npos) << c.reason;
}

// Split vertices (STL) and degenerate triangles do not make a closed mesh open (the rule of
// isClosedSurface, shared with the capture warnings).
TEST(CaptureChoice, StlSplitClosedMeshIsClosed) {
  TriangleMesh stl = test::splitVertices(makeBox(1.0, 1.0, 1.0));
  stl.triangles.push_back({0, 0, 1});
  EXPECT_EQ(chooseCapture(sceneWith({SceneObject{"stl box", "mesh", stl}}), CaptureUse::ShadowMap).mode,
            CaptureMode::Back);
}

TEST(CaptureChoice, ManyOpenMeshesNamedUpToThreeInSceneOrder) {
  std::vector<SceneObject> objects;
  for (const char* name : {"a", "b", "c", "d", "e"}) objects.push_back(SceneObject{name, "mesh", openBowl()});
  const CaptureChoice c = chooseCapture(sceneWith(std::move(objects)), CaptureUse::RefinedVolume);
  EXPECT_EQ(c.mode, CaptureMode::Front);
  EXPECT_EQ(c.openMeshes, (std::vector<std::string>{"a", "b", "c", "d", "e"}));
  EXPECT_NE(c.reason.find("\"a\", \"b\", \"c\" and 2 more"), std::string::npos) << c.reason;
  EXPECT_EQ(c.reason.find("\"d\""), std::string::npos) << c.reason;
}

// What a frame's map is for: a hybrid volume's sheet (refined or not), but one layer for the GPU's
// walk and for dual-paraboloid maps; a shadow map for the other methods.
TEST(CaptureChoice, TheUseOfAFramesMap) {
  RenderOptions o;
  EXPECT_EQ(captureUse(o), CaptureUse::Volume);
  o.volumeOptions.refineSteps = 6;
  EXPECT_EQ(captureUse(o), CaptureUse::RefinedVolume);
  o.refineCrossings = RefineCrossings::GpuWalk;
  EXPECT_EQ(captureUse(o), CaptureUse::OneLayer);
  o = {};
  for (ShadowMethod m : {ShadowMethod::ShadowMap, ShadowMethod::Pcf3, ShadowMethod::Pcf5}) {
    o.method = m;
    EXPECT_EQ(captureUse(o), CaptureUse::ShadowMap) << toString(m);
  }
  o.method = ShadowMethod::Dpsm;
  EXPECT_EQ(captureUse(o), CaptureUse::OneLayer);
  EXPECT_EQ(volumeUse(0), CaptureUse::Volume);  // what `build` takes without a frame's options
  EXPECT_EQ(volumeUse(6), CaptureUse::RefinedVolume);
}

// The same scene gives the same choice (no state between calls).
TEST(CaptureChoice, Deterministic) {
  const Scene s = sceneWith({SceneObject{"bowl", "mesh", openBowl()}});
  const CaptureChoice a = chooseCapture(s, CaptureUse::RefinedVolume), b = chooseCapture(s, CaptureUse::RefinedVolume);
  EXPECT_EQ(a.mode, b.mode);
  EXPECT_EQ(a.reason, b.reason);
}

}  // namespace
}  // namespace shadowvol

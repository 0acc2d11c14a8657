// From the GL renderer's result to the validation's input. Header-only, so that shadowvol::validate
// stays GL-free; include it where both shadowvol::gl and shadowvol::validate are linked (the
// command line's validate, the Python module).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "shadowvol/dual_paraboloid.h"
#include <nlohmann/json.hpp>

#include "shadowvol/gl/renderer.h"
#include "shadowvol/report_json.h"
#include "shadowvol/validate/frame_validation.h"
#include "shadowvol/validate/report_folder.h"
#include "shadowvol/validate/validation_report.h"

namespace shadowvol {

/// The render options a validated frame needs on top of the caller's: stencil, depth map, the
/// method's own shadow test and (explicit volume) the mesh drawn read back.
inline gl::RenderOptions validationRenderOptions(gl::RenderOptions ro) {
  ro.readStencil = true;
  ro.readDepthMap = true;
  ro.readVisibility = true;
  ro.keepVolume = true;
  return ro;
}

/// The frame as the validation sees it: the image, the stencil (shadow-volume methods), and the
/// method's shadow test (visibility below one half = in shadow).
inline RenderedFrame toRenderedFrame(const gl::RenderResult& result, gl::ShadowMethod method) {
  RenderedFrame frame;
  frame.width = result.width;
  frame.height = result.height;
  frame.rgba = result.rgba;
  frame.hybrid = method == gl::ShadowMethod::Hybrid;
  if (frame.hybrid) frame.stencil = result.stencil;
  frame.zPass = result.volumeCountUsed == gl::VolumeCount::ZPass;
  frame.volume = result.volume;
  frame.gpuVolume = result.gpuVolume;
  frame.stencilBits = result.stencilBits;
  frame.faceVolumes = result.faceVolumes;
  frame.faceGpuVolumes = result.faceGpuVolumes;
  frame.shadowed.resize(result.visibility.size());
  for (std::size_t k = 0; k < result.visibility.size(); ++k) frame.shadowed[k] = result.visibility[k] < 128;
  return frame;
}
/// The shadow maps' constant bias for `light` as scene.frag applies it (renderer_camera.cpp): the
/// option's, or the default of the map the method samples (a dual-paraboloid map's for dpsm).
/// Reports name it `shadowBias`.
inline double shadowMapBias(const Light& light, const gl::RenderOptions& ro) {
  return ro.shadowBiasConstant.value_or(ro.method == gl::ShadowMethod::Dpsm
                                            ? dualParaboloidDefaultBias(light, ro.depthWidth, ro.capture)
                                            : defaultBias(light, ro.depthWidth, ro.depthHeight, ro.capture));
}

/// How the leak criterion (shadow_leaks.h) judges a frame of `ro` lit by `light`: the map side and
/// depth offset of the depth-map methods (hybrid: the volume's bias and blur offset; the shadow maps:
/// scene.frag's constant and slope bias), an exact method for silhouette volumes, not judged for
/// the others (dual-paraboloid maps, none).
inline void setLeakModel(RenderedFrame& frame, const gl::RenderOptions& ro, const gl::RenderResult& result,
                         const Light& light) {
  switch (ro.method) {
    case gl::ShadowMethod::Hybrid:
      frame.leakMapSide = ro.depthWidth;
      frame.leakOffset = result.biasUsed + (ro.volumeOptions.blur ? ro.volumeOptions.blurOffset : 0.0);
      return;
    case gl::ShadowMethod::ShadowMap:
    case gl::ShadowMethod::Pcf3:
    case gl::ShadowMethod::Pcf5:
      frame.leakMapSide = ro.depthWidth;
      frame.leakOffset = shadowMapBias(light, ro);
      frame.leakOffsetSlope = ro.shadowBiasSlope;
      return;
    case gl::ShadowMethod::Silhouette:
      frame.leakMapSide = 0;
      return;
    default:
      frame.leakMapSide.reset();
  }
}

/// The depth offset of a single depth map's shadow test (RenderedFrame::depthOffset): the volume's
/// bias (plus the blur offset with blur) for hybrid, the constant bias for the shadow maps; unset
/// for the other methods and where no depth map came back (a point light's six faces).
inline std::optional<double> methodDepthOffset(const gl::RenderOptions& ro, const gl::RenderResult& result) {
  if (!result.depthMap) return std::nullopt;
  switch (ro.method) {
    case gl::ShadowMethod::Hybrid:
      return result.biasUsed + (ro.volumeOptions.blur ? ro.volumeOptions.blurOffset : 0.0);
    case gl::ShadowMethod::ShadowMap:
    case gl::ShadowMethod::Pcf3:
    case gl::ShadowMethod::Pcf5:
      return ro.shadowBiasConstant.value_or(defaultBias(*result.depthMap));
    default:
      return std::nullopt;
  }
}

/// Every check of validateFrame on a frame rendered with validationRenderOptions(ro).
inline FrameValidation validateRender(const Scene& scene, const gl::RenderOptions& ro, const gl::RenderResult& result,
                                      const RenderedFrame& frame, const ValidationOptions& options) {
  if (frame.hybrid && !result.depthMap && !result.volume && result.faceVolumes.empty())
    throw std::runtime_error("the renderer returned no depth map and no volume");
  return validateFrame(scene, result.depthMap ? *result.depthMap : DepthMap{}, ro.volumeOptions, frame, options);
}

/// One light's part of a validated frame (validateEveryLight).
struct LightValidation {
  const gl::RenderResult* result = nullptr;  ///< the frame's for light 0, else otherLights[k - 1]
  RenderedFrame frame;                       ///< its stencil and shadow test, the frame's image
  FrameValidation validation;                ///< against the scene with light k alone
};

/// validateRender for every light of the scene (Scene::withOnlyLight: each light's shadows are
/// its own); `result` must outlive the answer.
inline std::vector<LightValidation> validateEveryLight(const Scene& scene, const gl::RenderOptions& ro,
                                                       const gl::RenderResult& result,
                                                       const ValidationOptions& options) {
  if (result.otherLights.size() + 1 != scene.lightCount())
    throw std::runtime_error("the frame has " + std::to_string(result.otherLights.size() + 1) + " lights' results, the scene " +
                             std::to_string(scene.lightCount()) + " lights");
  std::vector<LightValidation> out(scene.lightCount());
  for (std::size_t k = 0; k < out.size(); ++k) {
    LightValidation& l = out[k];
    l.result = k == 0 ? &result : &result.otherLights[k - 1];
    l.frame = toRenderedFrame(*l.result, ro.method);
    setLeakModel(l.frame, ro, *l.result, scene.lightAt(k));
    l.frame.rgba = result.rgba;
    l.frame.depthOffset = methodDepthOffset(ro, *l.result);
    l.validation = out.size() == 1 ? validateRender(scene, ro, *l.result, l.frame, options)
                                   : validateRender(scene.withOnlyLight(k), ro, *l.result, l.frame, options);
  }
  return out;
}

/// The report's fields of one light's checks (report.json's, all of them at the top level for one
/// light; the Python module's validate returns the same): its volume's build figures, the refined
/// GPU volume's, describeValidation's, the stencil count used and the method's extras.
inline nlohmann::json describeLightValidation(const LightValidation& c, const gl::RenderOptions& ro,
                                              const ValidationOptions& vo) {
  const gl::RenderResult& result = *c.result;
  nlohmann::json j;
  if (result.volumeStats) j["volume"] = describeVolumeStats(*result.volumeStats);  // refined GPU: the CPU mesh's
  if (result.gpuVolumeDrawUsed == gl::GpuVolumeDraw::Refined)
    j["gpuRefinement"] = {{"boundaryEdges", result.gpuBoundaryEdges},
                          {"crossingFallbacks", result.gpuCrossingFallbacks},
                          {"cpuRuleDifferences", result.cpuRuleEdgeDifferences},
                          {"volumeTriangles", result.volumeTriangles}};
  if (!result.faceVolumes.empty()) j["gpuRefinement"]["faceVolumes"] = result.faceVolumes.size();  // a point light's
  j.update(describeValidation(c.validation, vo, ro.method == gl::ShadowMethod::Silhouette));
  if (c.frame.hybrid || ro.method == gl::ShadowMethod::Silhouette) {
    j["volumeCount"] = gl::toString(result.volumeCountUsed);
    if (!result.zPassRefused.empty()) j["zPassRefused"] = result.zPassRefused;
  }
  if (ro.method == gl::ShadowMethod::Dpsm) j["dualParaboloid"] = describeDualParaboloid(ro.depthWidth);
  if (ro.method == gl::ShadowMethod::Silhouette) {
    j["receiversOnly"] = result.receiversOnly;    // open objects: they cast no silhouette shadow
    j["skippedCasters"] = result.skippedCasters;  // closed objects behind a spot light
  }
  return j;
}

/// Light k's section of a report with several lights (report.json's lights[k]): which light, its
/// volume's bias and the shadow maps', its image folder, then `fields` (its describeLightValidation).
inline nlohmann::json describeLightSection(const Scene& scene, std::size_t k, const LightValidation& c,
                                           const gl::RenderOptions& ro, const nlohmann::json& fields) {
  nlohmann::json section = {{"index", k},
                            {"pointer", scene.lightPointer(k)},
                            {"type", toString(scene.lightAt(k).type)},
                            {"bias", c.result->biasUsed},
                            {"shadowBias", shadowMapBias(scene.lightAt(k), ro)},
                            {"imageFolder", lightReportFolderName(k)}};
  section.update(fields);
  return section;
}

/// The verdict over several lights' sections (report.json's top-level `verdict` and `passed` beside
/// `lights`): passed when every light's frame passed.
inline void describeSeveralLightsVerdict(bool passed, nlohmann::json& report) {
  report["passed"] = passed;
  report["verdict"] = passed ? "every light's frame is consistent and accurate"
                             : "at least one light's frame failed: see lights[k].verdict";
}

}  // namespace shadowvol

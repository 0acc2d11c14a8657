// From the GL renderer's result to the validation's input. Header-only, so that shadowvol::validate
// stays GL-free; include it where both shadowvol::gl and shadowvol::validate are linked (the
// command line's validate, the Python module).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "shadowvol/gl/renderer.h"
#include "shadowvol/validate/frame_validation.h"

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

/// The leak criterion's texel size of a method (RenderedFrame::leakMapSide): the map side for the
/// depth-map methods, 0 for silhouette volumes (exact), unset for dual-paraboloid maps and none.
inline std::optional<int> leakMapSideOf(gl::ShadowMethod method, int depthWidth) {
  switch (method) {
    case gl::ShadowMethod::Hybrid:
    case gl::ShadowMethod::ShadowMap:
    case gl::ShadowMethod::Pcf3:
    case gl::ShadowMethod::Pcf5:
      return depthWidth;
    case gl::ShadowMethod::Silhouette:
      return 0;
    default:
      return std::nullopt;
  }
}

/// The frame as the validation sees it: the image, the stencil (shadow-volume methods), and the
/// method's shadow test (visibility below one half = in shadow); with `ro`, how the leak criterion
/// sizes its texels.
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
inline RenderedFrame toRenderedFrame(const gl::RenderResult& result, const gl::RenderOptions& ro) {
  RenderedFrame frame = toRenderedFrame(result, ro.method);
  frame.leakMapSide = leakMapSideOf(ro.method, ro.depthWidth);
  return frame;
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
    l.frame = toRenderedFrame(*l.result, ro);
    l.frame.rgba = result.rgba;
    l.frame.depthOffset = methodDepthOffset(ro, *l.result);
    l.validation = out.size() == 1 ? validateRender(scene, ro, *l.result, l.frame, options)
                                   : validateRender(scene.withOnlyLight(k), ro, *l.result, l.frame, options);
  }
  return out;
}

}  // namespace shadowvol

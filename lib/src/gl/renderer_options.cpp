// The checks of a frame's options against the scene, the light and this context (InputError).
#include "renderer_impl.h"

namespace shadowvol::gl {

void Renderer::Impl::validatePointLight(const RenderOptions& o) const {
  if (o.method == ShadowMethod::Hybrid) {  // either cube volume
    // The GPU cube volume's face volumes take the GPU's rays or walk as one map's refined GPU
    // volume does; the explicit cube volume only Embree's rays.
    if (o.volumeOptions.refineSteps > 0 && o.refineCrossings != RefineCrossings::Rays && o.volume != VolumeSource::Gpu)
      throw OptionConflict("RenderOptions", "refineCrossings", toString(o.refineCrossings),
                           MarkedProblem{"a point light's explicit volume finds its crossings by the scene's rays "
                                         "alone: ${refineCrossings} rays, or ${volume} gpu for the GPU's"});
    // Refused here, before any pass, rather than by buildCubeVolume mid-frame: with several
    // lights validateForLight then names the point light.
    if (o.volumeOptions.refineSteps > 0 && o.volumeOptions.refineChords)
      throw OptionConflict("volume options", "refine chords", "true", MarkedProblem{kCubeRefinementRule});
    // Here too rather than in chooseZPass mid-frame, so that several lights name this one (a
    // second probe's finding).
    if (o.volumeCount == VolumeCount::ZPass)
      throw OptionConflict("RenderOptions", "volumeCount", "zpass", kPointZPassRule);
    if (o.volumeOptions.refineSteps > 0 && o.volumeOptions.refineSubdivisions > 1)
      throw OptionConflict("volume options", "refine subdivisions", std::to_string(o.volumeOptions.refineSubdivisions),
                           MarkedProblem{kCubeRefinementRule});
    if (o.volumeOptions.facePrisms)
      throw OptionConflict("volume options", "face prisms", "true",
                           "are made for spot and directional lights; a point light's cube volume has none yet");
    if (o.volumeOptions.cap != FarCap::Exact)
      throw OptionConflict("RenderOptions", "volumeOptions.cap", toString(o.volumeOptions.cap), kCubeVolumeCapRule);
    if (o.volume == VolumeSource::Gpu) validateGpuCubeVolume(o);
  }
  const bool shadowMap =
      o.method == ShadowMethod::ShadowMap || o.method == ShadowMethod::Pcf3 || o.method == ShadowMethod::Pcf5;
  if (shadowMap && !hasCompute)
    throw InputError("RenderOptions", "method", toString(o.method),
                     "a point light's cube shadow map needs OpenGL 4.3 (glCopyImageSubData); this context has " +
                         context.info().glVersion);
  if (o.method == ShadowMethod::Dpsm && usesTwoLayers(o.capture))
    throw OptionConflict("RenderOptions", "capture", toString(o.capture),
                         "the dual-paraboloid map takes back or front capture (it has no second layer)");
  const int s = o.paraboloidSubdivision;
  if (s != 1 && s != 2 && s != 4 && s != 8)
    throw InputError("RenderOptions", "paraboloidSubdivision", std::to_string(s), "must be 1, 2, 4 or 8");
  if (o.method == ShadowMethod::Dpsm) {
    const int side = dualParaboloidSide(o.depthWidth);
    if (2 * side > std::min(maxTextureSize, maxViewport[0]))
      throw InputError("RenderOptions", "depthWidth", std::to_string(o.depthWidth),
                       "its dual-paraboloid maps (2 x " + std::to_string(side) +
                           " texels wide) exceed this "
                           "context's largest texture or viewport, " +
                           std::to_string(std::min(maxTextureSize, maxViewport[0])));
  }
  if (o.depthWidth != o.depthHeight)
    throw InputError("RenderOptions", "depthWidth x depthHeight",
                     std::to_string(o.depthWidth) + "x" + std::to_string(o.depthHeight),
                     "a point light's cube faces are square");
}

void Renderer::Impl::validateGpuCubeVolume(const RenderOptions& o) const {
  if (!hasCompute)
    throw InputError("RenderOptions", "volume", "gpu",
                     "a point light's GPU cube volume needs OpenGL 4.3 (glCopyImageSubData); this context has " +
                         context.info().glVersion + ": use volume explicit");
  const GpuVolumeDraw d = o.gpuVolumeDraw;
  if (d != GpuVolumeDraw::Auto && d != GpuVolumeDraw::Indexed && d != GpuVolumeDraw::AllQuads)
    throw OptionConflict("RenderOptions", "gpuVolumeDraw", toString(d),
                         "a point light's GPU cube volume is drawn indexed (auto) or one point per cell (all-quads)");
}

void Renderer::Impl::checkOffsetRanges(const RenderOptions& o) const {
  const VolumeBuildOptions& v = o.volumeOptions;
  const double bias = v.bias.value_or(0.0);
  const EmptyingOffset e = volumeOffsetEmptiesRange(bias, v.blurOffset, v.blur, light.nearPlane, light.farPlane);
  if (o.method == ShadowMethod::Hybrid && !e.why.empty())
    throw InputError("RenderOptions", e.blurOffset ? "volumeOptions.blurOffset" : "volumeOptions.bias",
                     numberText(e.blurOffset ? v.blurOffset : bias), e.why);
  const bool oneMap =
      o.method == ShadowMethod::ShadowMap || o.method == ShadowMethod::Pcf3 || o.method == ShadowMethod::Pcf5;
  if (oneMap && light.type != LightType::Point && o.shadowBiasConstant)
    if (const std::string why = offsetEmptiesRange(*o.shadowBiasConstant, light.nearPlane, light.farPlane);
        !why.empty())
      throw InputError("RenderOptions", "shadowBiasConstant", numberText(*o.shadowBiasConstant), why);
}

void Renderer::Impl::checkGuardedSize(const char* source, const char* field, int w, int h, int guard) const {
  const int limit = std::min(maxTextureSize, maxViewport[0]);
  if (w > limit - 2 * guard || h > limit - 2 * guard)
    throw InputError(source, field, std::to_string(w) + "x" + std::to_string(h),
                     "the map has a guard band of " + std::to_string(guard) + " texels a side (light.h): at most " +
                         std::to_string(limit - 2 * guard) + " per side on this OpenGL implementation");
}

void Renderer::Impl::validate(const RenderOptions& o, const CameraSetup& cam) const {
  requireScene();
  checkSize("RenderOptions", "depthWidth x depthHeight", o.depthWidth, o.depthHeight,
            std::min(maxTextureSize, maxViewport[0]));
  if (o.method == ShadowMethod::Hybrid && light.type != LightType::Point)
    checkGuardedSize("RenderOptions", "depthWidth x depthHeight", o.depthWidth, o.depthHeight, kVolumeGuardTexels);
  if (cam.w < 1 || cam.h < 1 || cam.w > maxRenderbufferSize || cam.h > maxRenderbufferSize)
    throw InputError("RenderOptions", "imageWidth x imageHeight", std::to_string(cam.w) + "x" + std::to_string(cam.h),
                     "must be between 1 and " + std::to_string(maxRenderbufferSize) + " per side");
  if (!std::isfinite(o.ambient) || !std::isfinite(o.diffuse) || o.ambient < 0 || o.diffuse < 0)
    throw InputError("RenderOptions", "ambient/diffuse", numberText(o.ambient) + "/" + numberText(o.diffuse),
                     "must be finite and >= 0");
  if (o.shadowBiasConstant && (!std::isfinite(*o.shadowBiasConstant) || *o.shadowBiasConstant < 0.0))
    throw InputError("RenderOptions", "shadowBiasConstant", numberText(*o.shadowBiasConstant),
                     "must be finite and >= 0 (a negative bias moves receivers in front of themselves: acne)");
  if (!std::isfinite(o.shadowBiasSlope))
    throw InputError("RenderOptions", "shadowBiasSlope", numberText(o.shadowBiasSlope), "must be finite");
  if (!std::isfinite(o.volumeOptions.blurOffset))
    throw InputError("RenderOptions", "volumeOptions.blurOffset", numberText(o.volumeOptions.blurOffset),
                     "must be finite");
  if (o.volumeOptions.bias && !std::isfinite(*o.volumeOptions.bias))
    throw InputError("RenderOptions", "volumeOptions.bias", numberText(*o.volumeOptions.bias), "must be finite");
  checkOffsetRanges(o);
  if (light.type == LightType::Point) validatePointLight(o);
  if (light.type != LightType::Point && o.method == ShadowMethod::Dpsm)
    throw InputError(
        "RenderOptions", "method", "dpsm",
        std::string("dual-paraboloid maps are a point light's; this scene's light is ") + toString(light.type));
  if (refinedGpuVolume(o)) {
    auto refuse = [&](const std::string& why) {  // a combination of options
      throw OptionConflict("RenderOptions", "volumeOptions.refineSteps", std::to_string(o.volumeOptions.refineSteps),
                           MarkedProblem{"the refined GPU volume " + why});
    };
    if (!hasCompute)
      throw InputError("RenderOptions", "volumeOptions.refineSteps", std::to_string(o.volumeOptions.refineSteps),
                       "the refined GPU volume needs OpenGL 4.3 (compute shaders); this context has " +
                           context.info().glVersion);
    if (o.capture == CaptureMode::Midpoint)
      refuse("finds its crossings by one surface's rule (its rays or its walk); midpoint capture records the mean "
             "of two: use back, front or entry ${capture}, or ${volume} explicit with ${refineCrossings} rays");
    if (o.volumeOptions.cap != FarCap::Exact)
      refuse("needs ${volumeOptions.cap} exact: the quad cap keeps the far-plane sheet that refinement replaces by "
             "walls");
    if (o.volumeOptions.refineChords || o.volumeOptions.refineSubdivisions > 1 || o.volumeOptions.facePrisms)
      refuse(
          "finds the boundary edges' crossings alone: chord points, the sub-grid and the face prisms need ${volume} "
          "explicit with ${refineCrossings} rays");
    // The maps it walks, with their guard band: one (W + 2 G) x (H + 2 G) (mapFrame, G =
    // kVolumeGuardTexels), or a point light's six faces (drawRefinedCubeFaces), each (N + 2 G)^2
    // with G = kCubeGuardTexels.
    const bool point = light.type == LightType::Point;
    const int guard = point ? kCubeGuardTexels : kVolumeGuardTexels;
    const std::int64_t w = o.depthWidth + 2 * guard;
    const std::int64_t h = (point ? o.depthWidth : o.depthHeight) + 2 * guard;
    if (w * h > kMaxRefinedGpuTexels)
      throw InputError("RenderOptions", "depthWidth x depthHeight",
                       std::to_string(o.depthWidth) + "x" + std::to_string(o.depthHeight),
                       "the refined GPU volume takes maps of up to 2048 x 2048 texels (its index list is kept "
                       "under 512 MiB), its guard band of " + std::to_string(guard) +
                           " texels a side included (light.h), so up to " + std::to_string(2048 - 2 * guard) +
                           (point ? " texels per face" : " texels a side"));
    if (o.gpuVolumeDraw != GpuVolumeDraw::Auto)
      throw OptionConflict("RenderOptions", "gpuVolumeDraw", toString(o.gpuVolumeDraw),
                           "the refined GPU volume lists its triangles its own way: leave it at auto");
  }
  if (o.gpuVolumeDraw == GpuVolumeDraw::Refined)
    throw InputError("RenderOptions", "gpuVolumeDraw", "refined",
                     MarkedProblem{"is what a refined GPU volume (${volumeOptions.refineSteps} > 0) reports, not a choice"});
  if (o.refineCrossings == RefineCrossings::GpuWalk) {
    auto refuse = [](const std::string& value, const std::string& why) {  // a combination of options
      throw OptionConflict("RenderOptions", "refineCrossings", value, MarkedProblem{why});
    };
    if (o.method != ShadowMethod::Hybrid || o.volumeOptions.refineSteps == 0)
      refuse("gpu-walk", "the silhouette walk refines a hybrid volume: it needs ${method} hybrid and ${volumeOptions.refineSteps} > 0");
    if (!hasCompute)
      throw InputError("RenderOptions", "refineCrossings", "gpu-walk",
                       "the silhouette walk needs OpenGL 4.3 (compute shaders); this context has " +
                           context.info().glVersion);
    if (usesTwoLayers(o.capture))
      refuse("gpu-walk", std::string("the silhouette walk follows one layer; ") + toString(o.capture) +
                             " capture reads two: use ${refineCrossings} rays (gpu-rays for the GPU volume), or back "
                                           "or front ${capture}");
    if (o.volumeOptions.refineChords || o.volumeOptions.refineSubdivisions > 1 || o.volumeOptions.facePrisms)
      refuse("gpu-walk",
             "chord points, the sub-grid and the face prisms need ${refineCrossings} rays (a depth oracle); the walk "
             "gives the boundary edges' crossings alone");
  }
  if (o.refineCrossings == RefineCrossings::GpuRays && !refinedGpuVolume(o))
    throw OptionConflict("RenderOptions", "refineCrossings", "gpu-rays",
                     MarkedProblem{"the GPU's rays refine the GPU volume: it needs ${method} hybrid, ${volume} gpu and "
                                   "${volumeOptions.refineSteps} > 0 (the explicit volume casts Embree's rays: "
                                   "${refineCrossings} rays)"});
  if (o.explicitDepth == ExplicitDepth::Rays) {
    auto refuse = [](const std::string& why) {
      throw OptionConflict("RenderOptions", "explicitDepth", "rays", MarkedProblem{why});
    };
    if (o.method != ShadowMethod::Hybrid || o.volume != VolumeSource::Explicit)
      refuse("casts the explicit volume's depth map: it needs ${method} hybrid and ${volume} explicit");
    if (!o.volumeOptions.depthOracle)
      throw InputError("RenderOptions", "explicitDepth", "rays",
                       "needs volumeOptions.depthOracle, the scene's rays (EmbreeDepthOracle)");
    if (o.refineCrossings == RefineCrossings::GpuWalk)
      refuse(
          "has no light pass, whose triangle record the silhouette walk follows: use the light pass "
          "(${explicitDepth} gpu) or ${refineCrossings} rays");
  }
}

}  // namespace shadowvol::gl

// One frame: every light's passes in order (render, renderLight).
#include "renderer_impl.h"

namespace shadowvol::gl {

bool Renderer::Impl::chooseZPass(const RenderOptions& o, const CameraSetup& cam, bool givenVolume,
                                 RenderResult& result) const {
  if (givenVolume || o.method != ShadowMethod::Hybrid || o.volumeCount == VolumeCount::ZFail) return false;
  if (light.type == LightType::Point) {  // zpass.h decides for one frustum; the cube has six
    if (o.volumeCount == VolumeCount::ZPass)
      throw OptionConflict("RenderOptions", "volumeCount", "zpass", kPointZPassRule);
    result.zPassRefused = kPointZPassRule;
    return false;
  }
  Camera c = camera;
  c.width = cam.w;
  c.height = cam.h;
  const ZPassSafety z = zPassSafety(light, double(o.depthWidth) / double(o.depthHeight), c, o.volumeOptions);
  if (!z.safe && o.volumeCount == VolumeCount::ZPass)
    throw InputError("RenderOptions", "volumeCount", "zpass", "z-pass is not safe for this camera: " + z.reason);
  if (!z.safe) result.zPassRefused = z.reason;
  return z.safe;
}

std::size_t Renderer::Impl::useBuiltVolume(VolumeBuildResult&& built, const RenderOptions& o, PassTimer& timer,
                                           RenderResult& result, std::size_t leftOut) {
  result.biasUsed = built.stats.biasUsed;
  result.volumeStats = built.stats;
  const auto t0 = Clock::now();
  auto& tris = built.mesh.triangles;
  const std::size_t firstPartEnd = built.mesh.partStarts.empty() ? tris.size() : built.mesh.partStarts[0];
  SV_CHECK_LE(leftOut, firstPartEnd);
  const auto leftFirst = tris.begin() + std::ptrdiff_t(firstPartEnd - leftOut);
  const auto later = tris.begin() + std::ptrdiff_t(firstPartEnd);
  const std::ptrdiff_t laterCount = tris.end() - later;
  std::rotate(leftFirst, later, tris.end());  // the later parts before the triangles left out
  uploadVolume(built.mesh);
  std::rotate(leftFirst, leftFirst + laterCount, tris.end());  // and back: the parts as listed
  glFinish();
  timer.cpu("upload", msSince(t0));
  const std::size_t triangles = built.mesh.triangleCount() - leftOut;
  if (o.keepVolume) result.volume = std::move(built.mesh);
  return triangles;
}

RenderResult Renderer::Impl::render(const RenderOptions& o, const VolumeMesh* givenVolume) {
  context.makeCurrent();
  requireScene();
  const CameraSetup cam = cameraSetup(o);
  if (givenVolume && lights.size() > 1)
    throw InputError("Renderer", "renderWithVolume", std::to_string(lights.size()) + " lights",
                     "a caller-built volume is one light's: give a scene with one light");
  for (std::size_t k = 0; k < lights.size(); ++k) withLight(k, [&] { validateForLight(o, cam, k); });
  const bool gpuTimer = context.info().timerQueries && !context.info().softwareRenderer && !o.forceWallClock;
  PassTimer timer(queryPool, gpuTimer);
  RenderResult result = renderLight(o, cam, givenVolume, timer, false);
  for (std::size_t k = 1; k < lights.size(); ++k) {
    std::string suffix = "#";  // (not "#" + to_string: GCC 12's false -Wrestrict on that)
    suffix += std::to_string(k);
    timer.setSuffix(suffix);
    withLight(k, [&] { result.otherLights.push_back(renderLight(o, cam, nullptr, timer, true)); });
  }
  readColour(cam, result);
  result.timing = gpuTimer ? TimingMethod::GpuTimer : TimingMethod::WallClock;
  result.passes = timer.results();
  for (const auto& p : result.passes) result.totalMs += p.ms;
  return result;
}

void Renderer::Impl::validateForLight(const RenderOptions& o, const CameraSetup& cam, std::size_t k) const {
  if (lights.size() == 1) return validate(o, cam);
  const auto which = [&] { return " (for light " + std::to_string(k) + " of the scene's " + std::to_string(lights.size()) + ")"; };
  try {
    validate(o, cam);
  } catch (const OptionConflict& e) {  // stays a usage error, its marks kept (error.h)
    if (e.hasFieldMarks()) throw OptionConflict(e.source(), e.field(), e.value(), MarkedProblem{e.problemTemplate() + which()});
    throw OptionConflict(e.source(), e.field(), e.value(), e.problem() + which());
  } catch (const InputError& e) {
    if (e.hasFieldMarks()) throw InputError(e.source(), e.field(), e.value(), MarkedProblem{e.problemTemplate() + which()});
    throw InputError(e.source(), e.field(), e.value(), e.problem() + which());
  }
}

Renderer::Impl::LightFrame Renderer::Impl::planLightFrame(const RenderOptions& o, bool givenVolume) const {
  LightFrame f;
  const VolumeBuildOptions& vo = o.volumeOptions;
  f.given = givenVolume;
  f.silhouette = !givenVolume && o.method == ShadowMethod::Silhouette;
  f.hybrid = givenVolume || o.method == ShadowMethod::Hybrid;
  f.stencilShadows = f.hybrid || f.silhouette;
  f.point = light.type == LightType::Point;
  const bool gpuSource = f.hybrid && !givenVolume && o.volume == VolumeSource::Gpu;
  f.gpuVolume = gpuSource && !f.point;
  f.cubeGpu = gpuSource && f.point && vo.refineSteps == 0;
  f.refinedCube = gpuSource && f.point && vo.refineSteps > 0;
  f.refinedGpu = f.gpuVolume && refinedGpuVolume(o);
  f.gpuDraw = f.gpuVolume && !f.refinedGpu ? chooseGpuVolumeDraw(o.gpuVolumeDraw, vo)
              : f.refinedGpu               ? GpuVolumeDraw::Refined
                                           : GpuVolumeDraw::Auto;
  // The refined GPU volume lists its unrefined quads as the indexed way does.
  f.indexedVolume = f.gpuDraw == GpuVolumeDraw::Indexed || f.refinedGpu;
  f.dpsm = f.point && o.method == ShadowMethod::Dpsm;
  f.cubeShadowMap = f.point && !f.hybrid && !f.silhouette && !f.dpsm && o.method != ShadowMethod::None;
  f.rayDepth = f.hybrid && !givenVolume && o.volume == VolumeSource::Explicit &&
               chooseExplicitDepth(o, scene.triangleCount(), context.info().softwareRenderer, f.point ? 6 : 1) ==
                   ExplicitDepth::Rays;
  f.guarded = f.hybrid && !givenVolume && !f.point;
  return f;
}

Renderer::Impl::MapFrame Renderer::Impl::mapFrame(const RenderOptions& o, const LightFrame& f) const {
  MapFrame m{light, o};
  if (!f.guarded) return m;
  m.light = guardedLight(light, o.depthWidth, o.depthHeight, kVolumeGuardTexels);
  m.options.depthWidth += 2 * kVolumeGuardTexels;
  m.options.depthHeight += 2 * kVolumeGuardTexels;
  return m;
}

void Renderer::Impl::lightDepthPasses(const RenderOptions& o, const LightFrame& f, PassTimer& timer) {
  occupancyValid = false;
  if (f.cubeShadowMap) {
    TimedPass t(timer, "light");
    cubeShadowPass(o.depthWidth, o.capture);
  }
  if (f.dpsm) {
    TimedPass t(timer, "light");
    paraboloidPass(o.depthWidth, o.capture, o.paraboloidSubdivision);
  }
  if (!f.given && o.method != ShadowMethod::None && !f.silhouette && !f.point && !f.rayDepth) {
    TimedPass t(timer, "light");
    // The triangle record for the walk (the GPU's rays do not read it).
    lightPass(o.depthWidth, o.depthHeight, o.capture, f.indexedVolume,
              walkCrossings(o) || (f.refinedGpu && o.refineCrossings == RefineCrossings::GpuWalk));
  }
}

std::size_t Renderer::Impl::explicitCubeVolume(const RenderOptions& o, const LightFrame& f, PassTimer& timer,
                                               RenderResult& result) {
  const VolumeBuildOptions& vo = o.volumeOptions;
  auto t0 = Clock::now();
  const CubeDepthMap cube =
      f.rayDepth ? rayCastCube(o.depthWidth, o.capture, vo.depthOracle) : captureCube(o.depthWidth, o.capture);
  timer.cpu("light", msSince(t0));  // six light passes and their read-backs, or the faces' rays
  t0 = Clock::now();
  VolumeBuildResult built = buildCubeVolume(cube, vo);
  timer.cpu("build", msSince(t0));
  return useBuiltVolume(std::move(built), o, timer, result);  // z-fail: the cap too
}

std::size_t Renderer::Impl::explicitVolume(const RenderOptions& o, const LightFrame& f, PassTimer& timer,
                                           RenderResult& result) {
  const VolumeBuildOptions& vo = o.volumeOptions;
  auto t0 = Clock::now();
  if (f.rayDepth) {
    result.depthMap = rayCast(o.depthWidth, o.depthHeight, o.capture, vo.depthOracle);
    timer.cpu("light", msSince(t0));
  } else {
    result.depthMap = readBack(o.capture);
    timer.cpu("readback", msSince(t0));
  }
  t0 = Clock::now();
  VolumeBuildResult built = buildVolume(*result.depthMap, walkCrossings(o) ? withWalk(vo) : vo);
  timer.cpu("build", msSince(t0));
  // The cap comes last in the volume's first part (volume_builder.h): z-pass draws the rest, the
  // face prisms' part whole (its far caps lie behind every visible point too, as the cap does).
  const std::size_t cap = zPassFrame ? built.stats.capTrianglesAfter : 0;
  return useBuiltVolume(std::move(built), o, timer, result, cap);
}

std::size_t Renderer::Impl::silhouetteVolume(PassTimer& timer, RenderResult& result) {
  auto t0 = Clock::now();
  if (!occluders) {
    occluders.emplace(scene);  // throws InputError naming a non-manifold object
    timer.cpu("connectivity", msSince(t0));
    t0 = Clock::now();
  }
  SilhouetteVolume built = buildSilhouetteVolume(*occluders, light);
  timer.cpu("build", msSince(t0));
  t0 = Clock::now();
  uploadVolume(built.mesh);
  glFinish();
  timer.cpu("upload", msSince(t0));
  result.receiversOnly = std::move(built.receiversOnly);
  result.skippedCasters = std::move(built.skipped);
  return built.mesh.triangleCount();
}

void Renderer::Impl::volumeInput(const RenderOptions& o, LightFrame& f, const VolumeMesh* givenVolume, PassTimer& timer,
                                 RenderResult& result) {
  const VolumeBuildOptions& vo = o.volumeOptions;
  if (f.cubeGpu) {
    cubeVolumeDepthPass(o, timer, result);
  } else if (f.hybrid && !givenVolume && f.point && !f.refinedCube) {
    f.explicitTriangles = explicitCubeVolume(o, f, timer, result);
  } else if (f.hybrid && !givenVolume && o.volume == VolumeSource::Explicit) {
    f.explicitTriangles = explicitVolume(o, f, timer, result);
  } else if (f.silhouette) {
    f.explicitTriangles = silhouetteVolume(timer, result);
  } else if (givenVolume) {
    const auto t0 = Clock::now();
    uploadVolume(*givenVolume);
    glFinish();
    timer.cpu("upload", msSince(t0));
    f.explicitTriangles = givenVolume->triangleCount();
  } else if (f.hybrid && !f.refinedCube) {
    f.volumeDepth = gpuVolumeDepth(o, f.indexedVolume, timer);
    result.biasUsed = vo.bias ? *vo.bias : defaultBias(light, lightW, lightH, o.capture);
    if (f.refinedGpu) {
      TimedPass t(timer, "crossings");
      findGpuCrossings(vo, result.biasUsed, *f.volumeDepth, o.refineCrossings, o.capture);
    }
  } else if (o.method != ShadowMethod::None && usesTwoLayers(o.capture) && !f.point) {
    TimedPass t(timer, "resolve");  // the two layers' window depth for the hardware compare
    resolvePass(o.capture);
  }
}

void Renderer::Impl::stencilPasses(const RenderOptions& o, const MapFrame& map, const CameraSetup& cam,
                                   const LightFrame& f, PassTimer& timer, bool added, RenderResult& result) {
  const VolumeBuildOptions& vo = o.volumeOptions;
  // The light frustum's aspect: the options' size (the map's has a guard band; silhouette and a
  // caller's volume have none); a point light's faces' pass sizes.
  const int frustumW = f.point ? std::max(lightW, 2) : o.depthWidth;
  const int frustumH = f.point ? std::max(lightH, 2) : o.depthHeight;
  if (added) {
    beginAddedLight(cam, false);
  } else {
    TimedPass t(timer, "camera");
    beginCamera(cam, CameraExtra::Ambient);
    setSceneUniforms(cam, o, 0, frustumW, frustumH);
    drawScene();
    SV_GL(glDrawBuffer(GL_COLOR_ATTACHMENT0));  // the volume pass writes no colour
  }
  if (f.refinedCube) {
    drawRefinedCubeFaces(o, cam, timer, result);
  } else {
    TimedPass t(timer, f.silhouette ? "silhouette" : "volume");
    const LightRestore restore{light, light};
    light = map.light;
    beginVolume(zPassFrame);
    if (f.refinedGpu)
      drawRefinedGpuVolume(cam, vo, result.biasUsed, *f.volumeDepth, result);
    else if (f.volumeDepth)
      drawGpuVolume(cam, vo, result.biasUsed, *f.volumeDepth, f.gpuDraw, result);
    else if (f.cubeGpu)
      drawCubeGpuVolume(cam);
    else
      drawExplicitVolume(cam, f.explicitTriangles, result);
    endVolume();
  }
  TimedPass t(timer, "lighting");
  if (added)
    addDiffusePass(cam, o, frustumW, frustumH);
  else
    lightingPass(cam, double(frustumW) / double(frustumH));
}

void Renderer::Impl::shadeWithMap(const RenderOptions& o, const CameraSetup& cam, const LightFrame& f, PassTimer& timer,
                                  bool added) {
  TimedPass t(timer, "shade");
  const int taps = o.method == ShadowMethod::ShadowMap || o.method == ShadowMethod::Dpsm ? 1
                   : o.method == ShadowMethod::Pcf3                                      ? 3
                   : o.method == ShadowMethod::Pcf5                                      ? 5
                                                                                         : 0;
  const bool writeVisibility = o.readVisibility && taps > 0;
  if (added)
    beginAddedLight(cam, writeVisibility);
  else
    beginCamera(cam, writeVisibility ? CameraExtra::Visibility : CameraExtra::None);
  const int mw = f.dpsm ? paraboloidFrame.side : taps ? lightW : o.depthWidth;
  const int mh = f.dpsm ? paraboloidFrame.side : taps ? lightH : o.depthHeight;
  setSceneUniforms(cam, o, taps, mw, mh);
  if (f.dpsm) setParaboloidUniforms(o);
  sceneProgram.set("writeVisibility", writeVisibility ? 1 : 0);
  if (added) addDiffuseState(false);
  if (taps && !f.point) bindTexture(2, usesTwoLayers(o.capture) ? resolvedDepth : layer0, shadowSampler);
  if (taps && f.point && f.dpsm) bindTexture(2, paraboloid.texture(), shadowSampler);
  if (taps && f.point && !f.dpsm) bindCube(3, cubeShadow, shadowSampler);
  drawScene();
  bindTexture(2, Texture(), shadowSampler);
  bindCube(3, Texture(), shadowSampler);
  resetState();
}

void Renderer::Impl::lightFrameResults(const RenderOptions& o, const CameraSetup& cam, const LightFrame& f,
                                       RenderResult& result) {
  const VisibilitySource visibility = !o.readVisibility                ? VisibilitySource::NotRead
                                      : f.stencilShadows               ? VisibilitySource::FromStencil
                                      : o.method == ShadowMethod::None ? VisibilitySource::AllLit
                                                                       : VisibilitySource::FromAttachment;
  readShadowImages(cam, f.stencilShadows && o.readStencil, visibility, result);
  result.explicitDepthUsed = f.rayDepth ? ExplicitDepth::Rays : ExplicitDepth::LightPass;
  if (f.cubeGpu) std::tie(result.volumeTriangles, result.gpuVolumeQuadsDrawn) = cubeVolume.lastCounts();
  if (volumeTrianglesPending) {  // after the frame, so reading the query does not stall a pass
    GLuint64 n = 0;
    SV_GL(glGetQueryObjectui64v(primitivesQuery.id(), GL_QUERY_RESULT, &n));
    result.volumeTriangles = std::size_t(n);
    volumeTrianglesPending = false;
  }
  if (f.refinedGpu && o.keepVolume) refinedGpuDebugMeshes(cam, o, *f.volumeDepth, result);
  if (o.readDepthMap && !result.depthMap && !f.given && o.method != ShadowMethod::None && !f.silhouette && !f.point)
    result.depthMap = readBack(o.capture);
}

RenderResult Renderer::Impl::renderLight(const RenderOptions& o, const CameraSetup& cam, const VolumeMesh* givenVolume,
                                         PassTimer& timer, bool added) {
  volumeTrianglesPending = false;  // a frame that threw may have left it set
  volumeReadsWindowDepth = false;
  RenderResult result;
  LightFrame f = planLightFrame(o, givenVolume != nullptr);
  const MapFrame map = mapFrame(o, f);
  const LightRestore restore{light, light};
  light = map.light;  // the depth passes and the volume's input: the map's light
  zPassFrame = chooseZPass(map.options, cam, givenVolume != nullptr, result);
  result.volumeCountUsed = zPassFrame ? VolumeCount::ZPass : VolumeCount::ZFail;
  lightDepthPasses(map.options, f, timer);
  volumeInput(map.options, f, givenVolume, timer, result);
  light = restore.saved;  // the camera and lighting passes: the light's own window
  if (f.stencilShadows)
    stencilPasses(o, map, cam, f, timer, added, result);
  else
    shadeWithMap(o, cam, f, timer, added);
  light = map.light;  // read-backs of the map and the GPU volume's meshes
  lightFrameResults(map.options, cam, f, result);
  if (result.depthMap && f.guarded) result.depthMap->guard = kVolumeGuardTexels;
  return result;
}

}  // namespace shadowvol::gl

// The refined GPU volume (docs/gpu.md 'The refined GPU volume'): its crossings, walk inputs and
// debug meshes, and a point light's refined faces.
#include "renderer_impl.h"

namespace shadowvol::gl {

bool Renderer::Impl::refinedGpuVolume(const RenderOptions& o) {
  return o.method == ShadowMethod::Hybrid && o.volume == VolumeSource::Gpu && o.volumeOptions.refineSteps > 0;
}

bool Renderer::Impl::walkCrossings(const RenderOptions& o) {
  return o.refineCrossings == RefineCrossings::GpuWalk && o.method == ShadowMethod::Hybrid &&
         o.volume == VolumeSource::Explicit && o.volumeOptions.refineSteps > 0;
}

VolumeBuildOptions Renderer::Impl::withWalk(const VolumeBuildOptions& vo) {
  VolumeBuildOptions v = vo;
  v.crossingSource = [this](const DepthMap& map, const BoundaryEdges& edges, const SheetDepthRule& rule, bool blur,
                            std::span<const double> blurred, std::span<const glm::dvec2> centres) {
    return walk.run(walkInputs(), map, edges, rule, blur, blurred, centres);
  };
  return v;
}

WalkInputs Renderer::Impl::walkInputs() {
  setVolumeUniforms(walk.program(), VolumeBuildOptions(), 0.0);  // the map's size and projection
  WalkInputs in;
  in.sceneVertices = sceneVbo.id();
  in.sceneIndices = sceneEbo.id();
  in.vertexStride = kSceneVertexFloats;
  in.triangleIds = triangleIds.id();
  in.width = triangleIdsW;
  in.height = triangleIdsH;
  in.worldToLightView = toFloat(lightView(light));
  in.lightViewToWorld = toFloat(glm::inverse(lightView(light)));
  return in;
}

void Renderer::Impl::refinedGpuDebugMeshes(const CameraSetup& cam, const RenderOptions& o, const Texture& volumeDepth,
                                           RenderResult& result) {
  const VolumeBuildOptions& vo = o.volumeOptions;
  result.depthMap = readBack(o.capture);
  VolumeBuildOptions v = vo;
  v.crossingSource = gpuCrossingSource();
  // The GPU's own boundary edges (its float rule can differ from the CPU's double one where a
  // jump equals the threshold); the CPU rule's edges on the same map are counted against them.
  v.boundaryEdgeSource = [flags = refined->readFlags(), &result](const DepthMap& map, const SheetDepthRule& rule,
                                                                 bool blur, std::span<const double> blurred,
                                                                 std::uint8_t* splitBits) {
    BoundaryEdges gpu = boundaryEdgesFromFlags(map.width, map.height, flags, splitBits);
    result.cpuRuleEdgeDifferences = differingBoundaryEdges(gpu, findBoundaryEdges(map, rule, blur, blurred));
    return gpu;
  };
  VolumeBuildResult built = buildVolume(*result.depthMap, v);
  result.volume = std::move(built.mesh);
  result.volumeStats = built.stats;
  const SheetDepthRule rule(*result.depthMap, result.biasUsed, vo.blurOffset);
  // The list again, with the cap where the frame (z-pass) drew none: the closed mesh. (The
  // frame is drawn: zPassFrame = false only makes setVolumeUniforms set drawCap = 1.)
  zPassFrame = false;
  for (const Program* p : refined->programs()) setVolumeUniforms(*p, vo, result.biasUsed);
  bindTexture(3, vo.blur ? linearDepth : volumeDepth, fetchSampler);
  std::array<GLuint, 2> listed{};
  SV_CHECK(listIndexedGpuVolume(cam, vo, result.biasUsed, volumeDepth, std::int64_t(lightW - 1) * (lightH - 1), listed,
                                &*refined));
  bindTexture(3, Texture(), fetchSampler);
  const std::vector<std::uint32_t> indices = readIndexList(listed[0]);
  result.gpuVolume = decodeRefinedGpuVolume(*result.depthMap, rule, vo.blur, indices, refined->readRecords());
}

const Texture* Renderer::Impl::gpuVolumeDepth(const RenderOptions& o, bool indexedVolume, PassTimer& timer) {
  const VolumeBuildOptions& vo = o.volumeOptions;
  volumeReadsWindowDepth = indexedVolume && !usesTwoLayers(o.capture) && !vo.blur;  // refined too
  const Texture* depth = &layer0;
  if (!volumeReadsWindowDepth) {
    TimedPass t(timer, "resolve");
    resolvePass(o.capture);
    depth = &linearDepth;
  }
  if (vo.blur) {
    TimedPass t(timer, "blur");
    blurPass(vo.blurOffset);
    depth = &blurredDepth;
  }
  return depth;
}

void Renderer::Impl::drawRefinedCubeFaces(const RenderOptions& o, const CameraSetup& cam, PassTimer& timer,
                                          RenderResult& result) {
  const VolumeBuildOptions& vo = o.volumeOptions;
  const int n = o.depthWidth, m = n + 2 * kCubeGuardTexels;
  result.biasUsed = vo.bias ? *vo.bias : defaultBias(light, n, n, o.capture);
  result.gpuVolumeDrawUsed = GpuVolumeDraw::Refined;
  result.stencilBits = 7;
  if (o.keepVolume) result.faceVolumes.resize(kCubeFaces), result.faceGpuVolumes.resize(kCubeFaces);
  const LightRestore restore{light, light};
  const Light& point = restore.saved;
  {
    TimedPass t(timer, "volume");
    writeCubeFaceImage(cam, point.position);
  }
  for (int f = 0; f < kCubeFaces; ++f) {
    light = guardedCubeFaceLight(point, f, n, kCubeGuardTexels);
    {
      TimedPass t(timer, "light");
      lightPass(m, m, o.capture, true, o.refineCrossings == RefineCrossings::GpuWalk);  // the walk's record
    }
    const Texture* depth = gpuVolumeDepth(o, true, timer);
    {
      TimedPass t(timer, "crossings");
      findGpuCrossings(vo, result.biasUsed, *depth, o.refineCrossings, o.capture);
    }
    RenderResult face;
    face.biasUsed = result.biasUsed;
    {
      TimedPass t(timer, "volume");  // the face's mask and its volume
      maskOtherCubeFaces(cam, f);
      beginVolume(false);
      SV_GL(glStencilMask(0x7F));
      SV_GL(glStencilFunc(GL_EQUAL, 0, 0x80));
      drawRefinedGpuVolume(cam, vo, result.biasUsed, *depth, face);
      endVolume();
    }
    GLuint64 triangles = 0;  // the face's draw, read now: the next face's draw reuses the query
    SV_GL(glGetQueryObjectui64v(primitivesQuery.id(), GL_QUERY_RESULT, &triangles));
    volumeTrianglesPending = false;
    result.volumeTriangles += std::size_t(triangles);
    result.gpuVolumeQuads += face.gpuVolumeQuads;
    result.gpuVolumeQuadsDrawn += face.gpuVolumeQuadsDrawn;
    result.gpuBoundaryEdges += face.gpuBoundaryEdges;
    result.gpuCrossingFallbacks += face.gpuCrossingFallbacks;
    if (o.keepVolume) {
      refinedGpuDebugMeshes(cam, o, *depth, face);
      result.cpuRuleEdgeDifferences += face.cpuRuleEdgeDifferences;
      result.faceVolumes[std::size_t(f)] = std::move(*face.volume);
      result.faceGpuVolumes[std::size_t(f)] = std::move(*face.gpuVolume);
    }
    light = point;
  }
  resetState();
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, cameraFbo.id()));
  SV_GL(glViewport(0, 0, cam.w, cam.h));
  SV_GL(glStencilMask(0x80));  // the last mask cleared: bits 0-6 are the counts
  SV_GL(glClearStencil(0));
  SV_GL(glClear(GL_STENCIL_BUFFER_BIT));
  resetState();
}

}  // namespace shadowvol::gl

// Shadow volumes drawn from the light's depth texture (VolumeSource::Gpu): every quad through the
// geometry shader, the kept quads, the compute-built mesh or the indexed list (GpuVolumeDraw).
#include "renderer_impl.h"

namespace shadowvol::gl {

void Renderer::Impl::setVolumeUniforms(const Program& p, const VolumeBuildOptions& vo, double bias) {
  const glm::dmat4 lp = lightProjection(light, double(lightW) / double(lightH));
  p.use();
  p.set("lightDepth", 0);
  p.set("size", glm::ivec2(lightW, lightH));
  p.set("farPlane", float(light.farPlane));
  p.set("nearPlane", float(light.nearPlane));
  p.set("farSnap", float(light.farPlane * (1.0 - kFarSnap)));
  p.set("bias", float(bias));
  p.set("projXY", glm::vec4(float(lp[0][0]), float(lp[1][1]), float(lp[3][0]), float(lp[3][1])));
  p.set("projShear", glm::vec2(float(lp[2][0]), float(lp[2][1])));
  p.set("projZW", depthParams(lp));
  p.set("perfect", vo.triangulation == Triangulation::Perfect ? 1 : 0);
  p.set("exactCap", vo.cap == FarCap::Exact ? 1 : 0);
  p.set("drawCap", zPassFrame ? 0 : 1);
  p.set("planarTolerance", float(kPlanarTolerance));
  p.set("windowDepthInput", volumeReadsWindowDepth ? 1 : 0);
  p.set("depthParams", depthParams(reversedZ(lp)));
}

GpuVolumeDraw Renderer::Impl::chooseGpuVolumeDraw(GpuVolumeDraw how, const VolumeBuildOptions& vo) const {
  if (vo.cap != FarCap::Exact) return GpuVolumeDraw::AllQuads;
  if (how == GpuVolumeDraw::Auto) return hasCompute ? GpuVolumeDraw::Indexed : GpuVolumeDraw::KeptQuads;
  if ((how == GpuVolumeDraw::ComputeMesh || how == GpuVolumeDraw::Indexed) && !hasCompute)
    throw InputError("RenderOptions", "gpuVolumeDraw", toString(how),
                     std::string("needs GL 4.3 (") +
                         (how == GpuVolumeDraw::Indexed ? "shader storage buffers and image atomics in fragment shaders"
                                                        : "compute shaders") +
                         "); this context is " + context.info().glVersion);
  return how;
}

void Renderer::Impl::drawGpuVolume(const CameraSetup& cam, const VolumeBuildOptions& vo, double bias,
                                   const Texture& depth, GpuVolumeDraw how, RenderResult& result) {
  const glm::dmat4 lightViewToClip = cam.proj * cam.view * glm::inverse(lightView(light));
  const std::int64_t quads = std::int64_t(lightW - 1) * std::int64_t(lightH - 1);
  result.gpuVolumeQuads = std::size_t(quads);
  result.gpuVolumeQuadsDrawn = std::size_t(quads);
  // KeptQuads needs 4 bytes per quad: up to 2^26 quads (8193^2 maps: 8189^2 with the guard band), 256 MB.
  constexpr std::int64_t kMaxKeptQuads = std::int64_t(1) << 26;
  if (how == GpuVolumeDraw::Indexed && drawIndexedGpuVolume(cam, lightViewToClip, vo, bias, depth, quads, result)) {
    result.gpuVolumeDrawUsed = how;
    return;
  }
  if (how == GpuVolumeDraw::ComputeMesh && quads <= kMaxKeptQuads &&
      drawComputedGpuVolume(lightViewToClip, vo, bias, depth, quads, result)) {
    result.gpuVolumeDrawUsed = how;
    return;
  }
  // Indexed or ComputeMesh whose list would not fit
  if (how == GpuVolumeDraw::Indexed || how == GpuVolumeDraw::ComputeMesh) how = GpuVolumeDraw::KeptQuads;
  if (how == GpuVolumeDraw::KeptQuads && quads > kMaxKeptQuads) how = GpuVolumeDraw::AllQuads;
  result.gpuVolumeDrawUsed = how;
  if (how == GpuVolumeDraw::KeptQuads) return drawCompactGpuVolume(lightViewToClip, vo, bias, depth, quads, result);
  setVolumeUniforms(volumeGpuProgram, vo, bias);
  volumeGpuProgram.set("lightViewToClip", toFloat(lightViewToClip));
  bindTexture(0, depth, fetchSampler);
  // gl_VertexID and GLsizei are 32-bit: draw at most kChunkQuads points (quads) per call.
  constexpr std::int64_t kChunkQuads = std::int64_t(1) << 30;
  SV_GL(glBindVertexArray(emptyVao.id()));
  SV_GL(glBeginQuery(GL_PRIMITIVES_GENERATED, primitivesQuery.id()));
  volumeGpuProgram.set("drawRectangle", 0);
  for (std::int64_t first = 0; first < quads; first += kChunkQuads) {
    volumeGpuProgram.set("firstQuad", int(first));
    SV_GL(glDrawArrays(GL_POINTS, 0, GLsizei(std::min(kChunkQuads, quads - first))));
  }
  if (vo.cap == FarCap::Quad && !zPassFrame) {  // the far rectangle: a fan over the ring (volume_gpu.geom)
    volumeGpuProgram.set("drawRectangle", 1);
    volumeGpuProgram.set("firstQuad", 0);
    SV_GL(glDrawArrays(GL_POINTS, 0, GLsizei(2 * (lightW - 1) + 2 * (lightH - 1))));
  }
  SV_GL(glEndQuery(GL_PRIMITIVES_GENERATED));
  SV_GL(glBindVertexArray(0));
  volumeTrianglesPending = true;
}

bool Renderer::Impl::drawComputedGpuVolume(const glm::dmat4& lightViewToClip, const VolumeBuildOptions& vo, double bias,
                                           const Texture& depth, std::int64_t quads, RenderResult& result) {
  constexpr std::int64_t kMaxMeshBytes = std::int64_t(1) << 29;  // 512 MiB
  constexpr std::int64_t kVertexBytes = 12;
  if (meshCapacity == 0) growMesh(std::min<std::int64_t>(quads * 12, 12 * 65536));
  bindTexture(0, depth, fetchSampler);
  setVolumeUniforms(volumeMeshProgram, vo, bias);
  GLuint count = 0;
  for (int attempt = 0; attempt < 2; ++attempt) {
    const GLuint zero = 0;
    SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, meshCount.id()));
    SV_GL(glBufferData(GL_SHADER_STORAGE_BUFFER, sizeof(GLuint), &zero, GL_DYNAMIC_READ));
    SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, meshCount.id()));
    SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, meshBuffer.id()));
    volumeMeshProgram.set("capacity", int(std::min<std::int64_t>(meshCapacity, 0x7fffffff)));
    // Work groups of 64 quads, in rows of at most 65535 (the smallest GL_MAX_COMPUTE_WORK_GROUP_COUNT).
    const std::int64_t groups = (quads + 63) / 64, row = std::min<std::int64_t>(groups, 65535);
    SV_GL(glDispatchCompute(GLuint(row), GLuint((groups + row - 1) / row), 1));
    SV_GL(glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT));
    SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, meshCount.id()));
    SV_GL(glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(GLuint), &count));
    if (std::int64_t(count) <= meshCapacity) break;
    if (std::int64_t(count) * kVertexBytes > kMaxMeshBytes) return false;
    growMesh(std::int64_t(count) + std::int64_t(count) / 4);
  }
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0));
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0));
  if (std::int64_t(count) > meshCapacity) return false;
  result.gpuVolumeQuadsDrawn = count / (zPassFrame ? 6 : 12);
  result.volumeTriangles = count / 3;
  volumeMeshDrawProgram.use();
  volumeMeshDrawProgram.set("lightViewToClip", toFloat(lightViewToClip));
  SV_GL(glBindVertexArray(meshVao.id()));
  SV_GL(glDrawArrays(GL_TRIANGLES, 0, GLsizei(count)));
  SV_GL(glBindVertexArray(0));
  return true;
}

bool Renderer::Impl::drawIndexedGpuVolume(const CameraSetup& cam, const glm::dmat4& lightViewToClip,
                                          const VolumeBuildOptions& vo, double bias, const Texture& depth,
                                          std::int64_t quads, RenderResult& result, RefinedGpuVolume* cells) {
  std::array<GLuint, 2> counts{};  // indices, kept quads
  if (!listIndexedGpuVolume(cam, vo, bias, depth, quads, counts, cells)) return false;
  result.gpuVolumeQuadsDrawn = counts[1];
  const Program& draw = cells ? cells->drawProgram() : volumeIndexedProgram;
  setVolumeUniforms(draw, vo, bias);
  draw.set("lightViewToClip", toFloat(lightViewToClip));
  SV_GL(glBindVertexArray(indexVao.id()));
  SV_GL(glBeginQuery(GL_PRIMITIVES_GENERATED, primitivesQuery.id()));
  SV_GL(glDrawElements(GL_TRIANGLES, GLsizei(counts[0]), GL_UNSIGNED_INT, nullptr));
  SV_GL(glEndQuery(GL_PRIMITIVES_GENERATED));
  SV_GL(glBindVertexArray(0));
  volumeTrianglesPending = true;
  return true;
}

bool Renderer::Impl::listIndexedGpuVolume(const CameraSetup& cam, const VolumeBuildOptions& vo, double bias,
                                          const Texture& depth, std::int64_t quads, std::array<GLuint, 2>& counts,
                                          RefinedGpuVolume* cells) {
  constexpr std::int64_t kMaxIndexBytes = std::int64_t(1) << 29;  // 512 MiB
  constexpr int kBlockX = 8, kBlockY = 4;                         // volume_index.frag's kBlock
  // Indices and the count are 32-bit: 2 W H vertices (8 W H with the refined cells' crossings),
  // up to 12 indices per quad (60 in a refined cell).
  if (std::int64_t(lightW) * lightH * (cells ? 8 : 2) > std::int64_t(0x7fffffff) ||
      quads * (cells ? 60 : 12) > std::int64_t(0xffffffff))
    return false;
  const GLuint skipRefinedFlags = cells ? cells->flags() : 0;
  if (indexCapacity == 0) growIndices(std::min<std::int64_t>(quads * 12, 12 * 65536));
  const int blocksX = (lightW - 1 + kBlockX - 1) / kBlockX, blocksY = (lightH - 1 + kBlockY - 1) / kBlockY;
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, listFbo.id()));
  SV_GL(glFramebufferParameteri(GL_FRAMEBUFFER, GL_FRAMEBUFFER_DEFAULT_WIDTH, blocksX));
  SV_GL(glFramebufferParameteri(GL_FRAMEBUFFER, GL_FRAMEBUFFER_DEFAULT_HEIGHT, blocksY));
  SV_GL(glViewport(0, 0, blocksX, blocksY));
  bindTexture(0, depth, fetchSampler);
  SV_CHECK(occupancyValid);  // the light pass marked the covered texels (render: indexedVolume)
  bindTexture(1, occupancy, fetchSampler);
  setVolumeUniforms(volumeIndexProgram, vo, bias);
  volumeIndexProgram.set("occupancy", 1);
  volumeIndexProgram.set("skipRefined", skipRefinedFlags != 0 ? 1 : 0);  // with the refined GPU volume's flags
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, skipRefinedFlags));
  GLuint& count = counts[0];
  for (int attempt = 0; attempt < 2; ++attempt) {
    const GLuint zero[2] = {0, 0};
    SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, indexCount.id()));
    SV_GL(glBufferData(GL_SHADER_STORAGE_BUFFER, sizeof(zero), zero, GL_DYNAMIC_READ));
    SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, indexCount.id()));
    SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, indexBuffer.id()));
    if (cells) {  // the refined cells first, into the same list
      cells->dispatchCells(indexCapacity);
      SV_GL(glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT));
      SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, skipRefinedFlags));
    }
    volumeIndexProgram.use();
    volumeIndexProgram.set("capacity", int(std::min<std::int64_t>(indexCapacity, 0x7fffffff)));
    SV_GL(glBindVertexArray(emptyVao.id()));
    SV_GL(glDrawArrays(GL_TRIANGLES, 0, 3));
    SV_GL(glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_ELEMENT_ARRAY_BARRIER_BIT));
    SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, indexCount.id()));
    SV_GL(glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(sizeof(counts)), counts.data()));
    if (std::int64_t(count) <= indexCapacity) break;
    if (std::int64_t(count) * 4 > kMaxIndexBytes) break;
    growIndices(std::int64_t(count) + std::int64_t(count) / 4);
  }
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0));
  SV_GL(glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, 0));
  SV_GL(glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0));
  bindTexture(1, Texture(), fetchSampler);
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, cameraFbo.id()));
  SV_GL(glViewport(0, 0, cam.w, cam.h));
  return std::int64_t(count) <= indexCapacity;
}

std::vector<std::uint32_t> Renderer::Impl::readIndexList(GLuint count) {
  std::vector<std::uint32_t> out(count);
  if (out.empty()) return out;
  SV_GL(glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT));
  SV_GL(glBindBuffer(GL_COPY_READ_BUFFER, indexBuffer.id()));
  SV_GL(glGetBufferSubData(GL_COPY_READ_BUFFER, 0, GLsizeiptr(out.size() * 4), out.data()));
  SV_GL(glBindBuffer(GL_COPY_READ_BUFFER, 0));
  return out;
}

void Renderer::Impl::findGpuCrossings(const VolumeBuildOptions& vo, double bias, const Texture& depth,
                                      RefineCrossings crossings, CaptureMode capture) {
  if (!refined) refined.emplace(shaders);  // compiled on the first refined frame
  if (!footprint || footprintW != lightW || footprintH != lightH) {
    footprint = TexelFootprint::of(makeDepthMap(light, lightW, lightH, CaptureMode::Back));  // metadata only
    footprintW = lightW, footprintH = lightH;
  }
  const WalkInputs in = walkInputs();  // sets the walk's map uniforms (bias 0): before the ones below
  std::vector<const Program*> programs = refined->programs();
  programs.push_back(&walk.program());
  programs.push_back(&rays.program());
  for (const Program* p : programs) {
    setVolumeUniforms(*p, vo, bias);
    p->set("blurOn", vo.blur ? 1 : 0);
    p->set("blurOffset", float(vo.blurOffset));
  }
  bindTexture(0, depth, fetchSampler);
  bindTexture(3, vo.blur ? linearDepth : depth, fetchSampler);
  const double farSnap = light.farPlane * (1.0 - kFarSnap);
  const double hitLimit = std::min(farSnap, farSnap - bias - (vo.blur ? vo.blurOffset : 0.0));
  const bool byRays = crossings != RefineCrossings::GpuWalk;
  refined->findCrossings(lightW, lightH, *footprint, [&](GLintptr indirectOffset) {
    const Program& p = byRays ? rays.program() : walk.program();
    p.use();
    p.set("rawDepth", 3);
    if (byRays)
      rays.dispatchGrid(in, vo.refineSteps, capture, vo.refineSnap, indirectOffset);
    else
      walk.dispatchGrid(in, hitLimit, indirectOffset);
  });
}

void Renderer::Impl::drawRefinedGpuVolume(const CameraSetup& cam, const VolumeBuildOptions& vo, double bias,
                                          const Texture& depth, RenderResult& result) {
  const glm::dmat4 lightViewToClip = cam.proj * cam.view * glm::inverse(lightView(light));
  const std::int64_t quads = std::int64_t(lightW - 1) * std::int64_t(lightH - 1);
  bindTexture(3, vo.blur ? linearDepth : depth, fetchSampler);
  const bool drawn = drawIndexedGpuVolume(cam, lightViewToClip, vo, bias, depth, quads, result, &*refined);
  bindTexture(3, Texture(), fetchSampler);
  SV_GL(glActiveTexture(GL_TEXTURE2));
  SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, 0));
  SV_GL(glActiveTexture(GL_TEXTURE0));
  if (!drawn)
    throw InputError("RenderOptions", "depthWidth x depthHeight",
                     std::to_string(lightW - 2 * kVolumeGuardTexels) + "x" + std::to_string(lightH - 2 * kVolumeGuardTexels),
                     "the refined GPU volume's index list (of the map and its guard band, light.h) would pass 512 MiB "
                     "or 32-bit indices: use a smaller map");
  const RefinedGpuCounts counts = refined->walkCounts();
  result.gpuVolumeDrawUsed = GpuVolumeDraw::Refined;
  result.gpuVolumeQuads = std::size_t(quads);
  result.gpuBoundaryEdges = counts.boundaryEdges;
  result.gpuCrossingFallbacks = counts.fallbacks;
}

CrossingSource Renderer::Impl::gpuCrossingSource() {
  return [flags = refined->readFlags(), records = refined->readRecords()](
             const DepthMap& map, const BoundaryEdges& edges, const SheetDepthRule& rule, bool blur,
             std::span<const double> blurred, std::span<const glm::dvec2> centres) {
    return refinementFromGpuRecords(map, edges, rule, blur, blurred, centres, flags, records);
  };
}

void Renderer::Impl::growIndices(std::int64_t indices) {
  SV_GL(glBindVertexArray(indexVao.id()));
  SV_GL(glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer.id()));
  SV_GL(glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices * 4), nullptr, GL_DYNAMIC_COPY));
  SV_GL(glBindVertexArray(0));
  indexCapacity = indices;
}

void Renderer::Impl::growMesh(std::int64_t vertices) {
  SV_GL(glBindBuffer(GL_ARRAY_BUFFER, meshBuffer.id()));
  SV_GL(glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices * 12), nullptr, GL_DYNAMIC_COPY));
  SV_GL(glBindVertexArray(meshVao.id()));
  SV_GL(glEnableVertexAttribArray(0));
  SV_GL(glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 12, nullptr));
  SV_GL(glBindVertexArray(0));
  SV_GL(glBindBuffer(GL_ARRAY_BUFFER, 0));
  meshCapacity = vertices;
}

void Renderer::Impl::drawCompactGpuVolume(const glm::dmat4& lightViewToClip, const VolumeBuildOptions& vo, double bias,
                                          const Texture& depth, std::int64_t quads, RenderResult& result) {
  if (keptCapacity < quads) {
    SV_GL(glBindBuffer(GL_ARRAY_BUFFER, keptBuffer.id()));
    SV_GL(glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(quads * 4), nullptr, GL_DYNAMIC_COPY));
    SV_GL(glBindVertexArray(keptVao.id()));
    SV_GL(glEnableVertexAttribArray(0));
    SV_GL(glVertexAttribIPointer(0, 1, GL_INT, 4, nullptr));
    SV_GL(glBindVertexArray(0));
    SV_GL(glBindBuffer(GL_ARRAY_BUFFER, 0));
    keptCapacity = quads;
  }
  bindTexture(0, depth, fetchSampler);
  setVolumeUniforms(volumeKeepProgram, vo, bias);
  volumeKeepProgram.set("firstQuad", 0);
  SV_GL(glBindVertexArray(emptyVao.id()));
  SV_GL(glEnable(GL_RASTERIZER_DISCARD));
  SV_GL(glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, keptBuffer.id()));
  SV_GL(glBeginQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, keptQuery.id()));
  SV_GL(glBeginTransformFeedback(GL_POINTS));
  constexpr std::int64_t kQuadsPerKeepPoint = 32;  // volume_keep.geom's
  SV_GL(glDrawArrays(GL_POINTS, 0, GLsizei((quads + kQuadsPerKeepPoint - 1) / kQuadsPerKeepPoint)));
  SV_GL(glEndTransformFeedback());
  SV_GL(glEndQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN));
  SV_GL(glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0));
  SV_GL(glDisable(GL_RASTERIZER_DISCARD));
  // The count is needed for the draw (GL 3.3 has no draw from a feedback object's count).
  GLuint kept = 0;
  SV_GL(glGetQueryObjectuiv(keptQuery.id(), GL_QUERY_RESULT, &kept));
  result.gpuVolumeQuadsDrawn = kept;
  setVolumeUniforms(volumeGpuKeptProgram, vo, bias);
  volumeGpuKeptProgram.set("lightViewToClip", toFloat(lightViewToClip));
  volumeGpuKeptProgram.set("drawRectangle", 0);
  SV_GL(glBindVertexArray(keptVao.id()));
  SV_GL(glBeginQuery(GL_PRIMITIVES_GENERATED, primitivesQuery.id()));
  SV_GL(glDrawArrays(GL_POINTS, 0, GLsizei(kept)));
  SV_GL(glEndQuery(GL_PRIMITIVES_GENERATED));
  SV_GL(glBindVertexArray(0));
  volumeTrianglesPending = true;
}

}  // namespace shadowvol::gl

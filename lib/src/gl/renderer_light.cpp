// The light's passes: depth into the light targets, resolve, blur, read-back, and the same maps
// from the depth oracle's rays (ExplicitDepth::Rays).
#include "renderer_impl.h"

namespace shadowvol::gl {

void Renderer::Impl::resetState() {
  SV_GL(glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE));
  SV_GL(glDisable(GL_BLEND));
  SV_GL(glDisable(GL_STENCIL_TEST));
  SV_GL(glDisable(GL_DEPTH_CLAMP));
  SV_GL(glDisable(GL_CULL_FACE));
  SV_GL(glDisable(GL_SCISSOR_TEST));
  SV_GL(glFrontFace(GL_CCW));
  SV_GL(glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE));
  SV_GL(glDepthMask(GL_TRUE));
  SV_GL(glStencilMask(0xFF));
  SV_GL(glEnable(GL_DEPTH_TEST));
  SV_GL(glDepthFunc(GL_GREATER));
}

void Renderer::Impl::drawFullScreenTriangle() {
  SV_GL(glBindVertexArray(emptyVao.id()));
  SV_GL(glDrawArrays(GL_TRIANGLES, 0, 3));
  SV_GL(glBindVertexArray(0));
}

void Renderer::Impl::drawScene() {
  SV_GL(glBindVertexArray(sceneVao.id()));
  SV_GL(glDrawElements(GL_TRIANGLES, sceneIndexCount, GL_UNSIGNED_INT, nullptr));
  SV_GL(glBindVertexArray(0));
}

void Renderer::Impl::drawLightLayer(const Program& program, const glm::dmat4& worldToLightClip, bool markOccupancy) {
  program.use();
  program.set("worldToLightClip", toFloat(worldToLightClip));
  if (markOccupancy) SV_GL(glBindImageTexture(0, occupancy.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI));
  drawScene();
  if (markOccupancy) {
    SV_GL(glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI));
    SV_GL(glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT));
  }
}

// Entry capture's first layer passes over faces lit nearly edge-on (light_entry.frag).
void Renderer::Impl::setEntryFacingUniforms() {
  lightEntryProgram.use();
  lightEntryProgram.set("lightType", int(light.type));
  lightEntryProgram.set("lightPosition", glm::vec3(light.position));
  lightEntryProgram.set("lightDirection", glm::vec3(glm::normalize(light.direction)));
  lightEntryProgram.set("grazingCos", float(kEntryGrazingCos));
}

void Renderer::Impl::lightPass(int w, int h, CaptureMode mode, bool markOccupancy, bool recordTriangles) {
  ensureLightTargets(w, h);
  if (markOccupancy) clearOccupancy((w + 7) / 8, (h + 3) / 4);
  if (recordTriangles) ensureTriangleIds(w, h);
  resetState();
  const glm::dmat4 worldToLightClip = reversedZ(lightProjection(light, double(w) / double(h))) * lightView(light);
  SV_GL(glViewport(0, 0, w, h));
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, recordTriangles ? layer0IdFbo.id() : layer0Fbo.id()));
  SV_GL(glClearDepth(0.0));  // reversed Z: 0 = nothing seen
  SV_GL(glClear(GL_DEPTH_BUFFER_BIT));
  if (recordTriangles) {
    const GLuint none[4] = {0, 0, 0, 0};
    SV_GL(glClearBufferuiv(GL_COLOR, 0, none));
  }
  if (mode == CaptureMode::Back) {
    SV_GL(glEnable(GL_CULL_FACE));
    SV_GL(glCullFace(GL_FRONT));
  }
  // Entry capture marks the texels its second pass (the back faces) covers: those it records.
  const bool markFirst = markOccupancy && mode != CaptureMode::Entry;
  const Program& first = markFirst && recordTriangles ? lightMarkTriangleProgram
                         : markFirst                  ? lightMarkProgram
                         : recordTriangles            ? lightTriangleProgram
                         : mode == CaptureMode::Entry ? lightEntryProgram
                                                      : lightProgram;
  if (&first == &lightEntryProgram) setEntryFacingUniforms();
  drawLightLayer(first, worldToLightClip, markFirst);
  occupancyValid = markOccupancy;
  SV_GL(glDisable(GL_CULL_FACE));
  if (mode == CaptureMode::Midpoint) {
    SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, layer1Fbo.id()));
    SV_GL(glClear(GL_DEPTH_BUFFER_BIT));
    peelProgram.use();
    peelProgram.set("worldToLightClip", toFloat(worldToLightClip));
    peelProgram.set("firstLayer", 0);
    bindTexture(0, layer0, fetchSampler);
    drawScene();
    bindTexture(0, Texture(), fetchSampler);
  }
  if (mode == CaptureMode::Entry) {  // the nearest back face: where layer0's surface counts
    SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, layer1Fbo.id()));
    SV_GL(glClear(GL_DEPTH_BUFFER_BIT));
    SV_GL(glEnable(GL_CULL_FACE));
    SV_GL(glCullFace(GL_FRONT));
    drawLightLayer(markOccupancy ? lightMarkProgram : lightProgram, worldToLightClip, markOccupancy);
    SV_GL(glDisable(GL_CULL_FACE));
  }
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, 0));
}

void Renderer::Impl::ensureTriangleIds(int w, int h) {
  if (w == triangleIdsW && h == triangleIdsH) return;
  triangleIds = makeTexture2D(GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, w, h);
  layer0IdFbo = colourDepthFramebuffer(triangleIds, layer0, "light depth with triangle record");
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, 0));
  triangleIdsW = w;
  triangleIdsH = h;
}

void Renderer::Impl::clearOccupancy(int bw, int bh) {
  if (bw != occupancyW || bh != occupancyH) {
    occupancy = makeTexture2D(GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, bw, bh);
    occupancyFbo = makeFramebuffer();
    SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, occupancyFbo.id()));
    SV_GL(glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, occupancy.id(), 0));
    SV_GL(glDrawBuffer(GL_COLOR_ATTACHMENT0));
    checkFramebufferComplete("light occupancy");
    occupancyW = bw;
    occupancyH = bh;
  }
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, occupancyFbo.id()));
  const GLuint zero[4] = {0, 0, 0, 0};
  SV_GL(glClearBufferuiv(GL_COLOR, 0, zero));
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, 0));
}

void Renderer::Impl::bindCube(int unit, const Texture& tex, const Sampler& sampler) {
  SV_GL(glActiveTexture(GLenum(GL_TEXTURE0 + unit)));
  SV_GL(glBindTexture(GL_TEXTURE_CUBE_MAP, tex.id()));
  SV_GL(glBindSampler(GLuint(unit), tex ? sampler.id() : 0));
  SV_GL(glActiveTexture(GL_TEXTURE0));
}

void Renderer::Impl::bindTexture(int unit, const Texture& tex, const Sampler& sampler) {
  SV_GL(glActiveTexture(GLenum(GL_TEXTURE0 + unit)));
  SV_GL(glBindTexture(GL_TEXTURE_2D, tex.id()));
  SV_GL(glBindSampler(GLuint(unit), tex ? sampler.id() : 0));
  SV_GL(glActiveTexture(GL_TEXTURE0));
}

void Renderer::Impl::resolvePass(CaptureMode mode) {
  resetState();
  const glm::dmat4 proj = reversedZ(lightProjection(light, double(lightW) / double(lightH)));
  SV_GL(glViewport(0, 0, lightW, lightH));
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, resolveFbo.id()));
  SV_GL(glDepthFunc(GL_ALWAYS));
  resolveProgram.use();
  resolveProgram.set("layer0", 0);
  resolveProgram.set("layer1", 1);
  resolveProgram.set("layers", mode == CaptureMode::Midpoint ? 1 : mode == CaptureMode::Entry ? 2 : 0);
  resolveProgram.set("depthParams", depthParams(proj));
  resolveProgram.set("farPlane", float(light.farPlane));
  bindTexture(0, layer0, fetchSampler);
  bindTexture(1, layer1, fetchSampler);
  drawFullScreenTriangle();
  SV_GL(glDepthFunc(GL_GREATER));
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, 0));
}

void Renderer::Impl::blurPass(double blurOffset) {
  resetState();
  SV_GL(glDisable(GL_DEPTH_TEST));
  SV_GL(glViewport(0, 0, lightW, lightH));
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, blurFbo.id()));
  blurProgram.use();
  blurProgram.set("lightDepth", 0);
  blurProgram.set("size", glm::ivec2(lightW, lightH));
  blurProgram.set("farSnap", float(light.farPlane * (1.0 - kFarSnap)));
  blurProgram.set("blurOffset", float(blurOffset));
  bindTexture(0, linearDepth, fetchSampler);
  drawFullScreenTriangle();
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, 0));
}

DepthMap Renderer::Impl::readBack(CaptureMode mode) {
  DepthMap map = makeDepthMap(light, lightW, lightH, mode);
  map.origin = scene.origin;
  const std::size_t n = std::size_t(lightW) * std::size_t(lightH);
  std::vector<float> w0(n), w1;
  SV_GL(glBindTexture(GL_TEXTURE_2D, layer0.id()));
  SV_GL(glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, w0.data()));
  if (usesTwoLayers(mode)) {
    w1.resize(n);
    SV_GL(glBindTexture(GL_TEXTURE_2D, layer1.id()));
    SV_GL(glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, w1.data()));
  }
  SV_GL(glBindTexture(GL_TEXTURE_2D, 0));
  const glm::dmat4 p = reversedZ(map.lightProjection);
  for (std::size_t k = 0; k < n; ++k) {
    if (w0[k] <= 0.0f) continue;  // cleared: the light saw nothing (kNoHit)
    if (mode == CaptureMode::Entry && w1[k] <= 0.0f) continue;  // no back face: nothing recorded
    double d = viewDepthFromWindow(p, double(w0[k]));
    if (mode == CaptureMode::Midpoint)
      d = 0.5 * (d + (w1[k] <= 0.0f ? map.farPlane : viewDepthFromWindow(p, double(w1[k]))));
    map.depth[k] = float(d);
  }
  return map;
}

DepthMap Renderer::Impl::rayCast(int w, int h, CaptureMode mode, const DepthOracle& oracle) const {
  DepthMap map = makeDepthMap(light, w, h, mode);
  map.origin = scene.origin;
  fillFromOracle(map, oracle);
  return map;
}

CubeDepthMap Renderer::Impl::rayCastCube(int n, CaptureMode mode, const DepthOracle& oracle) const {
  CubeDepthMap cube = makeCubeDepthMap(light, n, mode);
  for (DepthMap& face : cube.faces) {
    face.origin = scene.origin;
    fillFromOracle(face, oracle);
  }
  return cube;
}

}  // namespace shadowvol::gl

// The camera's passes: scene uniforms, the camera pass, the stencil state of a volume, further
// lights' diffuse terms and the lighting pass.
#include "renderer_impl.h"

namespace shadowvol::gl {

Renderer::Impl::CameraSetup Renderer::Impl::cameraSetup(const RenderOptions& o) const {
  if (o.imageWidth < 0 || o.imageHeight < 0)
    throw InputError("RenderOptions", "imageWidth x imageHeight",
                     std::to_string(o.imageWidth) + "x" + std::to_string(o.imageHeight),
                     "must not be negative (0 = the scene camera's size)");
  Camera c = camera;
  if (o.imageWidth > 0) c.width = o.imageWidth;
  if (o.imageHeight > 0) c.height = o.imageHeight;
  return {cameraView(c), reversedZ(cameraProjection(c)), c.width, c.height};
}

void Renderer::Impl::setSceneUniforms(const CameraSetup& cam, const RenderOptions& o, int shadowTaps, int mapW,
                                      int mapH) {
  const double aspect = double(mapW) / double(mapH);
  // A point light has no one projection; its lit region is the shell between its near and far
  // cubes (scene.frag), and its cube shadow map compares with its faces' shared projection.
  const glm::dmat4 lp =
      light.type == LightType::Point ? lightProjection(cubeFaceLight(light, 0), 1.0) : lightProjection(light, aspect);
  const glm::dmat4 lv = lightView(light);
  sceneProgram.use();
  sceneProgram.set("worldToClip", toFloat(cam.proj * cam.view));
  sceneProgram.set("cameraPosition", glm::vec3(camera.eye));
  sceneProgram.set("lightType", int(light.type));
  sceneProgram.set("lightNearFar", glm::vec2(float(light.nearPlane), float(light.farPlane)));
  sceneProgram.set("lightPosition", glm::vec3(light.position));
  sceneProgram.set("lightDirection", glm::vec3(glm::normalize(light.direction)));
  sceneProgram.set("worldToLightClip", toFloat(lp * lv));
  sceneProgram.set("worldToLightView", toFloat(lv));
  sceneProgram.set("lightDepthParams", depthParams(reversedZ(lp)));
  sceneProgram.set("ambient", float(o.ambient));
  sceneProgram.set("diffuse", float(o.diffuse * light.intensity));
  sceneProgram.set("shadowTaps", shadowTaps);
  sceneProgram.set("writeVisibility", 0);
  sceneProgram.set("shadowMap", 2);
  sceneProgram.set("cubeShadowMap", 3);
  sceneProgram.set("shadowMapSize", glm::vec2(float(mapW), float(mapH)));
  sceneProgram.set("biasConstant", float(o.shadowBiasConstant.value_or(defaultBias(light, mapW, mapH, o.capture))));
  sceneProgram.set("biasSlope", float(o.shadowBiasSlope));
  sceneProgram.set("texelFootprint", float(2.0 / (lp[1][1] * double(mapH))));
  sceneProgram.set("pointShadowMap", 0);
}

void Renderer::Impl::setParaboloidUniforms(const RenderOptions& o) {
  const int side = paraboloidFrame.side;
  sceneProgram.set("pointShadowMap", 1);
  DualParaboloidPass::setUniforms(sceneProgram, paraboloidFrame);
  sceneProgram.set("shadowMapSize", glm::vec2(float(2 * side), float(side)));
  sceneProgram.set("biasConstant",
                   float(o.shadowBiasConstant.value_or(dualParaboloidDefaultBias(light, o.depthWidth, o.capture))));
  sceneProgram.set("texelFootprint", float(4.0 / side));
}

void Renderer::Impl::beginCamera(const CameraSetup& cam, CameraExtra extra) {
  ensureCameraTargets(cam.w, cam.h);
  resetState();
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, cameraFbo.id()));
  SV_GL(glViewport(0, 0, cam.w, cam.h));
  SV_GL(glClearColor(0.10f, 0.12f, 0.15f, 1.0f));  // every enabled draw buffer, the ambient image too
  SV_GL(glClearDepth(0.0));                        // reversed Z: 0 is the far plane
  SV_GL(glClearStencil(0));
  const GLenum buffers[3] = {GL_COLOR_ATTACHMENT0,
                             extra == CameraExtra::Visibility ? GL_COLOR_ATTACHMENT1 : GLenum(GL_NONE),
                             GL_COLOR_ATTACHMENT2};
  SV_GL(glDrawBuffers(extra == CameraExtra::None ? 1 : extra == CameraExtra::Visibility ? 2 : 3, buffers));
  SV_GL(glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT));
  if (extra == CameraExtra::Visibility) {
    const GLfloat lit[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    SV_GL(glClearBufferfv(GL_COLOR, 1, lit));
  }
}

void Renderer::Impl::beginVolume(bool zPass) {
  SV_GL(glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE));
  SV_GL(glDepthMask(GL_FALSE));
  SV_GL(glDepthFunc(GL_GREATER));
  if (zPass)
    SV_GL(glDisable(GL_DEPTH_CLAMP));
  else
    SV_GL(glEnable(GL_DEPTH_CLAMP));
  SV_GL(glDisable(GL_CULL_FACE));
  SV_GL(glEnable(GL_STENCIL_TEST));
  SV_GL(glStencilMask(0xFF));
  SV_GL(glStencilFunc(GL_ALWAYS, 0, 0xFF));
  if (zPass) {
    SV_GL(glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP));
    SV_GL(glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP));
  } else {
    SV_GL(glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP));
    SV_GL(glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP));
  }
}

void Renderer::Impl::endVolume() {
  SV_GL(glDisable(GL_DEPTH_CLAMP));
  SV_GL(glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE));
}

std::array<GLint, 4> Renderer::Impl::lightFrustumOnImage(const CameraSetup& cam, double aspect) const {
  const std::array<GLint, 4> whole = {0, 0, cam.w, cam.h};
  if (light.type == LightType::Point) return whole;  // it lights every way
  const glm::dmat4 lightClipToWorld = glm::inverse(lightProjection(light, aspect) * lightView(light));
  const glm::dmat4 worldToClip = cam.proj * cam.view;
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (int k = 0; k < 8; ++k) {
    const glm::dvec4 corner(k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 4 ? 1.0 : -1.0, 1.0);
    const glm::dvec4 world = lightClipToWorld * corner;
    const glm::dvec4 clip = worldToClip * (world / world.w);
    if (!(clip.w > 0.0)) return whole;
    const glm::dvec2 window = (glm::dvec2(clip) / clip.w * 0.5 + 0.5) * glm::dvec2(cam.w, cam.h);
    lo = glm::min(lo, window);
    hi = glm::max(hi, window);
  }
  // One pixel of margin for rounding; clamped to the image.
  const GLint x0 = GLint(std::clamp(std::floor(lo.x) - 1.0, 0.0, double(cam.w)));
  const GLint y0 = GLint(std::clamp(std::floor(lo.y) - 1.0, 0.0, double(cam.h)));
  const GLint x1 = GLint(std::clamp(std::ceil(hi.x) + 1.0, 0.0, double(cam.w)));
  const GLint y1 = GLint(std::clamp(std::ceil(hi.y) + 1.0, 0.0, double(cam.h)));
  return {x0, y0, x1 - x0, y1 - y0};
}

void Renderer::Impl::beginAddedLight(const CameraSetup& cam, bool visibility) {
  resetState();
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, cameraFbo.id()));
  SV_GL(glViewport(0, 0, cam.w, cam.h));
  const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, visibility ? GL_COLOR_ATTACHMENT1 : GLenum(GL_NONE)};
  SV_GL(glDrawBuffers(2, buffers));
  SV_GL(glClearStencil(0));
  SV_GL(glClear(GL_STENCIL_BUFFER_BIT));
  if (visibility) {
    const GLfloat lit[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    SV_GL(glClearBufferfv(GL_COLOR, 1, lit));
  }
}

void Renderer::Impl::addDiffuseState(bool stencilLit) {
  sceneProgram.set("ambient", 0.0f);
  SV_GL(glEnable(GL_BLEND));
  SV_GL(glBlendEquation(GL_FUNC_ADD));
  SV_GL(glBlendFunc(GL_ONE, GL_ONE));
  SV_GL(glDisablei(GL_BLEND, 1));
  SV_GL(glDepthFunc(GL_EQUAL));
  SV_GL(glDepthMask(GL_FALSE));
  if (stencilLit) {
    SV_GL(glEnable(GL_STENCIL_TEST));
    SV_GL(glStencilFunc(GL_EQUAL, 0, 0xFF));
    SV_GL(glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP));
  }
}

void Renderer::Impl::addDiffusePass(const CameraSetup& cam, const RenderOptions& o, int frustumW, int frustumH) {
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, cameraFbo.id()));
  SV_GL(glDrawBuffer(GL_COLOR_ATTACHMENT0));
  const std::array<GLint, 4> r = lightFrustumOnImage(cam, double(frustumW) / double(frustumH));
  SV_GL(glEnable(GL_SCISSOR_TEST));
  SV_GL(glScissor(r[0], r[1], r[2], r[3]));
  setSceneUniforms(cam, o, 0, frustumW, frustumH);
  addDiffuseState(true);
  drawScene();
  resetState();
}

void Renderer::Impl::lightingPass(const CameraSetup& cam, double frustumAspect) {
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, shadowOverFbo.id()));
  const std::array<GLint, 4> r = lightFrustumOnImage(cam, frustumAspect);
  SV_GL(glEnable(GL_SCISSOR_TEST));
  SV_GL(glScissor(r[0], r[1], r[2], r[3]));
  SV_GL(glDisable(GL_DEPTH_TEST));
  SV_GL(glEnable(GL_STENCIL_TEST));
  SV_GL(glStencilFunc(GL_NOTEQUAL, 0, 0xFF));
  SV_GL(glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP));
  SV_GL(glDepthMask(GL_FALSE));
  ambientOverProgram.use();
  ambientOverProgram.set("ambientImage", 0);
  bindTexture(0, ambientImage, fetchSampler);
  drawFullScreenTriangle();
  bindTexture(0, Texture(), fetchSampler);
  resetState();
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, cameraFbo.id()));
}

}  // namespace shadowvol::gl

// Point lights: the six cube faces' passes, the cube shadow map, the GPU cube volume and the
// dual-paraboloid maps.
#include "renderer_impl.h"

namespace shadowvol::gl {

void Renderer::Impl::writeCubeFaceImage(const CameraSetup& cam, const glm::dvec3& lightPosition) {
  if (cubeFaceW != cam.w || cubeFaceH != cam.h) {
    cubeFaceImage = makeTexture2D(GL_R8UI, GL_RED_INTEGER, GL_UNSIGNED_BYTE, cam.w, cam.h);
    cubeFaceFbo = makeFramebuffer();
    SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, cubeFaceFbo.id()));
    SV_GL(glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, cubeFaceImage.id(), 0));
    SV_GL(glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depthStencilRb.id()));
    SV_GL(glDrawBuffer(GL_COLOR_ATTACHMENT0));
    checkFramebufferComplete("cube face image");
    cubeFaceW = cam.w, cubeFaceH = cam.h;
  }
  resetState();
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, cubeFaceFbo.id()));
  SV_GL(glViewport(0, 0, cam.w, cam.h));
  const GLuint background[4] = {255, 0, 0, 0};
  SV_GL(glClearBufferuiv(GL_COLOR, 0, background));
  SV_GL(glDepthMask(GL_FALSE));
  SV_GL(glDepthFunc(GL_EQUAL));
  cubeFaceIdProgram.use();
  cubeFaceIdProgram.set("worldToClip", toFloat(cam.proj * cam.view));  // as the camera pass: the same depths
  cubeFaceIdProgram.set("lightPosition", glm::vec3(lightPosition));
  drawScene();
  resetState();
}

void Renderer::Impl::maskOtherCubeFaces(const CameraSetup& cam, int face) {
  resetState();
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, cameraFbo.id()));
  SV_GL(glViewport(0, 0, cam.w, cam.h));
  SV_GL(glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE));
  SV_GL(glDepthMask(GL_FALSE));
  SV_GL(glDisable(GL_DEPTH_TEST));
  SV_GL(glStencilMask(0x80));
  SV_GL(glClearStencil(0));
  SV_GL(glClear(GL_STENCIL_BUFFER_BIT));
  SV_GL(glEnable(GL_STENCIL_TEST));
  SV_GL(glStencilFunc(GL_ALWAYS, 0x80, 0x80));
  SV_GL(glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE));
  cubeFaceMaskProgram.use();
  cubeFaceMaskProgram.set("faceImage", 0);
  SV_GL(glUniform1ui(cubeFaceMaskProgram.location("face"), GLuint(face)));
  bindTexture(0, cubeFaceImage, fetchSampler);
  drawFullScreenTriangle();
  bindTexture(0, Texture(), fetchSampler);
  resetState();
}

CubeDepthMap Renderer::Impl::captureCube(int n, CaptureMode mode) {
  CubeDepthMap cube = makeCubeDepthMap(light, n, mode);
  eachCubeFace(n, mode, [&](int f) { cube.faces[f] = readBack(mode); });
  return cube;
}

void Renderer::Impl::cubeVolumeDepthPass(const RenderOptions& o, PassTimer& timer, RenderResult& result) {
  const int n = o.depthWidth;
  const VolumeBuildOptions& vo = o.volumeOptions;
  std::optional<CubeDepthMap> faces;
  if (o.keepVolume) faces = makeCubeDepthMap(light, n, o.capture);
  {
    TimedPass t(timer, "light");
    cubeVolume.resize(n);
    eachCubeFace(n, o.capture, [&](int f) {
      if (faces) faces->faces[f] = readBack(o.capture);
      resolvePass(o.capture);
      if (vo.blur) blurPass(vo.blurOffset);
      cubeVolume.storeFace(f, vo.blur ? blurredDepth : linearDepth);
    });
  }
  result.biasUsed = vo.bias ? *vo.bias : defaultBias(light, n, n, o.capture);
  result.gpuVolumeQuads = cubeVolume.cells();
  {
    TimedPass t(timer, "list");  // the indexed way's compute pass
    const CubeVolumeRule rule{light.nearPlane, light.farPlane, result.biasUsed,
                              vo.triangulation == Triangulation::Perfect};
    result.gpuVolumeDrawUsed = cubeVolume.list(rule, o.gpuVolumeDraw);
  }
  if (faces) {
    VolumeBuildOptions mirror = vo;
    mirror.bias = result.biasUsed;
    VolumeBuildResult built = buildCubeVolume(*faces, mirror);
    result.volumeStats = built.stats;
    result.volume = std::move(built.mesh);
  }
}

void Renderer::Impl::drawCubeGpuVolume(const CameraSetup& cam) {
  cubeVolume.draw(cam.proj * cam.view * glm::translate(glm::dmat4(1.0), light.position));
}

void Renderer::Impl::cubeShadowPass(int n, CaptureMode mode) {
  if (n != cubeShadowSize) {
    cubeShadow = makeTexture();
    SV_GL(glBindTexture(GL_TEXTURE_CUBE_MAP, cubeShadow.id()));
    SV_GL(glTexStorage2D(GL_TEXTURE_CUBE_MAP, 1, GL_DEPTH_COMPONENT32F, n, n));
    SV_GL(glBindTexture(GL_TEXTURE_CUBE_MAP, 0));
    cubeShadowSize = n;
  }
  eachCubeFace(n, mode, [&](int f) {
    if (usesTwoLayers(mode)) resolvePass(mode);
    const Texture& face = usesTwoLayers(mode) ? resolvedDepth : layer0;
    SV_GL(glCopyImageSubData(face.id(), GL_TEXTURE_2D, 0, 0, 0, 0, cubeShadow.id(), GL_TEXTURE_CUBE_MAP, 0, 0, 0, f, n,
                             n, 1));
  });
}

void Renderer::Impl::paraboloidPass(int n, CaptureMode mode, int subdivision) {
  paraboloidFrame = makeDualParaboloid(light, sceneBounds, dualParaboloidSide(n));
  resetState();
  paraboloid.draw(paraboloidFrame, mode, subdivision, [this] { drawScene(); });
}

}  // namespace shadowvol::gl

// The renderer's context, shaders and targets, and its public calls (renderer.h); the passes are
// in the renderer_*.cpp files (renderer_impl.h lists them).
#include "renderer_impl.h"

namespace shadowvol::gl {

Renderer::Impl::Impl(const RendererOptions& options)
    : context(EglContext::create(options.context)), shaders(options.shaderDir) {
  lightProgram = Program(shaders, "light.vert", "depth_only.frag");
  peelProgram = Program(shaders, "light.vert", "depth_peel.frag");
  lightEntryProgram = Program(shaders, "light.vert", "light_entry.frag");
  resolveProgram =
      Program(shaders, {"fullscreen.vert"}, {"version_330.glsl", "light_window_depth.glsl", "resolve.frag"});
  blurProgram = Program(shaders, "fullscreen.vert", "blur.frag");
  sceneProgram =
      Program(shaders, {"scene.vert"}, {"version_330.glsl", "paraboloid.glsl", "cube_face.glsl", "scene.frag"});
  cubeFaceIdProgram = Program(shaders, {"scene.vert"}, {"version_330.glsl", "cube_face.glsl", "cube_face_id.frag"});
  cubeFaceMaskProgram = Program(shaders, "fullscreen.vert", "cube_face_mask.frag");
  paraboloid = DualParaboloidPass(shaders);
  ambientOverProgram = Program(shaders, "fullscreen.vert", "ambient_over.frag");
  volumeProgram = Program(shaders, "volume.vert", "depth_only.frag");
  volumeGpuProgram = Program(shaders, {"volume_gpu_points.vert"},
                             {"version_330.glsl", "light_window_depth.glsl", "volume_common.glsl", "volume_gpu.geom"},
                             {"depth_only.frag"});
  volumeKeepProgram = Program(shaders, {"volume_gpu_points.vert"},
                              {"version_330.glsl", "light_window_depth.glsl", "volume_common.glsl", "volume_keep.geom"},
                              {}, {"keptQuad"});
  volumeGpuKeptProgram = Program(
      shaders, {"volume_gpu_kept.vert"},
      {"version_330.glsl", "light_window_depth.glsl", "volume_common.glsl", "volume_gpu.geom"}, {"depth_only.frag"});
  const ContextInfo& ci = context.info();
  // Every pass draws in reversed Z through glClipControl: core in 4.5, an extension before.
  if (!(ci.glMajor > 4 || (ci.glMajor == 4 && ci.glMinor >= 5)) && !epoxy_has_gl_extension("GL_ARB_clip_control"))
    throw GlError("the renderer needs OpenGL 4.5 or GL_ARB_clip_control (reversed-Z depth); the context is " +
                  ci.glVersion + " on " + ci.glRenderer);
  hasCompute = ci.glMajor > 4 || (ci.glMajor == 4 && ci.glMinor >= 3);
  if (hasCompute) {
    cubeVolume = CubeGpuVolume(shaders);
    volumeMeshProgram = Program::compute(
        shaders, {"version_430.glsl", "light_window_depth.glsl", "volume_common.glsl", "volume_mesh.comp"});
    volumeMeshDrawProgram = Program(shaders, "volume_mesh.vert", "depth_only.frag");
    volumeIndexProgram =
        Program(shaders, {"fullscreen.vert"},
                {"version_430.glsl", "light_window_depth.glsl", "volume_common.glsl", "volume_index.frag"});
    volumeIndexedProgram =
        Program(shaders, {"version_330.glsl", "light_window_depth.glsl", "volume_common.glsl", "volume_index.vert"},
                {"depth_only.frag"});
    lightMarkProgram = Program(shaders, {"light.vert"}, {"version_430.glsl", "light_mark.glsl", "light_mark.frag"});
    lightTriangleProgram =
        Program(shaders, {"light.vert"}, {"version_330.glsl", "light_triangle.glsl", "light_triangle.frag"});
    lightMarkTriangleProgram =
        Program(shaders, {"light.vert"},
                {"version_430.glsl", "light_mark.glsl", "light_triangle.glsl", "light_mark_triangle.frag"});
    walk = SilhouetteWalk(shaders);
    rays = SilhouetteRays(shaders);
  }

  fetchSampler = makeSampler();
  for (GLenum p : {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER})
    SV_GL(glSamplerParameteri(fetchSampler.id(), p, GL_NEAREST));
  for (GLenum p : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T})
    SV_GL(glSamplerParameteri(fetchSampler.id(), p, GL_CLAMP_TO_EDGE));
  SV_GL(glSamplerParameteri(fetchSampler.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE));
  shadowSampler = makeSampler();
  for (GLenum p : {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER})
    SV_GL(glSamplerParameteri(shadowSampler.id(), p, GL_NEAREST));
  for (GLenum p : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T})
    SV_GL(glSamplerParameteri(shadowSampler.id(), p, GL_CLAMP_TO_EDGE));
  SV_GL(glSamplerParameteri(shadowSampler.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE));
  SV_GL(glSamplerParameteri(shadowSampler.id(), GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL));  // reversed Z

  emptyVao = makeVertexArray();
  primitivesQuery = makeQuery();
  sceneVao = makeVertexArray();
  sceneVbo = makeBuffer();
  sceneEbo = makeBuffer();
  volumeVao = makeVertexArray();
  volumeVbo = makeBuffer();
  volumeEbo = makeBuffer();
  keptVao = makeVertexArray();
  keptBuffer = makeBuffer();
  keptQuery = makeQuery();
  meshVao = makeVertexArray();
  meshBuffer = makeBuffer();
  meshCount = makeBuffer();
  indexVao = makeVertexArray();
  indexBuffer = makeBuffer();
  indexCount = makeBuffer();
  listFbo = makeFramebuffer();
  SV_GL(glBindVertexArray(volumeVao.id()));
  SV_GL(glBindBuffer(GL_ARRAY_BUFFER, volumeVbo.id()));
  SV_GL(glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, volumeEbo.id()));
  SV_GL(glEnableVertexAttribArray(0));
  SV_GL(glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr));
  SV_GL(glBindVertexArray(0));

  SV_GL(glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTextureSize));
  SV_GL(glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRenderbufferSize));
  SV_GL(glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport));
  // Every read-back and upload takes rows tight, for every pass: none changes these (a pack
  // alignment of 4 pads a row of one-byte pixels to a multiple of 4; readShadowImages checks it).
  SV_GL(glPixelStorei(GL_PACK_ALIGNMENT, 1));
  SV_GL(glPixelStorei(GL_UNPACK_ALIGNMENT, 1));
}

void Renderer::Impl::requireScene() const {
  if (!hasScene) throw InputError("renderer", "", "", "no scene: call setScene() before rendering");
}

void Renderer::Impl::checkSize(const char* source, const char* field, int w, int h, int limit) const {
  if (w < 2 || h < 2 || w > limit || h > limit)
    throw InputError(source, field, std::to_string(w) + "x" + std::to_string(h),
                     "must be between 2 and " + std::to_string(limit) + " per side on this OpenGL implementation");
}

void Renderer::Impl::ensureLightTargets(int w, int h) {
  if (w == lightW && h == lightH) return;
  layer0 = makeTexture2D(GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, w, h);
  layer1 = makeTexture2D(GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, w, h);
  resolvedDepth = makeTexture2D(GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, w, h);
  linearDepth = makeTexture2D(GL_R32F, GL_RED, GL_FLOAT, w, h);
  blurredDepth = makeTexture2D(GL_R32F, GL_RED, GL_FLOAT, w, h);
  auto depthFbo = [](const Texture& depth, const char* what) {
    Framebuffer f = makeFramebuffer();
    SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, f.id()));
    SV_GL(glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth.id(), 0));
    SV_GL(glDrawBuffer(GL_NONE));
    SV_GL(glReadBuffer(GL_NONE));
    checkFramebufferComplete(what);
    return f;
  };
  layer0Fbo = depthFbo(layer0, "light depth (first layer)");
  triangleIdsW = triangleIdsH = 0;  // its framebuffer held the old layer0
  layer1Fbo = depthFbo(layer1, "light depth (second layer)");
  resolveFbo = colourDepthFramebuffer(linearDepth, resolvedDepth, "light depth resolve");
  blurFbo = makeFramebuffer();
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, blurFbo.id()));
  SV_GL(glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, blurredDepth.id(), 0));
  SV_GL(glDrawBuffer(GL_COLOR_ATTACHMENT0));
  checkFramebufferComplete("depth blur");
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, 0));
  lightW = w;
  lightH = h;
}

void Renderer::Impl::ensureCameraTargets(int w, int h) {
  if (w == camW && h == camH) return;
  colorRb = makeRenderbuffer();
  SV_GL(glBindRenderbuffer(GL_RENDERBUFFER, colorRb.id()));
  SV_GL(glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h));
  depthStencilRb = makeRenderbuffer();
  SV_GL(glBindRenderbuffer(GL_RENDERBUFFER, depthStencilRb.id()));
  SV_GL(glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH32F_STENCIL8, w, h));  // reversed Z: see cameraSetup
  visibilityRb = makeRenderbuffer();
  SV_GL(glBindRenderbuffer(GL_RENDERBUFFER, visibilityRb.id()));
  SV_GL(glRenderbufferStorage(GL_RENDERBUFFER, GL_R8, w, h));
  SV_GL(glBindRenderbuffer(GL_RENDERBUFFER, 0));
  cameraFbo = makeFramebuffer();
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, cameraFbo.id()));
  SV_GL(glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colorRb.id()));
  SV_GL(glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depthStencilRb.id()));
  SV_GL(glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, visibilityRb.id()));
  ambientImage = makeTexture2D(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, w, h);
  SV_GL(glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, ambientImage.id(), 0));
  SV_GL(glDrawBuffer(GL_COLOR_ATTACHMENT0));
  SV_GL(glReadBuffer(GL_COLOR_ATTACHMENT0));
  checkFramebufferComplete("camera");
  // The lighting pass reads ambientImage: a framebuffer without it, so no feedback loop in any
  // GL version (the colour and depth-stencil renderbuffers are shared).
  shadowOverFbo = makeFramebuffer();
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, shadowOverFbo.id()));
  SV_GL(glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colorRb.id()));
  SV_GL(glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depthStencilRb.id()));
  SV_GL(glDrawBuffer(GL_COLOR_ATTACHMENT0));
  checkFramebufferComplete("camera lighting");
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, 0));
  cubeFaceW = cubeFaceH = 0;  // its framebuffer held the old depth + stencil (writeCubeFaceImage)
  camW = w;
  camH = h;
}

Renderer::Renderer(const RendererOptions& options) : impl_(std::make_unique<Impl>(options)) {}
Renderer::~Renderer() {
  // The GL objects are deleted with this context current; if that fails there is nothing to
  // report from a destructor (the context's own destruction still releases everything).
  if (impl_) {
    try {
      impl_->context.makeCurrent();
    } catch (const GlError&) {
    }
  }
}
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

const ContextInfo& Renderer::info() const {
  return impl_->context.info();
}

void Renderer::setScene(const Scene& scene) {
  Impl& s = *impl_;
  s.context.makeCurrent();
  if (!(scene.camera.farPlane > scene.camera.nearPlane) || !(scene.camera.nearPlane > 0.0))
    throw InputError(scene.source, "/camera", "", "near and far planes are not set (fitLightAndCamera)");
  for (std::size_t k = 0; k < scene.lightCount(); ++k) {
    const Light& l = scene.lightAt(k);
    if (!(l.farPlane > l.nearPlane))
      throw InputError(scene.source, scene.lightPointer(k), "", "near and far planes are not set (fitLightAndCamera)");
    if (l.type != LightType::Directional && !(l.nearPlane > 0.0))
      throw InputError(scene.source, scene.lightPointer(k) + "/near", numberText(l.nearPlane),
                       std::string("a ") + toString(l.type) + " light needs near > 0");
  }
  using Vertex = SceneVertex;
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;
  int colourIndex = 0;
  for (const auto& o : scene.objects) {
    const glm::vec3 albedo = albedoFor(o, colourIndex);
    const auto base = std::uint32_t(vertices.size());
    for (const auto& p : o.mesh.positions) vertices.push_back({p, albedo});
    for (const auto& t : o.mesh.triangles)
      for (auto k : t) indices.push_back(base + k);
  }
  if (indices.size() > std::size_t(std::numeric_limits<GLsizei>::max()))
    throw InputError(scene.source, "", std::to_string(indices.size() / 3), "too many triangles for one draw call");
  SV_GL(glBindVertexArray(s.sceneVao.id()));
  SV_GL(glBindBuffer(GL_ARRAY_BUFFER, s.sceneVbo.id()));
  SV_GL(glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(), GL_STATIC_DRAW));
  SV_GL(glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, s.sceneEbo.id()));
  SV_GL(glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(std::uint32_t)), indices.data(),
                     GL_STATIC_DRAW));
  SV_GL(glEnableVertexAttribArray(0));
  SV_GL(glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                              reinterpret_cast<void*>(offsetof(Vertex, position))));
  SV_GL(glEnableVertexAttribArray(1));
  SV_GL(glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                              reinterpret_cast<void*>(offsetof(Vertex, albedo))));
  SV_GL(glBindVertexArray(0));
  SV_GL(glBindBuffer(GL_ARRAY_BUFFER, 0));
  s.sceneIndexCount = GLsizei(indices.size());
  s.lights.assign(1, scene.light);
  s.lights.insert(s.lights.end(), scene.otherLights.begin(), scene.otherLights.end());
  s.light = scene.light;
  s.camera = scene.camera;
  s.scene = scene;
  s.sceneBounds = scene.bounds();
  s.occluders.reset();
  s.walk.setScene(&s.scene);
  s.rays.setScene(&s.scene);
  s.footprint.reset();
  s.hasScene = true;
}

DepthMap Renderer::captureDepth(int width, int height, CaptureMode mode, int guard) {
  Impl& s = *impl_;
  s.context.makeCurrent();
  s.requireScene();
  if (s.light.type == LightType::Point)
    throw InputError(s.scene.source, "/light/type", "point",
                     "a point light has six depth maps, one per cube face: capture them with captureCube");
  const int limit = std::min(s.maxTextureSize, s.maxViewport[0]);
  s.checkSize("Renderer::captureDepth", "width x height", width, height, limit);
  checkGuardTexels(guard, "Renderer::captureDepth", "guard");
  s.checkGuardedSize("Renderer::captureDepth", "width x height", width, height, guard);
  const Impl::LightRestore restore{s.light, s.light};
  if (guard > 0) s.light = guardedLight(s.light, width, height, guard);
  s.lightPass(width + 2 * guard, height + 2 * guard, mode, false);
  DepthMap map = s.readBack(mode);
  map.guard = guard;
  return map;
}

CubeDepthMap Renderer::captureCube(int n, CaptureMode mode) {
  Impl& s = *impl_;
  s.context.makeCurrent();
  s.requireScene();
  if (s.light.type != LightType::Point)
    throw InputError(s.scene.source, "/light/type", toString(s.light.type),
                     "a cube map is a point light's: capture a spot or directional light with captureDepth");
  s.checkSize("Renderer::captureCube", "n x n", n, n, std::min(s.maxTextureSize, s.maxViewport[0]));
  return s.captureCube(n, mode);
}

Renderer::DualParaboloidCapture Renderer::captureDualParaboloid(int cubeFaceSide, CaptureMode mode, int subdivision) {
  Impl& s = *impl_;
  s.context.makeCurrent();
  s.requireScene();
  RenderOptions o;
  o.method = ShadowMethod::Dpsm;
  o.capture = mode;
  o.depthWidth = o.depthHeight = cubeFaceSide;
  o.paraboloidSubdivision = subdivision;
  if (s.light.type != LightType::Point)
    throw InputError(s.scene.source, "/light/type", toString(s.light.type), "dual-paraboloid maps are a point light's");
  s.checkSize("Renderer::captureDualParaboloid", "n x n", cubeFaceSide, cubeFaceSide,
              std::min(s.maxTextureSize, s.maxViewport[0]));
  s.validatePointLight(o);
  s.paraboloidPass(cubeFaceSide, mode, subdivision);
  return {s.paraboloidFrame, s.paraboloid.readDistances(s.paraboloidFrame)};
}

std::vector<WalkResult> Renderer::walkSilhouettes(int width, int height, CaptureMode mode,
                                                  std::span<const WalkQuery> queries, double bias) {
  Impl& s = *impl_;
  s.context.makeCurrent();
  s.requireScene();
  s.checkSize("Renderer::walkSilhouettes", "width x height", width, height,
              std::min(s.maxTextureSize, s.maxViewport[0]));
  if (!s.hasCompute)
    throw InputError("Renderer::walkSilhouettes", "OpenGL version", s.context.info().glVersion,
                     "the silhouette walk needs OpenGL 4.3 (compute shaders)");
  s.lightPass(width, height, mode, false, true);
  const double farSnap = s.light.farPlane * (1.0 - kFarSnap);
  return s.walk.answers(s.walkInputs(), queries, std::min(farSnap, farSnap - bias));
}

RenderResult Renderer::render(const RenderOptions& options) {
  return impl_->render(options, nullptr);
}

RenderResult Renderer::renderWithVolume(const RenderOptions& options, const VolumeMesh& volume) {
  return impl_->render(options, &volume);
}

}  // namespace shadowvol::gl

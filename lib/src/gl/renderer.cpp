#include "shadowvol/gl/renderer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include "shadowvol/camera.h"
#include "shadowvol/check.h"
#include "shadowvol/cube_map.h"
#include "shadowvol/cube_volume.h"
#include "shadowvol/dual_paraboloid.h"
#include "shadowvol/depth_blur.h"
#include "shadowvol/error.h"
#include "shadowvol/gl/gl_error.h"
#include "shadowvol/gl/gl_objects.h"
#include "shadowvol/gl/shader_program.h"
#include "shadowvol/light.h"
#include "shadowvol/sheet_depth.h"
#include "shadowvol/silhouette_volume.h"
#include "shadowvol/zpass.h"
#include "refined_gpu_volume.h"
#include "cube_gpu_volume.h"
#include "dual_paraboloid_pass.h"
#include "silhouette_rays.h"
#include "silhouette_walk.h"

namespace shadowvol::gl {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

glm::mat4 toFloat(const glm::dmat4& m) {
  return glm::mat4(m);
}

/// Light projection coefficients (column-major m[col][row]) as the shaders take them.
glm::vec4 depthParams(const glm::dmat4& p) {
  return glm::vec4(float(p[2][2]), float(p[3][2]), float(p[2][3]), float(p[3][3]));
}

/// Reversed Z, as every pass of this renderer draws (with glClipControl ZERO_TO_ONE): clip
/// z' = (w - z) / 2 maps GL's NDC z in [-1, 1] to window depth 1 .. 0 (near .. far). Composed in
/// double, so the float matrix holds n / (f - n) and f n / (f - n) without cancellation, and a
/// 32-bit float depth keeps its relative precision at every distance (GL's default convention
/// stores 1 - near/d, where float's spacing near 1 makes the relative error grow as d / near).
glm::dmat4 reversedZ(const glm::dmat4& projection) {
  glm::dmat4 reverse(1.0);
  reverse[2][2] = -0.5;
  reverse[3][2] = 0.5;
  return reverse * projection;
}

/// Window depth (reversed Z, 0 = far .. 1 = near) -> view depth (world units), in double (the
/// read-back path; resolve.frag's viewDepth is the float mirror). `p` is reversedZ(projection).
double viewDepthFromWindow(const glm::dmat4& p, double window) {
  const double z = (window * p[3][3] - p[3][2]) / (p[2][2] - window * p[2][3]);
  return -z;
}

glm::vec3 albedoFor(const SceneObject& o, int& colourIndex) {
  if (o.type == "plane" || o.name == "ground") return {0.85f, 0.85f, 0.80f};
  static const glm::vec3 palette[] = {{0.90f, 0.35f, 0.30f},
                                      {0.30f, 0.55f, 0.90f},
                                      {0.40f, 0.80f, 0.40f},
                                      {0.90f, 0.75f, 0.30f},
                                      {0.70f, 0.45f, 0.85f}};
  return palette[std::size_t(colourIndex++) % 5];
}

/// Times passes: GL_TIME_ELAPSED queries (kept in a pool between frames) or glFinish + wall clock.
class PassTimer {
 public:
  PassTimer(std::vector<Query>& pool, bool gpu) : pool_(pool), gpu_(gpu) {}

  /// Appended to the names of the passes begun from now on ("#1": the scene's second light).
  void setSuffix(std::string suffix) { suffix_ = std::move(suffix); }

  void begin(const char* name) {
    entries_.push_back({name + suffix_, -1, 0.0});
    if (gpu_) {
      const std::size_t k = used_++;
      if (k >= pool_.size()) pool_.push_back(makeQuery());
      entries_.back().query = int(k);
      SV_GL(glBeginQuery(GL_TIME_ELAPSED, pool_[k].id()));
    } else {
      glFinish();
      t0_ = Clock::now();
    }
  }
  void end() {
    if (gpu_) {
      SV_GL(glEndQuery(GL_TIME_ELAPSED));
    } else {
      glFinish();
      entries_.back().ms = msSince(t0_);
    }
  }
  /// A CPU step measured by the caller (read-back, build, upload): always wall clock.
  void cpu(const char* name, double ms) { entries_.push_back({name + suffix_, -1, ms}); }

  std::vector<PassTime> results() {
    std::vector<PassTime> out;
    for (const auto& e : entries_) {
      double ms = e.ms;
      if (e.query >= 0) {
        GLuint64 ns = 0;
        SV_GL(glGetQueryObjectui64v(pool_[std::size_t(e.query)].id(), GL_QUERY_RESULT, &ns));
        ms = double(ns) * 1e-6;
      }
      out.push_back({e.name, ms});
    }
    return out;
  }

 private:
  struct Entry {
    std::string name;
    int query;
    double ms;
  };
  std::vector<Query>& pool_;
  bool gpu_;
  std::size_t used_ = 0;
  std::vector<Entry> entries_;
  Clock::time_point t0_;
  std::string suffix_;
};

/// RAII begin/end of one timed pass.
class TimedPass {
 public:
  TimedPass(PassTimer& t, const char* name) : t_(t) { t_.begin(name); }
  ~TimedPass() { t_.end(); }
  TimedPass(const TimedPass&) = delete;
  TimedPass& operator=(const TimedPass&) = delete;

 private:
  PassTimer& t_;
};

Texture makeTexture2D(GLenum internalFormat, GLenum format, GLenum type, int w, int h) {
  Texture t = makeTexture();
  SV_GL(glBindTexture(GL_TEXTURE_2D, t.id()));
  SV_GL(glTexImage2D(GL_TEXTURE_2D, 0, GLint(internalFormat), w, h, 0, format, type, nullptr));
  // No mipmaps: a non-mipmap filter keeps the texture complete (texelFetch needs that too).
  SV_GL(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST));
  SV_GL(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST));
  SV_GL(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE));
  SV_GL(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE));
  SV_GL(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0));
  SV_GL(glBindTexture(GL_TEXTURE_2D, 0));
  return t;
}

// A framebuffer drawing into `colour` (attachment 0) with `depth`; left bound.
Framebuffer colourDepthFramebuffer(const Texture& colour, const Texture& depth, const char* what) {
  Framebuffer f = makeFramebuffer();
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, f.id()));
  SV_GL(glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour.id(), 0));
  SV_GL(glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth.id(), 0));
  SV_GL(glDrawBuffer(GL_COLOR_ATTACHMENT0));
  checkFramebufferComplete(what);
  return f;
}

// A vertex of the scene's buffer (the silhouette walk reads its positions as an SSBO).
struct SceneVertex {
  glm::vec3 position, albedo;
};
constexpr int kSceneVertexFloats = int(sizeof(SceneVertex) / sizeof(float));

}  // namespace

// The largest map the refined GPU volume takes: a 2048^2 map's index list stays under 512 MiB
// unless more than about 40 % of its quads are refined cells (60 indices each at most; then the
// frame is refused with an InputError); its other buffers hold 68 bytes per texel (flags, work
// lists, crossing records).
constexpr std::int64_t kMaxRefinedGpuTexels = std::int64_t(2048) * 2048;
// The refined GPU cube volume's guard band (guardedCubeFaceLight): each face's map reaches this
// many texels past the face's borders, so that the map's border ring (on the far plane) and the
// blur's reach (2.5 texels) stay outside the face's pyramid (docs/gpu.md).
constexpr int kCubeGuardTexels = 4;

struct Renderer::Impl {
  // Declared first: destroyed last, so every GL object below is deleted with its context current.
  EglContext context;
  ShaderLibrary shaders;
  Program lightProgram, peelProgram, resolveProgram, blurProgram, sceneProgram, ambientOverProgram, volumeProgram;
  Program cubeFaceIdProgram, cubeFaceMaskProgram;  // the refined GPU cube volume's face image and masks
  Program volumeGpuProgram;
  Program volumeKeepProgram, volumeGpuKeptProgram;  // GpuVolumeDraw::KeptQuads
  Program volumeMeshProgram, volumeMeshDrawProgram; // GpuVolumeDraw::ComputeMesh (GL 4.3 only)
  Program volumeIndexProgram, volumeIndexedProgram; // GpuVolumeDraw::Indexed (GL 4.3 only)
  bool hasCompute = false;
  Texture cubeShadow;      // a point light's shadow-map methods: DEPTH_COMPONENT32F cube map
  int cubeShadowSize = 0;
  Sampler fetchSampler, shadowSampler;
  VertexArray emptyVao;
  std::vector<Query> queryPool;
  Query primitivesQuery;  // GL_PRIMITIVES_GENERATED of the GPU volume's geometry shader
  bool volumeTrianglesPending = false;
  bool zPassFrame = false;  // this frame's volume counted with z-pass: no far cap drawn
  bool volumeReadsWindowDepth = false;  // this frame's GPU volume reads the light pass's depth itself
  GLint maxTextureSize = 0, maxRenderbufferSize = 0;
  GLint maxViewport[2] = {0, 0};

  // Scene
  bool hasScene = false;
  Scene scene;                                  // kept for the silhouette method's connectivity
  std::optional<SilhouetteOccluders> occluders;  // built on the first silhouette frame
  std::vector<Light> lights;  // the scene's, first to last
  Light light;                // the one whose passes run now (lights[0] between frames)
  Camera camera;
  VertexArray sceneVao;
  Buffer sceneVbo, sceneEbo;
  GLsizei sceneIndexCount = 0;

  // Explicit volume
  VertexArray volumeVao;
  Buffer volumeVbo, volumeEbo;

  // Compacted GPU volume: the indices of the kept quads (transform feedback), drawn as points
  VertexArray keptVao;
  Buffer keptBuffer;
  std::int64_t keptCapacity = 0;  // quads the buffer holds
  Query keptQuery;                // GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN of the keep pass

  // GPU-built volume mesh: light-view vertices (3 floats each) and their count
  VertexArray meshVao;
  Buffer meshBuffer, meshCount;
  std::int64_t meshCapacity = 0;  // vertices the buffer holds

  // Indexed GPU volume: the kept quads' triangles as texel indices (volume_index.frag), their
  // count, and a framebuffer without attachments for the listing pass
  VertexArray indexVao;
  Buffer indexBuffer, indexCount;
  std::int64_t indexCapacity = 0;  // indices the buffer holds
  Framebuffer listFbo;
  Program lightMarkProgram;       // the light pass that also writes the occupancy bits
  Texture occupancy;              // R32UI, one bit per texel, a word per 8 x 4 texels (light_mark.frag)
  Framebuffer occupancyFbo;       // to clear it
  int occupancyW = 0, occupancyH = 0;
  bool occupancyValid = false;    // this frame's light pass wrote the occupancy bits

  // Refinement by the silhouette walk (GL 4.3 only): the light pass records each texel's triangle
  Program lightTriangleProgram;   // light.vert + light_triangle.frag
  Program lightMarkTriangleProgram;  // both: the refined GPU volume's light pass
  SilhouetteWalk walk;
  SilhouetteRays rays;            // the refined GPU volume's bisection rays (all but RefineCrossings::GpuWalk)
  DualParaboloidPass paraboloid;  // a point light's dual-paraboloid shadow map (ShadowMethod::Dpsm)
  CubeGpuVolume cubeVolume;       // a point light's GPU cube volume (GL 4.3: glCopyImageSubData)
  DualParaboloid paraboloidFrame;  // of the last paraboloid pass
  Bounds3 sceneBounds;             // the scene's (setScene): the paraboloid frame looks at its centre
  Texture triangleIds;            // R32UI, triangle index + 1 (0 = none), at the light targets' size
  Framebuffer layer0IdFbo;        // layer0's depth and triangleIds
  std::optional<RefinedGpuVolume> refined;  // the refined GPU volume's passes, made on its first frame
  std::optional<TexelFootprint> footprint;  // of the light's map at footprintW x footprintH (setScene resets)
  int footprintW = 0, footprintH = 0;
  int triangleIdsW = 0, triangleIdsH = 0;  // 0: to be made (ensureLightTargets remakes layer0)

  // Light targets (W x H)
  int lightW = 0, lightH = 0;
  Texture layer0, layer1, linearDepth, blurredDepth, resolvedDepth;
  Framebuffer layer0Fbo, layer1Fbo, resolveFbo, blurFbo;

  // Camera targets
  int camW = 0, camH = 0;
  Renderbuffer colorRb, depthStencilRb, visibilityRb;  // visibilityRb: R8, written only on request
  Texture ambientImage;      // RGBA8: the camera pass's ambient term (stencil methods)
  Framebuffer cameraFbo;     // colour, visibility, ambient image, depth + stencil
  Framebuffer shadowOverFbo; // colour and depth + stencil only: the lighting pass samples ambientImage
  Texture cubeFaceImage;     // R8UI: the refined GPU cube volume's face per pixel (made on its first frame)
  Framebuffer cubeFaceFbo;   // cubeFaceImage and the camera's depth + stencil
  int cubeFaceW = 0, cubeFaceH = 0;

  Impl(const RendererOptions& options) : context(EglContext::create(options.context)), shaders(options.shaderDir) {
    lightProgram = Program(shaders, "light.vert", "depth_only.frag");
    peelProgram = Program(shaders, "light.vert", "depth_peel.frag");
    resolveProgram = Program(shaders, {"fullscreen.vert"}, {"version_330.glsl", "light_window_depth.glsl", "resolve.frag"});
    blurProgram = Program(shaders, "fullscreen.vert", "blur.frag");
    sceneProgram = Program(shaders, {"scene.vert"}, {"version_330.glsl", "paraboloid.glsl", "cube_face.glsl", "scene.frag"});
    cubeFaceIdProgram = Program(shaders, {"scene.vert"}, {"version_330.glsl", "cube_face.glsl", "cube_face_id.frag"});
    cubeFaceMaskProgram = Program(shaders, "fullscreen.vert", "cube_face_mask.frag");
    paraboloid = DualParaboloidPass(shaders);
    ambientOverProgram = Program(shaders, "fullscreen.vert", "ambient_over.frag");
    volumeProgram = Program(shaders, "volume.vert", "depth_only.frag");
    volumeGpuProgram =
        Program(shaders, {"volume_gpu_points.vert"}, {"version_330.glsl", "light_window_depth.glsl", "volume_common.glsl", "volume_gpu.geom"}, {"depth_only.frag"});
    volumeKeepProgram =
        Program(shaders, {"volume_gpu_points.vert"}, {"version_330.glsl", "light_window_depth.glsl", "volume_common.glsl", "volume_keep.geom"}, {}, {"keptQuad"});
    volumeGpuKeptProgram =
        Program(shaders, {"volume_gpu_kept.vert"}, {"version_330.glsl", "light_window_depth.glsl", "volume_common.glsl", "volume_gpu.geom"}, {"depth_only.frag"});
    const ContextInfo& ci = context.info();
    // Every pass draws in reversed Z through glClipControl: core in 4.5, an extension before.
    if (!(ci.glMajor > 4 || (ci.glMajor == 4 && ci.glMinor >= 5)) && !epoxy_has_gl_extension("GL_ARB_clip_control"))
      throw GlError("the renderer needs OpenGL 4.5 or GL_ARB_clip_control (reversed-Z depth); the context is " +
                    ci.glVersion + " on " + ci.glRenderer);
    hasCompute = ci.glMajor > 4 || (ci.glMajor == 4 && ci.glMinor >= 3);
    if (hasCompute) {
      cubeVolume = CubeGpuVolume(shaders);
      volumeMeshProgram = Program::compute(shaders, {"version_430.glsl", "light_window_depth.glsl", "volume_common.glsl", "volume_mesh.comp"});
      volumeMeshDrawProgram = Program(shaders, "volume_mesh.vert", "depth_only.frag");
      volumeIndexProgram =
          Program(shaders, {"fullscreen.vert"}, {"version_430.glsl", "light_window_depth.glsl", "volume_common.glsl", "volume_index.frag"});
      volumeIndexedProgram =
          Program(shaders, {"version_330.glsl", "light_window_depth.glsl", "volume_common.glsl", "volume_index.vert"}, {"depth_only.frag"});
      lightMarkProgram = Program(shaders, {"light.vert"}, {"version_430.glsl", "light_mark.glsl", "light_mark.frag"});
      lightTriangleProgram =
          Program(shaders, {"light.vert"}, {"version_330.glsl", "light_triangle.glsl", "light_triangle.frag"});
      lightMarkTriangleProgram = Program(shaders, {"light.vert"},
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
    SV_GL(glPixelStorei(GL_PACK_ALIGNMENT, 1));
    SV_GL(glPixelStorei(GL_UNPACK_ALIGNMENT, 1));
  }

  void requireScene() const {
    if (!hasScene) throw InputError("renderer", "", "", "no scene: call setScene() before rendering");
  }

  void checkSize(const char* source, const char* field, int w, int h, int limit) const {
    if (w < 2 || h < 2 || w > limit || h > limit)
      throw InputError(source, field, std::to_string(w) + "x" + std::to_string(h),
                       "must be between 2 and " + std::to_string(limit) + " per side on this OpenGL implementation");
  }

  // ---- light targets -------------------------------------------------------------------------

  void ensureLightTargets(int w, int h) {
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

  void ensureCameraTargets(int w, int h) {
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

  // ---- passes --------------------------------------------------------------------------------

  // Every pass draws with reversed Z (see reversedZ): glClipControl ZERO_TO_ONE, window depth 1 at
  // the near plane and 0 at the far plane, depth cleared to 0, nearer = GL_GREATER.
  void resetState() {
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

  /// One triangle over the viewport (fullscreen.vert, no vertex buffer).
  void drawFullScreenTriangle() {
    SV_GL(glBindVertexArray(emptyVao.id()));
    SV_GL(glDrawArrays(GL_TRIANGLES, 0, 3));
    SV_GL(glBindVertexArray(0));
  }

  void drawScene() {
    SV_GL(glBindVertexArray(sceneVao.id()));
    SV_GL(glDrawElements(GL_TRIANGLES, sceneIndexCount, GL_UNSIGNED_INT, nullptr));
    SV_GL(glBindVertexArray(0));
  }

  /// The light's depth into layer0 (and layer1 for midpoint): window depth (reversed Z), cleared to
  /// 0. With markOccupancy (the indexed GPU volume, GL 4.3) the first layer's fragments also set
  /// their bits in `occupancy` (light_mark.frag).
  void lightPass(int w, int h, CaptureMode mode, bool markOccupancy, bool recordTriangles = false) {
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
    const Program& first = markOccupancy && recordTriangles ? lightMarkTriangleProgram
                           : markOccupancy                  ? lightMarkProgram
                           : recordTriangles                ? lightTriangleProgram
                                                            : lightProgram;
    first.use();
    first.set("worldToLightClip", toFloat(worldToLightClip));
    if (markOccupancy) SV_GL(glBindImageTexture(0, occupancy.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI));
    drawScene();
    if (markOccupancy) {
      SV_GL(glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI));
      SV_GL(glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT));
    }
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
    SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, 0));
  }

  /// The triangle record of the light's first layer (light_triangle.frag) at w x h, with its
  /// framebuffer (layer0's depth; call after ensureLightTargets).
  void ensureTriangleIds(int w, int h) {
    if (w == triangleIdsW && h == triangleIdsH) return;
    triangleIds = makeTexture2D(GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, w, h);
    layer0IdFbo = colourDepthFramebuffer(triangleIds, layer0, "light depth with triangle record");
    SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, 0));
    triangleIdsW = w;
    triangleIdsH = h;
  }

  /// Occupancy of a bw x bh block grid, all bits cleared.
  void clearOccupancy(int bw, int bh) {
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

  void bindCube(int unit, const Texture& tex, const Sampler& sampler) {
    SV_GL(glActiveTexture(GLenum(GL_TEXTURE0 + unit)));
    SV_GL(glBindTexture(GL_TEXTURE_CUBE_MAP, tex.id()));
    SV_GL(glBindSampler(GLuint(unit), tex ? sampler.id() : 0));
    SV_GL(glActiveTexture(GL_TEXTURE0));
  }

  void bindTexture(int unit, const Texture& tex, const Sampler& sampler) {
    SV_GL(glActiveTexture(GLenum(GL_TEXTURE0 + unit)));
    SV_GL(glBindTexture(GL_TEXTURE_2D, tex.id()));
    SV_GL(glBindSampler(GLuint(unit), tex ? sampler.id() : 0));
    SV_GL(glActiveTexture(GL_TEXTURE0));
  }

  /// layer0 (+ layer1) -> linearDepth (R32F, light-view depth, farPlane = no hit) and
  /// resolvedDepth (window depth of the same, for the shadow maps).
  void resolvePass(CaptureMode mode) {
    resetState();
    const glm::dmat4 proj = reversedZ(lightProjection(light, double(lightW) / double(lightH)));
    SV_GL(glViewport(0, 0, lightW, lightH));
    SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, resolveFbo.id()));
    SV_GL(glDepthFunc(GL_ALWAYS));
    resolveProgram.use();
    resolveProgram.set("layer0", 0);
    resolveProgram.set("layer1", 1);
    resolveProgram.set("midpoint", mode == CaptureMode::Midpoint ? 1 : 0);
    resolveProgram.set("depthParams", depthParams(proj));
    resolveProgram.set("farPlane", float(light.farPlane));
    bindTexture(0, layer0, fetchSampler);
    bindTexture(1, layer1, fetchSampler);
    drawFullScreenTriangle();
    SV_GL(glDepthFunc(GL_GREATER));
    SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, 0));
  }

  void blurPass(double blurOffset) {
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

  DepthMap readBack(CaptureMode mode) {
    DepthMap map = makeDepthMap(light, lightW, lightH, mode);
    map.origin = scene.origin;
    const std::size_t n = std::size_t(lightW) * std::size_t(lightH);
    std::vector<float> w0(n), w1;
    SV_GL(glBindTexture(GL_TEXTURE_2D, layer0.id()));
    SV_GL(glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, w0.data()));
    if (mode == CaptureMode::Midpoint) {
      w1.resize(n);
      SV_GL(glBindTexture(GL_TEXTURE_2D, layer1.id()));
      SV_GL(glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, w1.data()));
    }
    SV_GL(glBindTexture(GL_TEXTURE_2D, 0));
    const glm::dmat4 p = reversedZ(map.lightProjection);
    for (std::size_t k = 0; k < n; ++k) {
      if (w0[k] <= 0.0f) continue;  // cleared: the light saw nothing (kNoHit)
      double d = viewDepthFromWindow(p, double(w0[k]));
      if (mode == CaptureMode::Midpoint)
        d = 0.5 * (d + (w1[k] <= 0.0f ? map.farPlane : viewDepthFromWindow(p, double(w1[k]))));
      map.depth[k] = float(d);
    }
    return map;
  }

  /// The map readBack would return for this light after a w x h light pass, each texel from the
  /// oracle's ray at its centre instead (ExplicitDepth::Rays; no GL call).
  DepthMap rayCast(int w, int h, CaptureMode mode, const DepthOracle& oracle) const {
    DepthMap map = makeDepthMap(light, w, h, mode);
    map.origin = scene.origin;
    fillFromOracle(map, oracle);
    return map;
  }

  /// A point light's six faces as captureCube's, each from the oracle's rays.
  CubeDepthMap rayCastCube(int n, CaptureMode mode, const DepthOracle& oracle) const {
    CubeDepthMap cube = makeCubeDepthMap(light, n, mode);
    for (DepthMap& face : cube.faces) {
      face.origin = scene.origin;
      fillFromOracle(face, oracle);
    }
    return cube;
  }

  struct CameraSetup {
    glm::dmat4 view, proj;
    int w, h;
  };

  CameraSetup cameraSetup(const RenderOptions& o) const {
    if (o.imageWidth < 0 || o.imageHeight < 0)
      throw InputError("RenderOptions", "imageWidth x imageHeight",
                       std::to_string(o.imageWidth) + "x" + std::to_string(o.imageHeight),
                       "must not be negative (0 = the scene camera's size)");
    Camera c = camera;
    if (o.imageWidth > 0) c.width = o.imageWidth;
    if (o.imageHeight > 0) c.height = o.imageHeight;
    return {cameraView(c), reversedZ(cameraProjection(c)), c.width, c.height};
  }

  /// Uniforms of sceneProgram shared by every mode.
  void setSceneUniforms(const CameraSetup& cam, const RenderOptions& o, int shadowTaps, int mapW, int mapH) {
    const double aspect = double(mapW) / double(mapH);
    // A point light has no one projection; its lit region is the shell between its near and far
    // cubes (scene.frag), and its cube shadow map compares with its faces' shared projection.
    const glm::dmat4 lp = light.type == LightType::Point ? lightProjection(cubeFaceLight(light, 0), 1.0)
                                                         : lightProjection(light, aspect);
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
    sceneProgram.set("biasConstant",
                     float(o.shadowBiasConstant.value_or(defaultBias(light, mapW, mapH, o.capture))));
    sceneProgram.set("biasSlope", float(o.shadowBiasSlope));
    sceneProgram.set("texelFootprint", float(2.0 / (lp[1][1] * double(mapH))));
    sceneProgram.set("pointShadowMap", 0);
  }

  /// The shade pass's uniforms for the dual-paraboloid maps of the last paraboloidPass, after
  /// setSceneUniforms: the maps' size, the frame, the coarsest texel's angle (4 / side at a map's
  /// centre) as the footprint, and dualParaboloidDefaultBias.
  void setParaboloidUniforms(const RenderOptions& o) {
    const int side = paraboloidFrame.side;
    sceneProgram.set("pointShadowMap", 1);
    DualParaboloidPass::setUniforms(sceneProgram, paraboloidFrame);
    sceneProgram.set("shadowMapSize", glm::vec2(float(2 * side), float(side)));
    sceneProgram.set("biasConstant",
                     float(o.shadowBiasConstant.value_or(dualParaboloidDefaultBias(light, o.depthWidth, o.capture))));
    sceneProgram.set("texelFootprint", float(4.0 / side));
  }

  /// What the camera pass writes besides the colour (COLOR_ATTACHMENT0).
  enum class CameraExtra { None, Visibility, Ambient };

  /// Binds and clears the camera targets. Visibility: the shade pass also writes the shadow test
  /// into COLOR_ATTACHMENT1 (cleared to 1 = lit). Ambient: the stencil methods' camera pass also
  /// writes the ambient term into ambientImage (COLOR_ATTACHMENT2, cleared to the background, so
  /// the lighting pass leaves the background as it is).
  void beginCamera(const CameraSetup& cam, CameraExtra extra = CameraExtra::None) {
    ensureCameraTargets(cam.w, cam.h);
    resetState();
    SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, cameraFbo.id()));
    SV_GL(glViewport(0, 0, cam.w, cam.h));
    SV_GL(glClearColor(0.10f, 0.12f, 0.15f, 1.0f));  // every enabled draw buffer, the ambient image too
    SV_GL(glClearDepth(0.0));  // reversed Z: 0 is the far plane
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

  /// Volume state: two-sided, wrap; colour and depth writes off. z-fail: back faces behind the
  /// surface (failing the reversed-Z GREATER test) add one, front faces subtract one, with depth
  /// clamp on so that the far cap is never clipped. z-pass: front faces in front of the surface
  /// add one, back faces subtract one, clipped at the near plane as usual. A face exactly at the
  /// surface's depth counts as behind in both, so where both are right they agree exactly.
  void beginVolume(bool zPass) {
    SV_GL(glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE));
    SV_GL(glDepthMask(GL_FALSE));
    SV_GL(glDepthFunc(GL_GREATER));
    if (zPass) SV_GL(glDisable(GL_DEPTH_CLAMP));
    else SV_GL(glEnable(GL_DEPTH_CLAMP));
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

  void endVolume() {
    SV_GL(glDisable(GL_DEPTH_CLAMP));
    SV_GL(glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE));
  }

  /// The image rectangle (x, y, width, height; GL window coordinates) that holds the light
  /// frustum's projection, `aspect` the frustum's as in the camera pass; the whole image when a
  /// corner lies on or behind the camera's eye plane. Outside the frustum lit = 0 (scene.frag), so
  /// the lit colour there is the ambient term already.
  std::array<GLint, 4> lightFrustumOnImage(const CameraSetup& cam, double aspect) const {
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

  /// A further light's start (render()): the camera's colour and depth kept, the stencil cleared
  /// for its volume, and with `visibility` its shadow test's attachment cleared to lit.
  void beginAddedLight(const CameraSetup& cam, bool visibility) {
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

  /// State of a further light's shade draw: the scene again at the depth the camera pass left
  /// (GL_EQUAL: the same program and vertices give the same depth), its colour added to the
  /// image (the shadow test's attachment written, not added), and with `stencilLit` only where
  /// this light's stencil is 0. The caller sets ambient 0 after setSceneUniforms.
  void addDiffuseState(bool stencilLit) {
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

  /// A further light's diffuse term where its stencil is 0 (stencil methods), scissored to its
  /// frustum's rectangle on the image (lightFrustumOnImage): outside it the light adds nothing.
  void addDiffusePass(const CameraSetup& cam, const RenderOptions& o, int frustumW, int frustumH) {
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

  /// The ambient term over the lit colour where stencil != 0: one full-screen triangle instead of
  /// drawing the scene again (docs/gpu.md "Passes of one frame"), scissored to the light
  /// frustum's rectangle on the image (lightFrustumOnImage).
  void lightingPass(const CameraSetup& cam, double frustumAspect) {
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

  /// Uniforms of volume_common.glsl (both GPU-volume programs).
  void setVolumeUniforms(const Program& p, const VolumeBuildOptions& vo, double bias) {
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

  /// The way the GPU volume will be drawn (before the fallbacks for sizes, drawGpuVolume):
  /// Auto is Indexed where GL 4.3 is there, else KeptQuads (the fastest measured on llvmpipe,
  /// docs/gpu.md); nothing is skipped with the quad cap.
  GpuVolumeDraw chooseGpuVolumeDraw(GpuVolumeDraw how, const VolumeBuildOptions& vo) const {
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

  /// `how`: chooseGpuVolumeDraw's choice for this frame (made before the light pass, which marks
  /// the occupancy bits for Indexed); here it may still fall back for sizes.
  void drawGpuVolume(const CameraSetup& cam, const VolumeBuildOptions& vo, double bias, const Texture& depth,
                     GpuVolumeDraw how, RenderResult& result) {
    const glm::dmat4 lightViewToClip = cam.proj * cam.view * glm::inverse(lightView(light));
    const std::int64_t quads = std::int64_t(lightW - 1) * std::int64_t(lightH - 1);
    result.gpuVolumeQuads = std::size_t(quads);
    result.gpuVolumeQuadsDrawn = std::size_t(quads);
    // KeptQuads needs 4 bytes per quad: up to 2^26 quads (8192^2 maps), 256 MB.
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
    if (how == GpuVolumeDraw::KeptQuads)
      return drawCompactGpuVolume(lightViewToClip, vo, bias, depth, quads, result);
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

  /// The GPU volume built by a compute pass (volume_mesh.comp) as a light-view triangle list, then
  /// drawn with a plain vertex shader. The buffer grows to what the frame needs (the count is read
  /// back after the pass; a frame that overflows it runs the pass again) up to kMaxMeshBytes;
  /// false when the mesh would be larger (the caller falls back to KeptQuads).
  bool drawComputedGpuVolume(const glm::dmat4& lightViewToClip, const VolumeBuildOptions& vo, double bias,
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

  /// The GPU volume as an indexed triangle list: volume_index.frag (one fragment per block of
  /// quads, a framebuffer without attachments) appends the kept quads' triangles as texel indices,
  /// volume_index.vert places each texel's vertex. The buffer grows to what the frame needs (the
  /// count is read back after the pass; a frame that overflows it runs the pass again) up to
  /// kMaxIndexBytes; false when the list would be larger (the caller falls back to KeptQuads).
  /// With `cells` the refined GPU volume: its cells in the same list, volume_refined.vert draws all.
  bool drawIndexedGpuVolume(const CameraSetup& cam, const glm::dmat4& lightViewToClip, const VolumeBuildOptions& vo,
                            double bias, const Texture& depth, std::int64_t quads, RenderResult& result,
                            RefinedGpuVolume* cells = nullptr) {
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

  /// drawIndexedGpuVolume's listing pass alone: `counts` = indices, quads; false when the list
  /// would not fit. With `cells` (the refined GPU volume) its refined cells are listed first into
  /// the same buffer and the listing pass leaves their quads out.
  bool listIndexedGpuVolume(const CameraSetup& cam, const VolumeBuildOptions& vo, double bias, const Texture& depth,
                            std::int64_t quads, std::array<GLuint, 2>& counts, RefinedGpuVolume* cells = nullptr) {
    constexpr std::int64_t kMaxIndexBytes = std::int64_t(1) << 29;  // 512 MiB
    constexpr int kBlockX = 8, kBlockY = 4;                        // volume_index.frag's kBlock
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

  /// The first `count` indices of the indexed volume's buffer (the refined GPU volume's debug path).
  std::vector<std::uint32_t> readIndexList(GLuint count) {
    std::vector<std::uint32_t> out(count);
    if (out.empty()) return out;
    SV_GL(glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT));
    SV_GL(glBindBuffer(GL_COPY_READ_BUFFER, indexBuffer.id()));
    SV_GL(glGetBufferSubData(GL_COPY_READ_BUFFER, 0, GLsizeiptr(out.size() * 4), out.data()));
    SV_GL(glBindBuffer(GL_COPY_READ_BUFFER, 0));
    return out;
  }

  /// The refined GPU volume's boundary edges and crossings for this frame's map (`depth`: the
  /// final sheet depths; with blur the unblurred are linearDepth): by the walk for
  /// RefineCrossings::GpuWalk, else by bisection rays on the GPU (vo.refineSteps per edge,
  /// `capture`'s rule).
  void findGpuCrossings(const VolumeBuildOptions& vo, double bias, const Texture& depth, RefineCrossings crossings,
                        CaptureMode capture) {
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
      if (byRays) rays.dispatchGrid(in, vo.refineSteps, capture, vo.refineSnap, indirectOffset);
      else walk.dispatchGrid(in, hitLimit, indirectOffset);
    });
  }

  /// The refined GPU volume: its refined cells (volume_refined.comp) and the other quads as the
  /// indexed way lists them (volume_index.frag with skipRefined), one list, one draw.
  void drawRefinedGpuVolume(const CameraSetup& cam, const VolumeBuildOptions& vo, double bias, const Texture& depth,
                            RenderResult& result) {
    const glm::dmat4 lightViewToClip = cam.proj * cam.view * glm::inverse(lightView(light));
    const std::int64_t quads = std::int64_t(lightW - 1) * std::int64_t(lightH - 1);
    bindTexture(3, vo.blur ? linearDepth : depth, fetchSampler);
    const bool drawn = drawIndexedGpuVolume(cam, lightViewToClip, vo, bias, depth, quads, result, &*refined);
    bindTexture(3, Texture(), fetchSampler);
    SV_GL(glActiveTexture(GL_TEXTURE2));
    SV_GL(glBindTexture(GL_TEXTURE_2D_ARRAY, 0));
    SV_GL(glActiveTexture(GL_TEXTURE0));
    if (!drawn)
      throw InputError("RenderOptions", "depthWidth x depthHeight", std::to_string(lightW) + "x" + std::to_string(lightH),
                       "the refined GPU volume's index list would pass 512 MiB or 32-bit indices: use a smaller map");
    const RefinedGpuCounts counts = refined->walkCounts();
    result.gpuVolumeDrawUsed = GpuVolumeDraw::Refined;
    result.gpuVolumeQuads = std::size_t(quads);
    result.gpuBoundaryEdges = counts.boundaryEdges;
    result.gpuCrossingFallbacks = counts.fallbacks;
  }

  /// The crossings of the last refined GPU frame, read back, as the CPU builder's crossing source
  /// (refinementFromGpuRecords).
  CrossingSource gpuCrossingSource() {
    return [flags = refined->readFlags(), records = refined->readRecords()](
               const DepthMap& map, const BoundaryEdges& edges, const SheetDepthRule& rule, bool blur,
               std::span<const double> blurred, std::span<const glm::dvec2> centres) {
      return refinementFromGpuRecords(map, edges, rule, blur, blurred, centres, flags, records);
    };
  }

  void growIndices(std::int64_t indices) {
    SV_GL(glBindVertexArray(indexVao.id()));
    SV_GL(glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer.id()));
    SV_GL(glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices * 4), nullptr, GL_DYNAMIC_COPY));
    SV_GL(glBindVertexArray(0));
    indexCapacity = indices;
  }

  void growMesh(std::int64_t vertices) {
    SV_GL(glBindBuffer(GL_ARRAY_BUFFER, meshBuffer.id()));
    SV_GL(glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices * 12), nullptr, GL_DYNAMIC_COPY));
    SV_GL(glBindVertexArray(meshVao.id()));
    SV_GL(glEnableVertexAttribArray(0));
    SV_GL(glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 12, nullptr));
    SV_GL(glBindVertexArray(0));
    SV_GL(glBindBuffer(GL_ARRAY_BUFFER, 0));
    meshCapacity = vertices;
  }

  /// The GPU volume in two passes: volume_keep.geom writes the indices of the quads that are not
  /// all on the far plane (transform feedback, rasteriser off), then volume_gpu.geom expands only
  /// those. Same triangles as the direct draw, in the same quad order.
  void drawCompactGpuVolume(const glm::dmat4& lightViewToClip, const VolumeBuildOptions& vo, double bias,
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

  void uploadVolume(const VolumeMesh& volume) {
    const TriangleMesh m = volume.toTriangleMesh();
    SV_GL(glBindBuffer(GL_ARRAY_BUFFER, volumeVbo.id()));
    SV_GL(glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(m.positions.size() * sizeof(glm::vec3)), m.positions.data(),
                       GL_STREAM_DRAW));
    SV_GL(glBindBuffer(GL_ARRAY_BUFFER, 0));
    SV_GL(glBindVertexArray(volumeVao.id()));
    SV_GL(glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(m.triangles.size() * sizeof(m.triangles[0])),
                       m.triangles.data(), GL_STREAM_DRAW));
    SV_GL(glBindVertexArray(0));
  }

  void drawExplicitVolume(const CameraSetup& cam, std::size_t triangles, RenderResult& result) {
    volumeProgram.use();
    volumeProgram.set("worldToClip", toFloat(cam.proj * cam.view));
    SV_GL(glBindVertexArray(volumeVao.id()));
    SV_GL(glDrawElements(GL_TRIANGLES, GLsizei(triangles * 3), GL_UNSIGNED_INT, nullptr));
    SV_GL(glBindVertexArray(0));
    result.volumeTriangles = triangles;
  }

  /// Stencil counts (when `stencil`), and the visibility mask: from the stencil (`visibility` ==
  /// FromStencil), from COLOR_ATTACHMENT1 (FromAttachment), or all lit (AllLit).
  enum class VisibilitySource { NotRead, FromStencil, FromAttachment, AllLit };

  /// GL row 0 is the bottom; images start at the top. Flips `rows` rows of `rowBytes` in place.
  static void flipRows(std::vector<std::uint8_t>& image, std::size_t rowBytes, int rows) {
    for (int y = 0; y < rows / 2; ++y)
      std::swap_ranges(image.begin() + std::ptrdiff_t(std::size_t(y) * rowBytes),
                       image.begin() + std::ptrdiff_t(std::size_t(y + 1) * rowBytes),
                       image.begin() + std::ptrdiff_t(std::size_t(rows - 1 - y) * rowBytes));
  }

  // Read straight into the result's vectors and flipped in place, without the staging copies of
  // the colour and visibility images (the stencil counts still go through one vector).
  /// The frame's colour (after every light's passes).
  void readColour(const CameraSetup& cam, RenderResult& r) {
    SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, cameraFbo.id()));
    r.rgba.resize(std::size_t(cam.w) * std::size_t(cam.h) * 4);
    SV_GL(glReadBuffer(GL_COLOR_ATTACHMENT0));
    SV_GL(glReadPixels(0, 0, cam.w, cam.h, GL_RGBA, GL_UNSIGNED_BYTE, r.rgba.data()));
    flipRows(r.rgba, std::size_t(cam.w) * 4, cam.h);
    SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, 0));
  }

  /// One light's stencil counts and shadow test, read before the next light's passes.
  void readShadowImages(const CameraSetup& cam, bool stencil, VisibilitySource visibility, RenderResult& r) {
    const int w = cam.w, h = cam.h;
    r.width = w;
    r.height = h;
    SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, cameraFbo.id()));
    const std::size_t pixels = std::size_t(w) * std::size_t(h);
    if (stencil || visibility == VisibilitySource::FromStencil) {
      std::vector<std::uint8_t> counts(pixels);
      SV_GL(glReadPixels(0, 0, w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, counts.data()));
      flipRows(counts, std::size_t(w), h);
      if (visibility == VisibilitySource::FromStencil) {
        r.visibility.resize(pixels);
        for (std::size_t k = 0; k < pixels; ++k) r.visibility[k] = counts[k] == 0 ? 255 : 0;
      }
      if (stencil) r.stencil = std::move(counts);
    }
    if (visibility == VisibilitySource::FromAttachment) {
      r.visibility.resize(pixels);
      SV_GL(glReadBuffer(GL_COLOR_ATTACHMENT1));
      SV_GL(glReadPixels(0, 0, w, h, GL_RED, GL_UNSIGNED_BYTE, r.visibility.data()));
      SV_GL(glReadBuffer(GL_COLOR_ATTACHMENT0));
      flipRows(r.visibility, std::size_t(w), h);
    } else if (visibility == VisibilitySource::AllLit) {
      r.visibility.assign(pixels, 255);
    }
    SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, 0));
  }

  /// What a point light's frame can be (docs/gpu.md "Point lights"): the explicit cube volume
  /// (hybrid, explicit; refined by rays alone), the GPU cube volume (hybrid, gpu; GL 4.3; refined:
  /// six face volumes, drawRefinedCubeFaces, with the refined GPU volume's rules of validate()),
  /// silhouette volumes, a cube shadow map (GL 4.3), dual-paraboloid maps or no shadows.
  void validatePointLight(const RenderOptions& o) const {
    if (o.method == ShadowMethod::Hybrid) {  // either cube volume
      // The GPU cube volume's face volumes take the GPU's rays or walk as one map's refined GPU
      // volume does; the explicit cube volume only Embree's rays.
      if (o.volumeOptions.refineSteps > 0 && o.refineCrossings != RefineCrossings::Rays && o.volume != VolumeSource::Gpu)
        throw InputError("RenderOptions", "refineCrossings", toString(o.refineCrossings), kCubeRefinementRule);
      if (o.volumeOptions.cap != FarCap::Exact)
        throw InputError("RenderOptions", "volumeOptions.cap", toString(o.volumeOptions.cap), kCubeVolumeCapRule);
      if (o.volume == VolumeSource::Gpu) validateGpuCubeVolume(o);
    }
    const bool shadowMap = o.method == ShadowMethod::ShadowMap || o.method == ShadowMethod::Pcf3 ||
                           o.method == ShadowMethod::Pcf5;
    if (shadowMap && !hasCompute)
      throw InputError("RenderOptions", "method", toString(o.method),
                       "a point light's cube shadow map needs OpenGL 4.3 (glCopyImageSubData); this context has " +
                           context.info().glVersion);
    if (o.method == ShadowMethod::Dpsm && o.capture == CaptureMode::Midpoint)
      throw InputError("RenderOptions", "capture", "midpoint",
                       "the dual-paraboloid map takes back or front capture (it has no second layer)");
    const int s = o.paraboloidSubdivision;
    if (s != 1 && s != 2 && s != 4 && s != 8)
      throw InputError("RenderOptions", "paraboloidSubdivision", std::to_string(s), "must be 1, 2, 4 or 8");
    if (o.method == ShadowMethod::Dpsm) {
      const int side = dualParaboloidSide(o.depthWidth);
      if (2 * side > std::min(maxTextureSize, maxViewport[0]))
        throw InputError("RenderOptions", "depthWidth", std::to_string(o.depthWidth),
                         "its dual-paraboloid maps (2 x " + std::to_string(side) + " texels wide) exceed this "
                         "context's largest texture or viewport, " + std::to_string(std::min(maxTextureSize, maxViewport[0])));
    }
    if (o.depthWidth != o.depthHeight)
      throw InputError("RenderOptions", "depthWidth x depthHeight",
                       std::to_string(o.depthWidth) + "x" + std::to_string(o.depthHeight),
                       "a point light's cube faces are square");
  }

  /// What the GPU cube volume (cube_gpu_volume.h) takes beyond the explicit one: GL 4.3 and its two
  /// ways of drawing.
  void validateGpuCubeVolume(const RenderOptions& o) const {
    if (!hasCompute)
      throw InputError("RenderOptions", "volume", "gpu",
                       "a point light's GPU cube volume needs OpenGL 4.3 (glCopyImageSubData); this context has " +
                           context.info().glVersion + ": use volume explicit");
    const GpuVolumeDraw d = o.gpuVolumeDraw;
    if (d != GpuVolumeDraw::Auto && d != GpuVolumeDraw::Indexed && d != GpuVolumeDraw::AllQuads)
      throw InputError("RenderOptions", "gpuVolumeDraw", toString(d),
                       "a point light's GPU cube volume is drawn indexed (auto) or one point per cell (all-quads)");
  }

  /// Given depth offsets that would leave nothing in shadow under this light (offsetEmptiesRange,
  /// sheet_depth.h): the volume's bias (plus the blur offset with blur), a one-map shadow map's
  /// constant bias.
  void checkOffsetRanges(const RenderOptions& o) const {
    const VolumeBuildOptions& v = o.volumeOptions;
    const double bias = v.bias.value_or(0.0);
    const EmptyingOffset e = volumeOffsetEmptiesRange(bias, v.blurOffset, v.blur, light.nearPlane, light.farPlane);
    if (o.method == ShadowMethod::Hybrid && !e.why.empty())
      throw InputError("RenderOptions", e.blurOffset ? "volumeOptions.blurOffset" : "volumeOptions.bias",
                       numberText(e.blurOffset ? v.blurOffset : bias), e.why);
    const bool oneMap = o.method == ShadowMethod::ShadowMap || o.method == ShadowMethod::Pcf3 || o.method == ShadowMethod::Pcf5;
    if (oneMap && light.type != LightType::Point && o.shadowBiasConstant)
      if (const std::string why = offsetEmptiesRange(*o.shadowBiasConstant, light.nearPlane, light.farPlane); !why.empty())
        throw InputError("RenderOptions", "shadowBiasConstant", numberText(*o.shadowBiasConstant), why);
  }

  void validate(const RenderOptions& o, const CameraSetup& cam) const {
    requireScene();
    checkSize("RenderOptions", "depthWidth x depthHeight", o.depthWidth, o.depthHeight, std::min(maxTextureSize, maxViewport[0]));
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
      throw InputError("RenderOptions", "method", "dpsm",
                       std::string("dual-paraboloid maps are a point light's; this scene's light is ") +
                           toString(light.type));
    if (refinedGpuVolume(o)) {
      auto refuse = [&](const std::string& why) {
        throw InputError("RenderOptions", "volumeOptions.refineSteps", std::to_string(o.volumeOptions.refineSteps),
                         "the refined GPU volume " + why);
      };
      if (!hasCompute) refuse("needs OpenGL 4.3 (compute shaders); this context has " + context.info().glVersion);
      if (o.capture == CaptureMode::Midpoint)
        refuse("finds its crossings on one layer (its rays or its walk); midpoint capture is the mean of two: use "
               "back or front capture, or the explicit volume with rays");
      if (o.volumeOptions.cap != FarCap::Exact)
        refuse("needs the exact cap: the quad cap keeps the far-plane sheet that refinement replaces by walls");
      if (o.volumeOptions.refineChords || o.volumeOptions.refineSubdivisions > 1)
        refuse("finds the boundary edges' crossings alone: chord points and the sub-grid need the explicit volume "
               "with rays");
      // The maps it walks: one W x H, or a point light's six faces with their guard band
      // (drawRefinedCubeFaces), each (N + 2 G)^2.
      const bool point = light.type == LightType::Point;
      const std::int64_t w = point ? o.depthWidth + 2 * kCubeGuardTexels : o.depthWidth;
      const std::int64_t h = point ? w : o.depthHeight;
      if (w * h > kMaxRefinedGpuTexels)
        throw InputError("RenderOptions", "depthWidth x depthHeight",
                         std::to_string(o.depthWidth) + "x" + std::to_string(o.depthHeight),
                         "the refined GPU volume takes maps of up to 2048 x 2048 texels (its index list is kept "
                         "under 512 MiB)" +
                             (point ? std::string("; a point light's faces are drawn with a guard band of ") +
                                          std::to_string(kCubeGuardTexels) + " texels a side, so up to " +
                                          std::to_string(2048 - 2 * kCubeGuardTexels) + " texels per face"
                                    : std::string()));
      if (o.gpuVolumeDraw != GpuVolumeDraw::Auto)
        throw InputError("RenderOptions", "gpuVolumeDraw", toString(o.gpuVolumeDraw),
                         "the refined GPU volume lists its triangles its own way: leave it at auto");
    }
    if (o.gpuVolumeDraw == GpuVolumeDraw::Refined)
      throw InputError("RenderOptions", "gpuVolumeDraw", "refined",
                       "is what a refined GPU volume (volumeOptions.refineSteps > 0) reports, not a choice");
    if (o.refineCrossings == RefineCrossings::GpuWalk) {
      auto refuse = [](const std::string& value, const std::string& why) {
        throw InputError("RenderOptions", "refineCrossings", value, why);
      };
      if (o.method != ShadowMethod::Hybrid || o.volumeOptions.refineSteps == 0)
        refuse("gpu-walk", "the silhouette walk refines a hybrid volume: it needs method hybrid and refineSteps > 0");
      if (!hasCompute) refuse("gpu-walk", "the silhouette walk needs OpenGL 4.3 (compute shaders); this context has " +
                                              context.info().glVersion);
      if (o.capture == CaptureMode::Midpoint)
        refuse("gpu-walk", "the silhouette walk follows one layer; midpoint capture is the mean of two: use rays "
                           "(RefineCrossings::Rays) or back or front capture");
      if (o.volumeOptions.refineChords || o.volumeOptions.refineSubdivisions > 1)
        refuse("gpu-walk", "chord points and the sub-grid need rays (a depth oracle); the walk gives the boundary "
                           "edges' crossings alone");
    }
    if (o.refineCrossings == RefineCrossings::GpuRays && !refinedGpuVolume(o))
      throw InputError("RenderOptions", "refineCrossings", "gpu-rays",
                       "the GPU's rays refine the GPU volume: it needs method hybrid, volume gpu and refineSteps > 0 "
                       "(the explicit volume casts Embree's rays: RefineCrossings::Rays)");
    if (o.explicitDepth == ExplicitDepth::Rays) {
      auto refuse = [](const std::string& why) { throw InputError("RenderOptions", "explicitDepth", "rays", why); };
      if (o.method != ShadowMethod::Hybrid || o.volume != VolumeSource::Explicit)
        refuse("casts the explicit volume's depth map: it needs method hybrid and volume explicit");
      if (!o.volumeOptions.depthOracle)
        refuse("needs volumeOptions.depthOracle, the scene's rays (EmbreeDepthOracle)");
      if (o.refineCrossings == RefineCrossings::GpuWalk)
        refuse("has no light pass, whose triangle record the silhouette walk follows: use the light pass "
               "(ExplicitDepth::LightPass) or the crossings from rays");
    }
  }

  /// This frame draws the refined GPU volume (refined_gpu_volume.h).
  static bool refinedGpuVolume(const RenderOptions& o) {
    return o.method == ShadowMethod::Hybrid && o.volume == VolumeSource::Gpu && o.volumeOptions.refineSteps > 0;
  }

  /// This frame refines its explicit volume with the GPU's silhouette walk.
  static bool walkCrossings(const RenderOptions& o) {
    return o.refineCrossings == RefineCrossings::GpuWalk && o.method == ShadowMethod::Hybrid &&
           o.volume == VolumeSource::Explicit && o.volumeOptions.refineSteps > 0;
  }

  /// The volume options with the silhouette walk as the crossing source, reading this frame's
  /// light pass (its triangle record) and the scene's buffers.
  VolumeBuildOptions withWalk(const VolumeBuildOptions& vo) {
    VolumeBuildOptions v = vo;
    v.crossingSource = [this](const DepthMap& map, const BoundaryEdges& edges, const SheetDepthRule& rule,
                                              bool blur, std::span<const double> blurred,
                                              std::span<const glm::dvec2> centres) {
      return walk.run(walkInputs(), map, edges, rule, blur, blurred, centres);
    };
    return v;
  }

  /// What the walk reads after a light pass that recorded its triangles; sets its uniforms.
  WalkInputs walkInputs() {
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

  /// The refined GPU volume's debug read-back of the map just drawn (`volumeDepth` its final sheet
  /// depths): the map (result.depthMap), the CPU mesh from the GPU's crossings (result.volume and
  /// volumeStats) and the GPU's own triangles placed in double (result.gpuVolume).
  void refinedGpuDebugMeshes(const CameraSetup& cam, const RenderOptions& o, const Texture& volumeDepth,
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
    SV_CHECK(listIndexedGpuVolume(cam, vo, result.biasUsed, volumeDepth, std::int64_t(lightW - 1) * (lightH - 1),
                                  listed, &*refined));
    bindTexture(3, Texture(), fetchSampler);
    const std::vector<std::uint32_t> indices = readIndexList(listed[0]);
    result.gpuVolume = decodeRefinedGpuVolume(*result.depthMap, rule, vo.blur, indices, refined->readRecords());
  }

  /// The GPU volume's input depths for this frame's light pass: the light pass's window depth
  /// where the indexed volume converts the few texels it reads itself, else the resolved depth
  /// (timed as `resolve`); with blur the blurred (timed as `blur`). Midpoint and blur need the
  /// resolved depth (docs/gpu.md).
  const Texture* gpuVolumeDepth(const RenderOptions& o, bool indexedVolume, PassTimer& timer) {
    const VolumeBuildOptions& vo = o.volumeOptions;
    volumeReadsWindowDepth = indexedVolume && o.capture != CaptureMode::Midpoint && !vo.blur;  // refined too
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

  /// The refined GPU cube volume (docs/gpu.md "The refined GPU cube volume"): six closed volumes,
  /// each face's refined GPU volume (refined_gpu_volume.h) over the face's frustum widened by
  /// kCubeGuardTexels (guardedCubeFaceLight), and each pixel counted against the volume of the
  /// face its surface point lies on. Once: the face image (writeCubeFaceImage). Per face: the light
  /// pass with the triangle record, the crossings, the face mask (maskOtherCubeFaces: stencil bit 7
  /// on the pixels of the other faces) and the volume counted in bits 0-6 where bit 7 is clear. The
  /// mask is cleared at the end, so the stencil holds each pixel's count of its own face's volume,
  /// modulo 128 (result.stencilBits).
  /// With keepVolume each face's debug meshes (refinedGpuDebugMeshes) go to result.faceVolumes
  /// and faceGpuVolumes. Call with the camera pass drawn; the point light is set back afterwards.
  void drawRefinedCubeFaces(const RenderOptions& o, const CameraSetup& cam, PassTimer& timer, RenderResult& result) {
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

  /// The face image of a point light at `lightPosition`: for each pixel, the cube face its surface
  /// point (the camera pass's depth, GL_EQUAL) lies on (cube_face_id.frag, cubeLookup's rule); 255
  /// on the background. One scene pass per light, read by the six masks.
  void writeCubeFaceImage(const CameraSetup& cam, const glm::dvec3& lightPosition) {
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

  /// Stencil bit 7 set on the pixels of the face image (writeCubeFaceImage) that lie on another
  /// cube face than `face` or on the background, clear elsewhere; colour, depth and bits 0-6 kept.
  void maskOtherCubeFaces(const CameraSetup& cam, int face) {
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

  /// Sets the renderer's light back to `saved` when it goes (a pass between may throw).
  struct LightRestore {
    Light& light;
    Light saved;
    ~LightRestore() { light = saved; }
  };

  /// For each face of a point light's cube (cube_map.h): the light pass of the face's spot light
  /// at n x n, then `afterPass(f)` while that light is the renderer's; the point light is set back
  /// after each face, and when a pass throws.
  template <class AfterPass>
  void eachCubeFace(int n, CaptureMode mode, AfterPass afterPass) {
    const LightRestore restore{light, light};
    const Light& point = restore.saved;
    for (int f = 0; f < kCubeFaces; ++f) {
      light = cubeFaceLight(point, f);
      lightPass(n, n, mode, false);
      afterPass(f);
      light = point;
    }
  }

  /// A point light's six faces: each face's light pass, read back as captureDepth does.
  CubeDepthMap captureCube(int n, CaptureMode mode) {
    CubeDepthMap cube = makeCubeDepthMap(light, n, mode);
    eachCubeFace(n, mode, [&](int f) { cube.faces[f] = readBack(mode); });
    return cube;
  }

  /// The GPU cube volume's input (cube_gpu_volume.h): each face's light pass, resolved (and with
  /// blur blurred) and copied into the cube volume's layer, all timed as `light`; then its
  /// triangles listed (timed as `list`). With keepVolume each face is also read back and the
  /// explicit cube volume built from the six maps with the same options (result.volume: the CPU
  /// mirror that validation counts the crossings of; the GPU draws the same surface, its cap
  /// triangulated otherwise).
  void cubeVolumeDepthPass(const RenderOptions& o, PassTimer& timer, RenderResult& result) {
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

  /// The GPU cube volume of the faces cubeVolumeDepthPass stored and listed (stencil state set);
  /// its counts are read after the frame (cubeVolume.lastCounts).
  void drawCubeGpuVolume(const CameraSetup& cam) {
    cubeVolume.draw(cam.proj * cam.view * glm::translate(glm::dmat4(1.0), light.position));
  }

  /// A point light's cube shadow map: the light pass of each face's spot light (and for midpoint
  /// the mean's window depth, resolvePass), copied into face f of the cube texture, whose texel
  /// order is the faces' (cube_map.h), so samplerCubeShadow looks up the texel the face's
  /// map has. Window depth as the 2D shadow map's; the same projection for all six faces.
  void cubeShadowPass(int n, CaptureMode mode) {
    if (n != cubeShadowSize) {
      cubeShadow = makeTexture();
      SV_GL(glBindTexture(GL_TEXTURE_CUBE_MAP, cubeShadow.id()));
      SV_GL(glTexStorage2D(GL_TEXTURE_CUBE_MAP, 1, GL_DEPTH_COMPONENT32F, n, n));
      SV_GL(glBindTexture(GL_TEXTURE_CUBE_MAP, 0));
      cubeShadowSize = n;
    }
    eachCubeFace(n, mode, [&](int f) {
      if (mode == CaptureMode::Midpoint) resolvePass(mode);
      const Texture& face = mode == CaptureMode::Midpoint ? resolvedDepth : layer0;
      SV_GL(glCopyImageSubData(face.id(), GL_TEXTURE_2D, 0, 0, 0, 0, cubeShadow.id(), GL_TEXTURE_CUBE_MAP, 0, 0, 0, f,
                               n, n, 1));
    });
  }

  /// A point light's dual-paraboloid maps for a cube face side of n (dual_paraboloid.h).
  void paraboloidPass(int n, CaptureMode mode, int subdivision) {
    paraboloidFrame = makeDualParaboloid(light, sceneBounds, dualParaboloidSide(n));
    resetState();
    paraboloid.draw(paraboloidFrame, mode, subdivision, [this] { drawScene(); });
  }

  /// Z-pass for this frame: hybrid volumes built from the depth map only, where zPassSafety allows.
  bool chooseZPass(const RenderOptions& o, const CameraSetup& cam, bool givenVolume, RenderResult& result) const {
    if (givenVolume || o.method != ShadowMethod::Hybrid || o.volumeCount == VolumeCount::ZFail) return false;
    if (light.type == LightType::Point) {  // zpass.h decides for one frustum; the cube has six
      if (o.volumeCount == VolumeCount::ZPass)
        throw InputError("RenderOptions", "volumeCount", "zpass", "a point light's volume is counted by z-fail only");
      result.zPassRefused = "a point light's volume is counted by z-fail only";
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

  /// A CPU-built volume into the frame: its stats and bias into `result`, uploaded (timed as
  /// `upload`), kept when the options ask; returns its triangle count.
  std::size_t useBuiltVolume(VolumeBuildResult&& built, const RenderOptions& o, PassTimer& timer, RenderResult& result) {
    result.biasUsed = built.stats.biasUsed;
    result.volumeStats = built.stats;
    const auto t0 = Clock::now();
    uploadVolume(built.mesh);
    glFinish();
    timer.cpu("upload", msSince(t0));
    const std::size_t triangles = built.mesh.triangleCount();
    if (o.keepVolume) result.volume = std::move(built.mesh);
    return triangles;
  }

  /// Light k of the scene as the renderer's light while `f` runs; lights[0] again afterwards.
  template <class F>
  void withLight(std::size_t k, F&& f) {
    struct Restore {
      Impl& impl;
      ~Restore() { impl.light = impl.lights.front(); }
    } restore{*this};
    light = lights[k];
    f();
  }

  /// One frame: every light's passes into the same image (README "Several lights"). Light 0
  /// draws the camera pass; each further light clears the stencil, draws its volume or shadow
  /// map, and adds its diffuse term where its own test says lit (additive blending on the RGBA8
  /// image, so a channel's sum saturates at 1).
  RenderResult render(const RenderOptions& o, const VolumeMesh* givenVolume) {
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

  /// validate() for light k (the renderer's light now), its errors naming the light.
  void validateForLight(const RenderOptions& o, const CameraSetup& cam, std::size_t k) const {
    if (lights.size() == 1) return validate(o, cam);
    try {
      validate(o, cam);
    } catch (const InputError& e) {
      throw InputError(e.source(), e.field(), e.value(),
                       e.problem() + " (for light " + std::to_string(k) + " of the scene's " +
                           std::to_string(lights.size()) + ")");
    }
  }

  /// The passes of the renderer's light. `added`: a further light of the frame (render()): no
  /// camera pass, its diffuse term added to the image.
  RenderResult renderLight(const RenderOptions& o, const CameraSetup& cam, const VolumeMesh* givenVolume,
                           PassTimer& timer, bool added) {
    volumeTrianglesPending = false;  // a frame that threw may have left it set
    volumeReadsWindowDepth = false;
    RenderResult result;
    zPassFrame = chooseZPass(o, cam, givenVolume != nullptr, result);
    result.volumeCountUsed = zPassFrame ? VolumeCount::ZPass : VolumeCount::ZFail;
    const bool silhouette = !givenVolume && o.method == ShadowMethod::Silhouette;
    const bool hybrid = givenVolume || o.method == ShadowMethod::Hybrid;
    const bool stencilShadows = hybrid || silhouette;
    const VolumeBuildOptions& vo = o.volumeOptions;

    const bool point = light.type == LightType::Point;
    const bool gpuVolume = hybrid && !givenVolume && o.volume == VolumeSource::Gpu && !point;
    const bool cubeGpu = hybrid && !givenVolume && o.volume == VolumeSource::Gpu && point && vo.refineSteps == 0;
    const bool refinedCube = hybrid && !givenVolume && o.volume == VolumeSource::Gpu && point && vo.refineSteps > 0;
    const bool refinedGpu = gpuVolume && refinedGpuVolume(o);
    const GpuVolumeDraw gpuDraw = gpuVolume && !refinedGpu ? chooseGpuVolumeDraw(o.gpuVolumeDraw, vo)
                                  : refinedGpu             ? GpuVolumeDraw::Refined
                                                           : GpuVolumeDraw::Auto;
    // The refined GPU volume lists its unrefined quads as the indexed way does.
    const bool indexedVolume = gpuDraw == GpuVolumeDraw::Indexed || refinedGpu;
    occupancyValid = false;
    const bool dpsm = point && o.method == ShadowMethod::Dpsm;
    const bool cubeShadowMap = point && !hybrid && !silhouette && !dpsm && o.method != ShadowMethod::None;
    if (cubeShadowMap) {
      TimedPass t(timer, "light");
      cubeShadowPass(o.depthWidth, o.capture);
    }
    if (dpsm) {
      TimedPass t(timer, "light");
      paraboloidPass(o.depthWidth, o.capture, o.paraboloidSubdivision);
    }
    const bool rayDepth =
        hybrid && !givenVolume && o.volume == VolumeSource::Explicit && o.explicitDepth == ExplicitDepth::Rays;
    if (!givenVolume && o.method != ShadowMethod::None && !silhouette && !point && !rayDepth) {
      TimedPass t(timer, "light");
      // The triangle record for the walk (the GPU's rays do not read it).
      lightPass(o.depthWidth, o.depthHeight, o.capture, indexedVolume,
                walkCrossings(o) || (refinedGpu && o.refineCrossings == RefineCrossings::GpuWalk));
    }

    std::size_t explicitTriangles = 0;
    const Texture* volumeDepth = nullptr;
    if (cubeGpu) {
      cubeVolumeDepthPass(o, timer, result);
    } else if (hybrid && !givenVolume && point && !refinedCube) {
      auto t0 = Clock::now();
      const CubeDepthMap cube = rayDepth ? rayCastCube(o.depthWidth, o.capture, vo.depthOracle)
                                         : captureCube(o.depthWidth, o.capture);
      timer.cpu("light", msSince(t0));  // six light passes and their read-backs, or the faces' rays
      t0 = Clock::now();
      VolumeBuildResult built = buildCubeVolume(cube, vo);
      timer.cpu("build", msSince(t0));
      explicitTriangles = useBuiltVolume(std::move(built), o, timer, result);  // z-fail: the cap too
    } else if (hybrid && !givenVolume && o.volume == VolumeSource::Explicit) {
      auto t0 = Clock::now();
      if (rayDepth) {
        result.depthMap = rayCast(o.depthWidth, o.depthHeight, o.capture, vo.depthOracle);
        timer.cpu("light", msSince(t0));
      } else {
        result.depthMap = readBack(o.capture);
        timer.cpu("readback", msSince(t0));
      }
      t0 = Clock::now();
      VolumeBuildResult built = buildVolume(*result.depthMap, walkCrossings(o) ? withWalk(vo) : vo);
      timer.cpu("build", msSince(t0));
      // The cap comes last in the mesh (volume_builder.h): z-pass draws the sheet alone.
      const std::size_t cap = zPassFrame ? built.stats.capTrianglesAfter : 0;
      explicitTriangles = useBuiltVolume(std::move(built), o, timer, result) - cap;
    } else if (silhouette) {
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
      explicitTriangles = built.mesh.triangleCount();
      result.receiversOnly = std::move(built.receiversOnly);
      result.skippedCasters = std::move(built.skipped);
    } else if (givenVolume) {
      const auto t0 = Clock::now();
      uploadVolume(*givenVolume);
      glFinish();
      timer.cpu("upload", msSince(t0));
      explicitTriangles = givenVolume->triangleCount();
    } else if (hybrid && !refinedCube) {
      volumeDepth = gpuVolumeDepth(o, indexedVolume, timer);
      result.biasUsed = vo.bias ? *vo.bias : defaultBias(light, lightW, lightH, o.capture);
      if (refinedGpu) {
        TimedPass t(timer, "crossings");
        findGpuCrossings(vo, result.biasUsed, *volumeDepth, o.refineCrossings, o.capture);
      }
    } else if (o.method != ShadowMethod::None && o.capture == CaptureMode::Midpoint && !point) {
      TimedPass t(timer, "resolve");  // the mean's window depth for the hardware compare
      resolvePass(o.capture);
    }

    if (stencilShadows) {
      // The light frustum's aspect: the depth map's (silhouette has none: the options' size).
      const int frustumW = silhouette ? o.depthWidth : std::max(lightW, 2);
      const int frustumH = silhouette ? o.depthHeight : std::max(lightH, 2);
      if (added) {
        beginAddedLight(cam, false);
      } else {
        TimedPass t(timer, "camera");
        beginCamera(cam, CameraExtra::Ambient);
        setSceneUniforms(cam, o, 0, frustumW, frustumH);
        drawScene();
        SV_GL(glDrawBuffer(GL_COLOR_ATTACHMENT0));  // the volume pass writes no colour
      }
      if (refinedCube) {
        drawRefinedCubeFaces(o, cam, timer, result);
      } else {
        TimedPass t(timer, silhouette ? "silhouette" : "volume");
        beginVolume(zPassFrame);
        if (refinedGpu)
          drawRefinedGpuVolume(cam, vo, result.biasUsed, *volumeDepth, result);
        else if (volumeDepth)
          drawGpuVolume(cam, vo, result.biasUsed, *volumeDepth, gpuDraw, result);
        else if (cubeGpu)
          drawCubeGpuVolume(cam);
        else
          drawExplicitVolume(cam, explicitTriangles, result);
        endVolume();
      }
      {
        TimedPass t(timer, "lighting");
        if (added) addDiffusePass(cam, o, frustumW, frustumH);
        else lightingPass(cam, double(frustumW) / double(frustumH));
      }
    } else {
      TimedPass t(timer, "shade");
      const int taps = o.method == ShadowMethod::ShadowMap || o.method == ShadowMethod::Dpsm ? 1
                       : o.method == ShadowMethod::Pcf3    ? 3
                       : o.method == ShadowMethod::Pcf5    ? 5
                                                           : 0;
      const bool writeVisibility = o.readVisibility && taps > 0;
      if (added) beginAddedLight(cam, writeVisibility);
      else beginCamera(cam, writeVisibility ? CameraExtra::Visibility : CameraExtra::None);
      const int mw = dpsm ? paraboloidFrame.side : taps ? lightW : o.depthWidth;
      const int mh = dpsm ? paraboloidFrame.side : taps ? lightH : o.depthHeight;
      setSceneUniforms(cam, o, taps, mw, mh);
      if (dpsm) setParaboloidUniforms(o);
      sceneProgram.set("writeVisibility", writeVisibility ? 1 : 0);
      if (added) addDiffuseState(false);
      if (taps && !point) bindTexture(2, o.capture == CaptureMode::Midpoint ? resolvedDepth : layer0, shadowSampler);
      if (taps && point && dpsm) bindTexture(2, paraboloid.texture(), shadowSampler);
      if (taps && point && !dpsm) bindCube(3, cubeShadow, shadowSampler);
      drawScene();
      bindTexture(2, Texture(), shadowSampler);
      bindCube(3, Texture(), shadowSampler);
      resetState();
    }
    const VisibilitySource visibility = !o.readVisibility                 ? VisibilitySource::NotRead
                                        : stencilShadows                   ? VisibilitySource::FromStencil
                                        : o.method == ShadowMethod::None   ? VisibilitySource::AllLit
                                                                           : VisibilitySource::FromAttachment;
    readShadowImages(cam, stencilShadows && o.readStencil, visibility, result);
    if (cubeGpu) std::tie(result.volumeTriangles, result.gpuVolumeQuadsDrawn) = cubeVolume.lastCounts();
    if (volumeTrianglesPending) {  // after the frame, so reading the query does not stall a pass
      GLuint64 n = 0;
      SV_GL(glGetQueryObjectui64v(primitivesQuery.id(), GL_QUERY_RESULT, &n));
      result.volumeTriangles = std::size_t(n);
      volumeTrianglesPending = false;
    }
    if (refinedGpu && o.keepVolume) refinedGpuDebugMeshes(cam, o, *volumeDepth, result);
    if (o.readDepthMap && !result.depthMap && !givenVolume && o.method != ShadowMethod::None && !silhouette && !point)
      result.depthMap = readBack(o.capture);
    return result;
  }
};

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

DepthMap Renderer::captureDepth(int width, int height, CaptureMode mode) {
  Impl& s = *impl_;
  s.context.makeCurrent();
  s.requireScene();
  if (s.light.type == LightType::Point)
    throw InputError(s.scene.source, "/light/type", "point",
                     "a point light has six depth maps, one per cube face: capture them with captureCube");
  s.checkSize("Renderer::captureDepth", "width x height", width, height, std::min(s.maxTextureSize, s.maxViewport[0]));
  s.lightPass(width, height, mode, false);
  return s.readBack(mode);
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
  s.checkSize("Renderer::walkSilhouettes", "width x height", width, height, std::min(s.maxTextureSize, s.maxViewport[0]));
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

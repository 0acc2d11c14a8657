// The renderer's state and passes (Renderer::Impl), shared by its source files, one part of a
// frame each: renderer.cpp (context, targets, the public calls), renderer_light.cpp (light passes,
// read-back, ray-cast maps), renderer_camera.cpp (camera, stencil and lighting passes),
// renderer_gpu_volume.cpp (volumes drawn from the depth texture), renderer_explicit.cpp (CPU-built
// volumes, read-back images), renderer_options.cpp (the checks of a frame's options),
// renderer_refined.cpp (the refined GPU volume), renderer_cube.cpp (point lights) and
// renderer_frame.cpp (one frame's passes in order). Internal to shadowvol_gl.
#pragma once

#include "shadowvol/gl/renderer.h"

#include <epoxy/gl.h>

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

#include "cube_gpu_volume.h"
#include "dual_paraboloid_pass.h"
#include "pass_timer.h"
#include "refined_gpu_volume.h"
#include "shadowvol/camera.h"
#include "shadowvol/check.h"
#include "shadowvol/cube_map.h"
#include "shadowvol/cube_volume.h"
#include "shadowvol/depth_blur.h"
#include "shadowvol/dual_paraboloid.h"
#include "shadowvol/error.h"
#include "shadowvol/gl/gl_error.h"
#include "shadowvol/gl/gl_objects.h"
#include "shadowvol/gl/shader_program.h"
#include "shadowvol/light.h"
#include "shadowvol/sheet_depth.h"
#include "shadowvol/silhouette_volume.h"
#include "shadowvol/zpass.h"
#include "silhouette_rays.h"
#include "silhouette_walk.h"

namespace shadowvol::gl {

/// Why a point light's hybrid volume refuses --count zpass (zpass.h decides for one frustum; the
/// cube has six).
inline constexpr const char* kPointZPassRule = "a point light's volume is counted by z-fail only";

inline glm::mat4 toFloat(const glm::dmat4& m) {
  return glm::mat4(m);
}

/// Light projection coefficients (column-major m[col][row]) as the shaders take them.
inline glm::vec4 depthParams(const glm::dmat4& p) {
  return glm::vec4(float(p[2][2]), float(p[3][2]), float(p[2][3]), float(p[3][3]));
}

/// Reversed Z, as every pass of this renderer draws (with glClipControl ZERO_TO_ONE): clip
/// z' = (w - z) / 2 maps GL's NDC z in [-1, 1] to window depth 1 .. 0 (near .. far). Composed in
/// double, so the float matrix holds n / (f - n) and f n / (f - n) without cancellation, and a
/// 32-bit float depth keeps its relative precision at every distance (GL's default convention
/// stores 1 - near/d, where float's spacing near 1 makes the relative error grow as d / near).
inline glm::dmat4 reversedZ(const glm::dmat4& projection) {
  glm::dmat4 reverse(1.0);
  reverse[2][2] = -0.5;
  reverse[3][2] = 0.5;
  return reverse * projection;
}

/// Window depth (reversed Z, 0 = far .. 1 = near) -> view depth (world units), in double (the
/// read-back path; resolve.frag's viewDepth is the float mirror). `p` is reversedZ(projection).
inline double viewDepthFromWindow(const glm::dmat4& p, double window) {
  const double z = (window * p[3][3] - p[3][2]) / (p[2][2] - window * p[2][3]);
  return -z;
}

inline glm::vec3 albedoFor(const SceneObject& o, int& colourIndex) {
  if (o.type == "plane" || o.name == "ground") return {0.85f, 0.85f, 0.80f};
  static const glm::vec3 palette[] = {{0.90f, 0.35f, 0.30f},
                                      {0.30f, 0.55f, 0.90f},
                                      {0.40f, 0.80f, 0.40f},
                                      {0.90f, 0.75f, 0.30f},
                                      {0.70f, 0.45f, 0.85f}};
  return palette[std::size_t(colourIndex++) % 5];
}

inline Texture makeTexture2D(GLenum internalFormat, GLenum format, GLenum type, int w, int h) {
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
inline Framebuffer colourDepthFramebuffer(const Texture& colour, const Texture& depth, const char* what) {
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
inline constexpr int kSceneVertexFloats = int(sizeof(SceneVertex) / sizeof(float));

// The largest map the refined GPU volume takes: a 2048^2 map's index list stays under 512 MiB
// unless more than about 40 % of its quads are refined cells (60 indices each at most; then the
// frame is refused with an InputError); its other buffers hold 68 bytes per texel (flags, work
// lists, crossing records).
constexpr std::int64_t kMaxRefinedGpuTexels = std::int64_t(2048) * 2048;
// The refined GPU cube volume's guard band (guardedCubeFaceLight): each face's map reaches this
// many texels past the face's borders, so that the map's border ring (on the far plane) and the
// blur's reach (2.5 texels) stay outside the face's pyramid (docs/gpu.md). A spot or directional
// light's volume map has a narrower band (kVolumeGuardTexels, light.h).
constexpr int kCubeGuardTexels = 4;

struct Renderer::Impl {
  // Declared first: destroyed last, so every GL object below is deleted with its context current.
  EglContext context;
  ShaderLibrary shaders;
  Program lightProgram, peelProgram, resolveProgram, blurProgram, sceneProgram, ambientOverProgram, volumeProgram;
  Program lightEntryProgram;  // entry capture's first layer (light_entry.frag)
  Program cubeFaceIdProgram, cubeFaceMaskProgram;  // the refined GPU cube volume's face image and masks
  Program volumeGpuProgram;
  Program volumeKeepProgram, volumeGpuKeptProgram;   // GpuVolumeDraw::KeptQuads
  Program volumeMeshProgram, volumeMeshDrawProgram;  // GpuVolumeDraw::ComputeMesh (GL 4.3 only)
  Program volumeIndexProgram, volumeIndexedProgram;  // GpuVolumeDraw::Indexed (GL 4.3 only)
  bool hasCompute = false;
  Texture cubeShadow;  // a point light's shadow-map methods: DEPTH_COMPONENT32F cube map
  int cubeShadowSize = 0;
  Sampler fetchSampler, shadowSampler;
  VertexArray emptyVao;
  std::vector<Query> queryPool;
  Query primitivesQuery;  // GL_PRIMITIVES_GENERATED of the GPU volume's geometry shader
  bool volumeTrianglesPending = false;
  bool zPassFrame = false;              // this frame's volume counted with z-pass: no far cap drawn
  bool volumeReadsWindowDepth = false;  // this frame's GPU volume reads the light pass's depth itself
  GLint maxTextureSize = 0, maxRenderbufferSize = 0;
  GLint maxViewport[2] = {0, 0};

  // Scene
  bool hasScene = false;
  Scene scene;                                   // kept for the silhouette method's connectivity
  std::optional<SilhouetteOccluders> occluders;  // built on the first silhouette frame
  std::vector<Light> lights;                     // the scene's, first to last
  Light light;                                   // the one whose passes run now (lights[0] between frames)
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
  Program lightMarkProgram;  // the light pass that also writes the occupancy bits
  Texture occupancy;         // R32UI, one bit per texel, a word per 8 x 4 texels (light_mark.frag)
  Framebuffer occupancyFbo;  // to clear it
  int occupancyW = 0, occupancyH = 0;
  bool occupancyValid = false;  // this frame's light pass wrote the occupancy bits

  // Refinement by the silhouette walk (GL 4.3 only): the light pass records each texel's triangle
  Program lightTriangleProgram;      // light.vert + light_triangle.frag
  Program lightMarkTriangleProgram;  // both: the refined GPU volume's light pass
  SilhouetteWalk walk;
  SilhouetteRays rays;             // the refined GPU volume's bisection rays (all but RefineCrossings::GpuWalk)
  DualParaboloidPass paraboloid;   // a point light's dual-paraboloid shadow map (ShadowMethod::Dpsm)
  CubeGpuVolume cubeVolume;        // a point light's GPU cube volume (GL 4.3: glCopyImageSubData)
  DualParaboloid paraboloidFrame;  // of the last paraboloid pass
  Bounds3 sceneBounds;             // the scene's (setScene): the paraboloid frame looks at its centre
  Texture triangleIds;             // R32UI, triangle index + 1 (0 = none), at the light targets' size
  Framebuffer layer0IdFbo;         // layer0's depth and triangleIds
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
  Texture ambientImage;                                // RGBA8: the camera pass's ambient term (stencil methods)
  Framebuffer cameraFbo;                               // colour, visibility, ambient image, depth + stencil
  Framebuffer shadowOverFbo;  // colour and depth + stencil only: the lighting pass samples ambientImage
  Texture cubeFaceImage;      // R8UI: the refined GPU cube volume's face per pixel (made on its first frame)
  Framebuffer cubeFaceFbo;    // cubeFaceImage and the camera's depth + stencil
  int cubeFaceW = 0, cubeFaceH = 0;

  Impl(const RendererOptions& options);

  void requireScene() const;

  void checkSize(const char* source, const char* field, int w, int h, int limit) const;
  /// A W x H window's map with a guard band of `guard` texels a side (guardedLight, light.h)
  /// within the GL implementation's limits: InputError naming source and field.
  void checkGuardedSize(const char* source, const char* field, int w, int h, int guard) const;

  // ---- light targets -------------------------------------------------------------------------

  void ensureLightTargets(int w, int h);

  void ensureCameraTargets(int w, int h);

  // ---- passes --------------------------------------------------------------------------------

  // Every pass draws with reversed Z (see reversedZ): glClipControl ZERO_TO_ONE, window depth 1 at
  // the near plane and 0 at the far plane, depth cleared to 0, nearer = GL_GREATER.
  void resetState();

  /// One triangle over the viewport (fullscreen.vert, no vertex buffer).
  void drawFullScreenTriangle();

  void drawScene();
  /// The scene into the bound depth target with `program` (a light program), setting the
  /// occupancy bits of the texels it covers with `markOccupancy` (a light_mark program).
  void drawLightLayer(const Program& program, const glm::dmat4& worldToLightClip, bool markOccupancy);
  /// Entry capture's first layer: the uniforms of its test for faces lit nearly edge-on.
  void setEntryFacingUniforms();

  /// The light's depth into layer0 (and layer1: for midpoint the peeled second surface, for entry
  /// the nearest back face): window depth (reversed Z), cleared to 0. With markOccupancy (the
  /// indexed GPU volume, GL 4.3) the first layer's fragments (entry: the back faces') also set
  /// their bits in `occupancy` (light_mark.frag).
  void lightPass(int w, int h, CaptureMode mode, bool markOccupancy, bool recordTriangles = false);

  /// The triangle record of the light's first layer (light_triangle.frag) at w x h, with its
  /// framebuffer (layer0's depth; call after ensureLightTargets).
  void ensureTriangleIds(int w, int h);

  /// Occupancy of a bw x bh block grid, all bits cleared.
  void clearOccupancy(int bw, int bh);

  void bindCube(int unit, const Texture& tex, const Sampler& sampler);

  void bindTexture(int unit, const Texture& tex, const Sampler& sampler);

  /// layer0 (+ layer1) -> linearDepth (R32F, light-view depth, farPlane = no hit) and
  /// resolvedDepth (window depth of the same, for the shadow maps).
  void resolvePass(CaptureMode mode);

  void blurPass(double blurOffset);

  DepthMap readBack(CaptureMode mode);

  /// The map readBack would return for this light after a w x h light pass, each texel from the
  /// oracle's ray at its centre instead (ExplicitDepth::Rays; no GL call).
  DepthMap rayCast(int w, int h, CaptureMode mode, const DepthOracle& oracle) const;

  /// A point light's six faces as captureCube's, each from the oracle's rays.
  CubeDepthMap rayCastCube(int n, CaptureMode mode, const DepthOracle& oracle) const;

  struct CameraSetup {
    glm::dmat4 view, proj;
    int w, h;
  };

  CameraSetup cameraSetup(const RenderOptions& o) const;

  /// Uniforms of sceneProgram shared by every mode.
  void setSceneUniforms(const CameraSetup& cam, const RenderOptions& o, int shadowTaps, int mapW, int mapH);

  /// The shade pass's uniforms for the dual-paraboloid maps of the last paraboloidPass, after
  /// setSceneUniforms: the maps' size, the frame, the coarsest texel's angle (4 / side at a map's
  /// centre) as the footprint, and dualParaboloidDefaultBias.
  void setParaboloidUniforms(const RenderOptions& o);

  /// What the camera pass writes besides the colour (COLOR_ATTACHMENT0).
  enum class CameraExtra { None, Visibility, Ambient };

  /// Binds and clears the camera targets. Visibility: the shade pass also writes the shadow test
  /// into COLOR_ATTACHMENT1 (cleared to 1 = lit). Ambient: the stencil methods' camera pass also
  /// writes the ambient term into ambientImage (COLOR_ATTACHMENT2, cleared to the background, so
  /// the lighting pass leaves the background as it is).
  void beginCamera(const CameraSetup& cam, CameraExtra extra = CameraExtra::None);

  /// Volume state: two-sided, wrap; colour and depth writes off. z-fail: back faces behind the
  /// surface (failing the reversed-Z GREATER test) add one, front faces subtract one, with depth
  /// clamp on so that the far cap is never clipped. z-pass: front faces in front of the surface
  /// add one, back faces subtract one, clipped at the near plane as usual. A face exactly at the
  /// surface's depth counts as behind in both, so where both are right they agree exactly.
  void beginVolume(bool zPass);

  void endVolume();

  /// The image rectangle (x, y, width, height; GL window coordinates) that holds the light
  /// frustum's projection, `aspect` the frustum's as in the camera pass; the whole image when a
  /// corner lies on or behind the camera's eye plane. Outside the frustum lit = 0 (scene.frag), so
  /// the lit colour there is the ambient term already.
  std::array<GLint, 4> lightFrustumOnImage(const CameraSetup& cam, double aspect) const;

  /// A further light's start (render()): the camera's colour and depth kept, the stencil cleared
  /// for its volume, and with `visibility` its shadow test's attachment cleared to lit.
  void beginAddedLight(const CameraSetup& cam, bool visibility);

  /// State of a further light's shade draw: the scene again at the depth the camera pass left
  /// (GL_EQUAL: the same program and vertices give the same depth), its colour added to the
  /// image (the shadow test's attachment written, not added), and with `stencilLit` only where
  /// this light's stencil is 0. The caller sets ambient 0 after setSceneUniforms.
  void addDiffuseState(bool stencilLit);

  /// A further light's diffuse term where its stencil is 0 (stencil methods), scissored to its
  /// frustum's rectangle on the image (lightFrustumOnImage): outside it the light adds nothing.
  void addDiffusePass(const CameraSetup& cam, const RenderOptions& o, int frustumW, int frustumH);

  /// The ambient term over the lit colour where stencil != 0: one full-screen triangle instead of
  /// drawing the scene again (docs/gpu.md "Passes of one frame"), scissored to the light
  /// frustum's rectangle on the image (lightFrustumOnImage).
  void lightingPass(const CameraSetup& cam, double frustumAspect);

  /// Uniforms of volume_common.glsl (both GPU-volume programs).
  void setVolumeUniforms(const Program& p, const VolumeBuildOptions& vo, double bias);

  /// The way the GPU volume will be drawn (before the fallbacks for sizes, drawGpuVolume):
  /// Auto is Indexed where GL 4.3 is there, else KeptQuads (the fastest measured on llvmpipe,
  /// docs/gpu.md); nothing is skipped with the quad cap.
  GpuVolumeDraw chooseGpuVolumeDraw(GpuVolumeDraw how, const VolumeBuildOptions& vo) const;

  /// `how`: chooseGpuVolumeDraw's choice for this frame (made before the light pass, which marks
  /// the occupancy bits for Indexed); here it may still fall back for sizes.
  void drawGpuVolume(const CameraSetup& cam, const VolumeBuildOptions& vo, double bias, const Texture& depth,
                     GpuVolumeDraw how, RenderResult& result);

  /// The GPU volume built by a compute pass (volume_mesh.comp) as a light-view triangle list, then
  /// drawn with a plain vertex shader. The buffer grows to what the frame needs (the count is read
  /// back after the pass; a frame that overflows it runs the pass again) up to kMaxMeshBytes;
  /// false when the mesh would be larger (the caller falls back to KeptQuads).
  bool drawComputedGpuVolume(const glm::dmat4& lightViewToClip, const VolumeBuildOptions& vo, double bias,
                             const Texture& depth, std::int64_t quads, RenderResult& result);

  /// The GPU volume as an indexed triangle list: volume_index.frag (one fragment per block of
  /// quads, a framebuffer without attachments) appends the kept quads' triangles as texel indices,
  /// volume_index.vert places each texel's vertex. The buffer grows to what the frame needs (the
  /// count is read back after the pass; a frame that overflows it runs the pass again) up to
  /// kMaxIndexBytes; false when the list would be larger (the caller falls back to KeptQuads).
  /// With `cells` the refined GPU volume: its cells in the same list, volume_refined.vert draws all.
  bool drawIndexedGpuVolume(const CameraSetup& cam, const glm::dmat4& lightViewToClip, const VolumeBuildOptions& vo,
                            double bias, const Texture& depth, std::int64_t quads, RenderResult& result,
                            RefinedGpuVolume* cells = nullptr);

  /// drawIndexedGpuVolume's listing pass alone: `counts` = indices, quads; false when the list
  /// would not fit. With `cells` (the refined GPU volume) its refined cells are listed first into
  /// the same buffer and the listing pass leaves their quads out.
  bool listIndexedGpuVolume(const CameraSetup& cam, const VolumeBuildOptions& vo, double bias, const Texture& depth,
                            std::int64_t quads, std::array<GLuint, 2>& counts, RefinedGpuVolume* cells = nullptr);

  /// The first `count` indices of the indexed volume's buffer (the refined GPU volume's debug path).
  std::vector<std::uint32_t> readIndexList(GLuint count);

  /// The refined GPU volume's boundary edges and crossings for this frame's map (`depth`: the
  /// final sheet depths; with blur the unblurred are linearDepth): by the walk for
  /// RefineCrossings::GpuWalk, else by bisection rays on the GPU (vo.refineSteps per edge,
  /// `capture`'s rule).
  void findGpuCrossings(const VolumeBuildOptions& vo, double bias, const Texture& depth, RefineCrossings crossings,
                        CaptureMode capture);

  /// The refined GPU volume: its refined cells (volume_refined.comp) and the other quads as the
  /// indexed way lists them (volume_index.frag with skipRefined), one list, one draw.
  void drawRefinedGpuVolume(const CameraSetup& cam, const VolumeBuildOptions& vo, double bias, const Texture& depth,
                            RenderResult& result);

  /// The crossings of the last refined GPU frame, read back, as the CPU builder's crossing source
  /// (refinementFromGpuRecords).
  CrossingSource gpuCrossingSource();

  void growIndices(std::int64_t indices);

  void growMesh(std::int64_t vertices);

  /// The GPU volume in two passes: volume_keep.geom writes the indices of the quads that are not
  /// all on the far plane (transform feedback, rasteriser off), then volume_gpu.geom expands only
  /// those. Same triangles as the direct draw, in the same quad order.
  void drawCompactGpuVolume(const glm::dmat4& lightViewToClip, const VolumeBuildOptions& vo, double bias,
                            const Texture& depth, std::int64_t quads, RenderResult& result);

  void uploadVolume(const VolumeMesh& volume);

  void drawExplicitVolume(const CameraSetup& cam, std::size_t triangles, RenderResult& result);

  /// Stencil counts (when `stencil`), and the visibility mask: from the stencil (`visibility` ==
  /// FromStencil), from COLOR_ATTACHMENT1 (FromAttachment), or all lit (AllLit).
  enum class VisibilitySource { NotRead, FromStencil, FromAttachment, AllLit };

  /// GL row 0 is the bottom; images start at the top. Flips `rows` rows of `rowBytes` in place.
  static void flipRows(std::vector<std::uint8_t>& image, std::size_t rowBytes, int rows);

  // Read straight into the result's vectors and flipped in place, without the staging copies of
  // the colour and visibility images (the stencil counts still go through one vector).
  /// The frame's colour (after every light's passes).
  void readColour(const CameraSetup& cam, RenderResult& r);

  /// One light's stencil counts and shadow test, read before the next light's passes.
  void readShadowImages(const CameraSetup& cam, bool stencil, VisibilitySource visibility, RenderResult& r);

  /// What a point light's frame can be (docs/gpu.md "Point lights"): the explicit cube volume
  /// (hybrid, explicit; refined by rays alone), the GPU cube volume (hybrid, gpu; GL 4.3; refined:
  /// six face volumes, drawRefinedCubeFaces, with the refined GPU volume's rules of validate()),
  /// silhouette volumes, a cube shadow map (GL 4.3), dual-paraboloid maps or no shadows.
  void validatePointLight(const RenderOptions& o) const;

  /// What the GPU cube volume (cube_gpu_volume.h) takes beyond the explicit one: GL 4.3 and its two
  /// ways of drawing.
  void validateGpuCubeVolume(const RenderOptions& o) const;

  /// Given depth offsets that would leave nothing in shadow under this light (offsetEmptiesRange,
  /// sheet_depth.h): the volume's bias (plus the blur offset with blur), a one-map shadow map's
  /// constant bias.
  void checkOffsetRanges(const RenderOptions& o) const;

  void validate(const RenderOptions& o, const CameraSetup& cam) const;

  /// This frame draws the refined GPU volume (refined_gpu_volume.h).
  static bool refinedGpuVolume(const RenderOptions& o);

  /// This frame refines its explicit volume with the GPU's silhouette walk.
  static bool walkCrossings(const RenderOptions& o);

  /// The volume options with the silhouette walk as the crossing source, reading this frame's
  /// light pass (its triangle record) and the scene's buffers.
  VolumeBuildOptions withWalk(const VolumeBuildOptions& vo);

  /// What the walk reads after a light pass that recorded its triangles; sets its uniforms.
  WalkInputs walkInputs();

  /// The refined GPU volume's debug read-back of the map just drawn (`volumeDepth` its final sheet
  /// depths): the map (result.depthMap), the CPU mesh from the GPU's crossings (result.volume and
  /// volumeStats) and the GPU's own triangles placed in double (result.gpuVolume).
  void refinedGpuDebugMeshes(const CameraSetup& cam, const RenderOptions& o, const Texture& volumeDepth,
                             RenderResult& result);

  /// The GPU volume's input depths for this frame's light pass: the light pass's window depth
  /// where the indexed volume converts the few texels it reads itself, else the resolved depth
  /// (timed as `resolve`); with blur the blurred (timed as `blur`). Midpoint and blur need the
  /// resolved depth (docs/gpu.md).
  const Texture* gpuVolumeDepth(const RenderOptions& o, bool indexedVolume, PassTimer& timer);

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
  void drawRefinedCubeFaces(const RenderOptions& o, const CameraSetup& cam, PassTimer& timer, RenderResult& result);

  /// The face image of a point light at `lightPosition`: for each pixel, the cube face its surface
  /// point (the camera pass's depth, GL_EQUAL) lies on (cube_face_id.frag, cubeLookup's rule); 255
  /// on the background. One scene pass per light, read by the six masks.
  void writeCubeFaceImage(const CameraSetup& cam, const glm::dvec3& lightPosition);

  /// Stencil bit 7 set on the pixels of the face image (writeCubeFaceImage) that lie on another
  /// cube face than `face` or on the background, clear elsewhere; colour, depth and bits 0-6 kept.
  void maskOtherCubeFaces(const CameraSetup& cam, int face);

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
  CubeDepthMap captureCube(int n, CaptureMode mode);

  /// The GPU cube volume's input (cube_gpu_volume.h): each face's light pass, resolved (and with
  /// blur blurred) and copied into the cube volume's layer, all timed as `light`; then its
  /// triangles listed (timed as `list`). With keepVolume each face is also read back and the
  /// explicit cube volume built from the six maps with the same options (result.volume: the CPU
  /// mirror that validation counts the crossings of; the GPU draws the same surface, its cap
  /// triangulated otherwise).
  void cubeVolumeDepthPass(const RenderOptions& o, PassTimer& timer, RenderResult& result);

  /// The GPU cube volume of the faces cubeVolumeDepthPass stored and listed (stencil state set);
  /// its counts are read after the frame (cubeVolume.lastCounts).
  void drawCubeGpuVolume(const CameraSetup& cam);

  /// A point light's cube shadow map: the light pass of each face's spot light (and for midpoint
  /// the mean's window depth, resolvePass), copied into face f of the cube texture, whose texel
  /// order is the faces' (cube_map.h), so samplerCubeShadow looks up the texel the face's
  /// map has. Window depth as the 2D shadow map's; the same projection for all six faces.
  void cubeShadowPass(int n, CaptureMode mode);

  /// A point light's dual-paraboloid maps for a cube face side of n (dual_paraboloid.h).
  void paraboloidPass(int n, CaptureMode mode, int subdivision);

  /// Z-pass for this frame: hybrid volumes built from the depth map only, where zPassSafety allows.
  bool chooseZPass(const RenderOptions& o, const CameraSetup& cam, bool givenVolume, RenderResult& result) const;

  /// A CPU-built volume into the frame: its stats and bias into `result`, uploaded (timed as
  /// `upload`), kept when the options ask; returns the triangles to draw: all, or with `leftOut` >
  /// 0 all but the first part's last `leftOut` (a z-pass frame's far cap), the later parts (the face
  /// prisms) uploaded before them and the kept mesh as built.
  std::size_t useBuiltVolume(VolumeBuildResult&& built, const RenderOptions& o, PassTimer& timer, RenderResult& result,
                             std::size_t leftOut = 0);

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
  RenderResult render(const RenderOptions& o, const VolumeMesh* givenVolume);

  /// validate() for light k (the renderer's light now), its errors naming the light.
  void validateForLight(const RenderOptions& o, const CameraSetup& cam, std::size_t k) const;

  /// What one light's passes are, decided from the options (planLightFrame), and what the volume
  /// stage leaves for the stencil stage.
  struct LightFrame {
    bool given = false;           // a caller-built volume (renderWithVolume)
    bool silhouette = false;      // ShadowMethod::Silhouette
    bool hybrid = false;          // the depth-map volume, or a given one
    bool stencilShadows = false;  // hybrid or silhouette: a volume counted in the stencil
    bool point = false;           // a point light
    bool gpuVolume = false;       // a spot or directional light's volume drawn from the depth texture
    bool cubeGpu = false;         // a point light's GPU cube volume
    bool refinedCube = false;     // a point light's refined GPU face volumes
    bool refinedGpu = false;      // the refined GPU volume
    bool indexedVolume = false;   // its light pass marks occupancy (indexed or refined GPU volume)
    bool dpsm = false;            // a point light's dual-paraboloid maps
    bool cubeShadowMap = false;   // a point light's cube shadow map (or PCF)
    bool rayDepth = false;        // the explicit volume's map from the oracle's rays (ExplicitDepth::Rays, or Auto's pick)
    bool guarded = false;         // a spot or directional light's own volume: its map has a guard band (guardedFrame)
    GpuVolumeDraw gpuDraw = GpuVolumeDraw::Auto;
    std::size_t explicitTriangles = 0;     // of an uploaded volume (drawExplicitVolume)
    const Texture* volumeDepth = nullptr;  // what a GPU volume reads (gpuVolumeDepth)
  };

  LightFrame planLightFrame(const RenderOptions& o, bool givenVolume) const;

  /// What the light's depth passes, the volume's input and its draw use: for a guarded frame
  /// (LightFrame::guarded) the light widened by kVolumeGuardTexels texels a side and the options'
  /// depth size grown by as many (guardedLight, light.h), so the map's far-plane ring and blur
  /// reach lie outside the light's window; otherwise the light and options as given. The camera
  /// and lighting passes keep the given light's window.
  struct MapFrame {
    Light light;
    RenderOptions options;
  };
  MapFrame mapFrame(const RenderOptions& o, const LightFrame& f) const;

  /// The light's depth passes this frame needs: the cube shadow map, the dual-paraboloid maps, or
  /// the light pass (none for a ray-cast map, the silhouette method or a given volume).
  void lightDepthPasses(const RenderOptions& o, const LightFrame& f, PassTimer& timer);

  /// A point light's explicit cube volume: six maps (light passes or rays), built and uploaded;
  /// returns its triangle count.
  std::size_t explicitCubeVolume(const RenderOptions& o, const LightFrame& f, PassTimer& timer, RenderResult& result);

  /// The explicit volume: the map read back (or ray-cast), built and uploaded; returns the
  /// triangles to draw (the sheet alone with z-pass).
  std::size_t explicitVolume(const RenderOptions& o, const LightFrame& f, PassTimer& timer, RenderResult& result);

  /// The silhouette volume of the scene's closed objects, built and uploaded; returns its triangles.
  std::size_t silhouetteVolume(PassTimer& timer, RenderResult& result);

  /// The volume's input after the depth passes: built and uploaded on the CPU, or the GPU volume's
  /// depth texture and crossings, or (shadow maps, midpoint) the resolved depth.
  void volumeInput(const RenderOptions& o, LightFrame& f, const VolumeMesh* givenVolume, PassTimer& timer,
                   RenderResult& result);

  /// The stencil methods' passes: the camera pass (the first light), the volume into the
  /// stencil, and the lighting (or a further light's diffuse) pass. The renderer's light is the
  /// given one; the volume is drawn with `map`'s (mapFrame).
  void stencilPasses(const RenderOptions& o, const MapFrame& map, const CameraSetup& cam, const LightFrame& f,
                     PassTimer& timer, bool added, RenderResult& result);

  /// The shadow-map methods' one shade pass (and none: no shadow test).
  void shadeWithMap(const RenderOptions& o, const CameraSetup& cam, const LightFrame& f, PassTimer& timer, bool added);

  /// After the light's passes: the images and counts the options ask for.
  void lightFrameResults(const RenderOptions& o, const CameraSetup& cam, const LightFrame& f, RenderResult& result);

  /// The passes of the renderer's light. `added`: a further light of the frame (render()): no
  /// camera pass, its diffuse term added to the image.
  RenderResult renderLight(const RenderOptions& o, const CameraSetup& cam, const VolumeMesh* givenVolume,
                           PassTimer& timer, bool added);
};

}  // namespace shadowvol::gl

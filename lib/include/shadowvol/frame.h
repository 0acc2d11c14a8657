// What one frame of a shadow method is asked to do and what it returns, independent of the
// backend that draws it (gl/renderer.h, the OpenGL renderer, is the one backend today; its
// header keeps these names in shadowvol::gl too). Option values are checked by the backend, which
// throws InputError naming RenderOptions and the member.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "shadowvol/capture_choice.h"
#include "shadowvol/depth_map.h"
#include "shadowvol/enum_names.h"
#include "shadowvol/volume_builder.h"

namespace shadowvol {

enum class ShadowMethod {
  Hybrid,     ///< the shadow volume from the depth map, stencil z-fail (the project's method)
  ShadowMap,  ///< plain shadow mapping, hardware depth compare, one nearest tap
  Pcf3,       ///< percentage-closer filtering over 3 x 3 texels
  Pcf5,       ///< percentage-closer filtering over 5 x 5 texels
  None,       ///< no shadows (the frustum still limits the light)
  Silhouette, ///< classic silhouette shadow volumes (silhouette_volume.h): closed 2-manifold objects
              ///< cast, open sheets only receive (RenderResult::receiversOnly), anything else is an
              ///< InputError naming the object; exact for the casters; stencil z-fail like hybrid
  Dpsm,       ///< a point light's dual-paraboloid shadow map (dual_paraboloid.h): two maps of
              ///< dualParaboloidSide(depthWidth)^2 texels, the cube map's texel count; one tap
};
inline constexpr EnumNames<ShadowMethod, 7> kShadowMethodNames{
    {{ShadowMethod::Hybrid, "hybrid"}, {ShadowMethod::ShadowMap, "shadowmap"}, {ShadowMethod::Pcf3, "pcf3"},
     {ShadowMethod::Pcf5, "pcf5"}, {ShadowMethod::Silhouette, "silhouette"}, {ShadowMethod::Dpsm, "dpsm"},
     {ShadowMethod::None, "none"}}};
const char* toString(ShadowMethod m);
bool parseShadowMethod(const std::string& text, ShadowMethod& m);
/// Whether `m` draws a shadow volume into the stencil (hybrid, silhouette): the methods whose
/// results name a volume count (z-pass or z-fail); the maps and none draw none.
constexpr bool drawsShadowVolume(ShadowMethod m) { return m == ShadowMethod::Hybrid || m == ShadowMethod::Silhouette; }

enum class VolumeSource {
  Gpu,       ///< drawn straight from the depth texture, no read-back (production default)
  Explicit,  ///< depth read back, buildVolume() on the CPU, the mesh uploaded each frame
};
inline constexpr EnumNames<VolumeSource, 2> kVolumeSourceNames{
    {{VolumeSource::Gpu, "gpu"}, {VolumeSource::Explicit, "explicit"}}};
const char* toString(VolumeSource v);
bool parseVolumeSource(const std::string& text, VolumeSource& v);

/// How the stencil counts the hybrid volume (docs/gpu.md "Z-pass where it is safe").
enum class VolumeCount {
  Auto,   ///< z-pass without the far cap where zPassSafety (zpass.h) says so, else z-fail
  ZFail,  ///< z-fail with the far cap: right wherever the camera is (the depth clamp keeps the cap)
  ZPass,  ///< z-pass without the far cap; an InputError naming the reason where it is not safe
};
/// As reports name them (toString) and as options spell them (parseVolumeCount, the command line's
/// --count, the Python module's count).
inline constexpr EnumNames<VolumeCount, 3> kVolumeCountNames{
    {{VolumeCount::Auto, "auto"}, {VolumeCount::ZFail, "z-fail"}, {VolumeCount::ZPass, "z-pass"}}};
inline constexpr EnumNames<VolumeCount, 3> kVolumeCountOptionNames{
    {{VolumeCount::Auto, "auto"}, {VolumeCount::ZFail, "zfail"}, {VolumeCount::ZPass, "zpass"}}};
const char* toString(VolumeCount c);  ///< kVolumeCountNames
bool parseVolumeCount(const std::string& text, VolumeCount& c);  ///< kVolumeCountOptionNames

enum class TimingMethod {
  GpuTimer,   ///< GL_TIME_ELAPSED queries, one per pass (hardware drivers)
  WallClock,  ///< glFinish before and after each pass, steady_clock in between (no timer queries,
              ///< a software rasteriser such as llvmpipe, or RenderOptions::forceWallClock)
};
inline constexpr EnumNames<TimingMethod, 2> kTimingMethodNames{
    {{TimingMethod::GpuTimer, "gpu-timer-query"}, {TimingMethod::WallClock, "wall-clock-glfinish"}}};
const char* toString(TimingMethod t);

/// How the GPU volume is drawn. With the exact cap, quads whose four corners lie on the far plane
/// contribute nothing and can be skipped; with the quad cap every quad's sheet is needed. A point
/// light's GPU cube volume takes Auto or Indexed (a compute pass lists its cells' triangles, GL
/// 4.3) and AllQuads (one point per cell through a geometry shader); cube_gpu_volume.h.
enum class GpuVolumeDraw {
  Auto,         ///< Indexed with GL 4.3 (the fastest measured on llvmpipe), else KeptQuads;
                ///< AllQuads with the quad cap
  Indexed,      ///< the light pass marks the texels it covers, a fragment pass lists the kept
                ///< quads' triangles as texel indices, a vertex shader places each texel's vertex
                ///< (GL 4.3; falls back to KeptQuads past 512 MiB of indices); InputError without 4.3
  ComputeMesh,  ///< a compute pass writes the kept quads' triangles into a buffer, drawn as a plain
                ///< list (GL 4.3; falls back to KeptQuads past a 512 MiB mesh); InputError without 4.3
  KeptQuads,    ///< a transform-feedback pass lists the kept quads, the geometry shader expands them (GL 3.3)
  AllQuads,     ///< one point per quad through the geometry shader, none skipped (the first version)
  Refined,      ///< not a choice: what RenderResult::gpuVolumeDrawUsed says of a refined GPU volume
                ///< (volumeOptions.refineSteps > 0: compute passes list its triangles, GL 4.3)
};
inline constexpr EnumNames<GpuVolumeDraw, 6> kGpuVolumeDrawNames{
    {{GpuVolumeDraw::Auto, "auto"}, {GpuVolumeDraw::Indexed, "indexed"}, {GpuVolumeDraw::KeptQuads, "kept-quads"},
     {GpuVolumeDraw::ComputeMesh, "compute-mesh"}, {GpuVolumeDraw::AllQuads, "all-quads"},
     {GpuVolumeDraw::Refined, "refined"}}};
const char* toString(GpuVolumeDraw d);
/// Parses a choice of kGpuVolumeDrawNames: every name but "refined" (not a choice); false for
/// anything else.
bool parseGpuVolumeDraw(const std::string& text, GpuVolumeDraw& d);

/// Where refinement finds its crossings (volumeOptions.refineSteps > 0). The explicit volume takes
/// Rays or GpuWalk; the refined GPU volume (docs/gpu.md "The refined GPU volume") takes GpuWalk,
/// or its own rays for Rays (the default) and GpuRays alike.
enum class RefineCrossings {
  Rays,     ///< bisection rays from volumeOptions.depthOracle (Embree), refineSteps per edge
  GpuWalk,  ///< the GPU's silhouette walk over the scene's triangles (walk_crossings.h,
            ///< docs/gpu.md "Crossings from a triangle walk"): exact crossings without rays; needs
            ///< GL 4.3, refineSteps > 0 only switches it on; not with chord points or the sub-grid
  GpuRays,  ///< the refined GPU volume only: the same bisection as Rays, refineSteps rays per edge,
            ///< each cast on the GPU through a hierarchy of the scene's triangles (triangle_bvh.h,
            ///< docs/gpu.md "Crossings from GPU rays"); back, front or entry capture
};
inline constexpr EnumNames<RefineCrossings, 3> kRefineCrossingsNames{
    {{RefineCrossings::Rays, "rays"}, {RefineCrossings::GpuWalk, "gpu-walk"}, {RefineCrossings::GpuRays, "gpu-rays"}}};
const char* toString(RefineCrossings c);
bool parseRefineCrossings(const std::string& text, RefineCrossings& c);

/// Where the explicit volume's depth map comes from (hybrid, VolumeSource::Explicit, any light).
/// LightPass: the GPU's light pass, read back. Rays: one ray per texel centre from
/// volumeOptions.depthOracle (Embree: the same rule as captureDepthEmbree, so the map is the one
/// the refinement's rays see), on the CPU, no light pass and no read-back; its time is the frame's
/// "light" pass (wall clock). Which is faster depends on the machine: on llvmpipe a small map's
/// rays cost less than rasterising every triangle once more (README "Silhouette refinement").
/// Auto: chooseExplicitDepth's pick, frame by frame (the command line's and bench's default).
enum class ExplicitDepth {
  LightPass,  ///< the GPU's light pass, read back (the library's default)
  Rays,       ///< volumeOptions.depthOracle at every texel centre
  Auto,       ///< Rays where chooseExplicitDepth expects them to cost less, else LightPass
};
inline constexpr EnumNames<ExplicitDepth, 3> kExplicitDepthNames{
    {{ExplicitDepth::Auto, "auto"}, {ExplicitDepth::LightPass, "gpu"}, {ExplicitDepth::Rays, "rays"}}};
const char* toString(ExplicitDepth d);
bool parseExplicitDepth(const std::string& text, ExplicitDepth& d);

struct RenderOptions {
  ShadowMethod method = ShadowMethod::Hybrid;  ///< the project's method by default
  VolumeSource volume = VolumeSource::Gpu;     ///< hybrid only; gpu is the production path
  int depthWidth = 256;                        ///< light depth map texels over the light's window (> 1); a
                                               ///< spot or directional volume's map has a guard band of
  int depthHeight = 256;                       ///< kVolumeGuardTexels more a side (light.h): (W + 4) x (H + 4)
  CaptureMode capture = CaptureMode::Back;     ///< back faces: no self-shadow acne on lit faces
  VolumeBuildOptions volumeOptions;            ///< hybrid: triangulation, blur, blurOffset, bias,
                                               ///< cap (flattenCap, depthOracle, chord points and the
                                               ///< sub-grid apply to explicit only; refineSteps > 0
                                               ///< refines the GPU volume by the walk: GL 4.3, back
                                               ///< or front capture, the exact cap)
  int imageWidth = 0;                          ///< camera image pixels; 0 = scene camera's width
  int imageHeight = 0;                         ///< camera image pixels; 0 = scene camera's height
  double ambient = 0.2;                        ///< ambient factor of the albedo
  double diffuse = 0.8;                        ///< diffuse factor of the albedo
  std::optional<double> shadowBiasConstant;    ///< shadow maps: world units subtracted from the
                                               ///< receiver's light-view depth before the compare;
                                               ///< unset = defaultBias(light, W, H, capture), the
                                               ///< volume's default (0 for back and midpoint)
  double shadowBiasSlope = 1.0;                ///< shadow maps: + this x texel footprint (world
                                               ///< units at the receiver) x tan(angle between the
                                               ///< normal and the light axis), tan clamped to 10
  int paraboloidSubdivision = 1;               ///< dpsm: each triangle cut into up to s x s (1, 2,
                                               ///< 4 or 8) in its light pass, so none spans more
                                               ///< than kParaboloidSubdivisionAngle; 1 = the
                                               ///< tutorial's pass (docs/gpu.md)
  bool readStencil = true;                     ///< hybrid, silhouette: read the stencil counts back
  bool readDepthMap = false;                   ///< read the light depth back into the result
  bool readVisibility = false;                 ///< fill RenderResult::visibility (the method's own
                                               ///< shadow test per pixel); off = no extra cost
  bool keepVolume = false;                     ///< explicit volume: return the mesh drawn (RenderResult::volume);
                                               ///< refined GPU volume: the CPU builder's mesh from the
                                               ///< GPU's own boundary edges and crossings, and the
                                               ///< GPU's triangles (RenderResult::gpuVolume; debug read-backs);
                                               ///< GPU cube volume: the explicit cube volume of the six
                                               ///< faces read back (its CPU mirror)
  bool forceWallClock = false;                 ///< time with glFinish even if timer queries exist
  /// hybrid/gpu: how the volume is drawn from the depth texture (docs/gpu.md "Skipping the far
  /// quads"). All give the same stencil. The refined GPU volume (refineSteps > 0) takes only Auto.
  GpuVolumeDraw gpuVolumeDraw = GpuVolumeDraw::Auto;
  /// hybrid (gpu and explicit volumes): z-pass without the far cap where it is safe, or z-fail.
  /// Silhouette volumes and renderWithVolume always use z-fail.
  VolumeCount volumeCount = VolumeCount::Auto;
  /// hybrid with refinement: where the crossings come from (RefineCrossings: the explicit volume takes
  /// Embree's rays or the walk, the GPU volume its own rays or the walk).
  RefineCrossings refineCrossings = RefineCrossings::Rays;
  /// hybrid with the explicit volume: its depth map from the GPU's light pass or from the depth
  /// oracle's rays (ExplicitDepth; Rays needs volumeOptions.depthOracle).
  ExplicitDepth explicitDepth = ExplicitDepth::LightPass;
};

/// What a frame with these options uses its depth map for (capture_choice.h; `--capture auto`
/// decides by it): a hybrid volume's sheet, refined when volumeOptions.refineSteps > 0, unless the
/// GPU's silhouette walk follows its one layer; dual-paraboloid maps are one layer too; every other
/// method compares depths as a shadow map.
CaptureUse captureUse(const RenderOptions& o);

/// ExplicitDepth::Auto takes the rays when the scene has at least this many triangles per texel of
/// the map (a point light's six faces counted) and the rasteriser is a software one. Measured on
/// llvmpipe, 2 cores (README "Depth map from rays", docs/results/sweep-raycast): the rays cost
/// about 0.05-0.1 us each, the light pass about 0.1 us per triangle, so they break even near one
/// triangle per texel; below 0.75 the light pass won every measured cell but one, above 1.25 the
/// rays won every one.
inline constexpr double kRayDepthTrianglesPerTexel = 0.75;

/// The depth source a frame with these options takes: explicitDepth itself unless Auto. Auto is
/// Rays when the frame can cast them at no extra set-up (hybrid, explicit volume,
/// volumeOptions.depthOracle already given, as refinement's rays need it; not the GPU walk's
/// crossings, which follow the light pass's triangle record), the rasteriser is a software one
/// (`softwareRasterizer`: its light pass costs per triangle; a hardware GPU's is nearly free), and
/// sceneTriangles >= kRayDepthTrianglesPerTexel x texels, with `faces` maps of the options' size
/// (6 for a point light). Otherwise LightPass. Deterministic: no timing is involved.
ExplicitDepth chooseExplicitDepth(const RenderOptions& o, std::size_t sceneTriangles, bool softwareRasterizer,
                                  int faces = 1);

/// Whether a frame with these options needs volumeOptions.depthOracle (the scene's rays): the
/// explicit hybrid volume refined with RefineCrossings::Rays, or with its depth from rays.
bool needsDepthOracle(const RenderOptions& o);

struct PassTime {
  std::string name;  ///< light, resolve, blur, crossings (refined GPU volume: boundary edges and the walk),
                     ///< readback, build, upload, camera, volume, lighting, shade;
                     ///< silhouette: connectivity (first frame only), build, upload, camera,
                     ///< silhouette, lighting; with ExplicitDepth::Rays "light" is the CPU's
                     ///< rays and there is no readback
  double ms = 0.0;   ///< GPU time (timer query) or wall clock, see RenderResult::timing; CPU
                     ///< passes (readback, build, upload, the rays' light) are always wall clock
};

/// One frame's passes with each name once, in the order the names first ran: a pass that runs
/// several times in a frame (a point light's per cube face) counts with the sum of its times.
std::vector<PassTime> passTotals(const std::vector<PassTime>& passes);

struct RenderResult {
  int width = 0, height = 0;          ///< image pixels
  std::vector<std::uint8_t> rgba;     ///< width * height * 4, RGBA8, rows top first
  std::vector<std::uint8_t> stencil;  ///< width * height stencil counts (8-bit, wrapping),
                                      ///< rows top first; empty unless hybrid or silhouette,
                                      ///< and readStencil
  int stencilBits = 8;                ///< the bits of `stencil` that count: 7 for the refined GPU
                                      ///< cube volume (counts modulo 128; its bit 7 masks the faces)
  /// The method's own shadow test per pixel when RenderOptions::readVisibility, else empty:
  /// width * height bytes, rows top first, 255 = lit by the test, 0 = shadowed. Only the shadow
  /// test: not multiplied by N.L nor by the light frustum.
  ///   shadowmap, pcf3, pcf5: round(255 * fraction of the taps that pass), written by the shade
  ///     pass into a second colour attachment (R8); 255 outside the light frustum (the test is
  ///     not evaluated there) and on the background (cleared to 255). Faces turned away from the
  ///     light get the test's answer like any other pixel.
  ///   hybrid, silhouette (and renderWithVolume): 255 where stencil == 0, else 0, from the stencil read-back
  ///     (no GL pass). Background pixels carry whatever the stencil holds there (not meaningful),
  ///     and so do pixels outside the light's frustum in a z-pass frame (volumeCountUsed), and in
  ///     any hybrid frame of a spot or directional light those just outside it (the volume's map
  ///     reaches its guard band past the window, light.h): the lighting ignores both. The stencil
  ///     and its counts (stencil.png, render's "stencil pixels != 0") include them.
  ///   none: 255 everywhere.
  std::vector<std::uint8_t> visibility;
  std::optional<DepthMap> depthMap;   ///< light depth (read back) when readDepthMap or explicit; a
                                      ///< volume's: (W + 4) x (H + 4) with its guard band (DepthMap::guard)
  std::optional<VolumeMesh> volume;   ///< the explicit volume drawn, when RenderOptions::keepVolume
                                      ///< (refined GPU volume: the CPU mesh from its crossings;
                                      ///< GPU cube volume: the explicit one of the same faces)
  std::optional<VolumeMesh> gpuVolume;  ///< refined GPU volume with keepVolume: the GPU's own
                                        ///< triangles, read back and placed in double (a debug path)
  /// Refined GPU cube volume with keepVolume: face f's volume (cube_map.h's order), the CPU mesh
  /// from its crossings and the GPU's own triangles, as `volume` and `gpuVolume` are for one map.
  /// Each pixel is counted against the face its surface point lies on (cubeLookup); `volume`,
  /// `gpuVolume` and `depthMap` stay empty.
  std::vector<VolumeMesh> faceVolumes, faceGpuVolumes;
  std::vector<PassTime> passes;       ///< in execution order, every light's
  TimingMethod timing = TimingMethod::WallClock;
  double totalMs = 0.0;             ///< sum of passes
  std::size_t volumeTriangles = 0;  ///< triangles of the volume: explicit = the mesh's; gpu = emitted
                                    ///< by the geometry shader (GL_PRIMITIVES_GENERATED);
                                    ///< silhouette = the silhouette volume's
  std::size_t gpuVolumeQuads = 0;       ///< hybrid/gpu: quads of the depth map, (W + 3) (H + 3) with its guard band
  std::size_t gpuVolumeQuadsDrawn = 0;  ///< hybrid/gpu: quads whose triangles were drawn (all of
                                        ///< them with AllQuads)
  GpuVolumeDraw gpuVolumeDrawUsed = GpuVolumeDraw::Auto;  ///< hybrid/gpu: the way actually taken
  VolumeCount volumeCountUsed = VolumeCount::ZFail;      ///< stencil methods: ZFail or ZPass
  std::string zPassRefused;         ///< hybrid with Auto and z-fail used: why z-pass was not safe
  double biasUsed = 0.0;            ///< hybrid: the volume bias in world units
  /// hybrid, explicit volume: where its depth map came from (ExplicitDepth::Auto resolved)
  ExplicitDepth explicitDepthUsed = ExplicitDepth::LightPass;
  std::size_t gpuBoundaryEdges = 0;     ///< refined GPU volume: boundary edges walked
  std::size_t gpuCrossingFallbacks = 0; ///< refined GPU volume: of them, walls in the middle of the
                                        ///< edge (no crossing found, walk_crossings.h)
  std::size_t cpuRuleEdgeDifferences = 0; ///< refined GPU volume with keepVolume: edges on which the
                                          ///< CPU's rule (boundary_edges.h, in double) on the read-back
                                          ///< map differs from the GPU's flags (float); `volume` takes the GPU's
  std::optional<VolumeBuildStats> volumeStats;  ///< explicit volume: the CPU build's counts and times
                                                ///< (its time, refinement rays included, is the
                                                ///< "build" pass)
  std::vector<std::string> receiversOnly;  ///< silhouette: open objects (sheets such as a ground
                                           ///< plane) that receive but cast no shadow, by name
  std::vector<std::string> skippedCasters; ///< silhouette: closed objects entirely behind a spot
                                           ///< light's apex plane (they cannot shadow its frustum)
  /// A scene with several lights: this result's fields other than the image, the passes and
  /// the timing describe its first light (Scene::light); light k >= 1 has otherLights[k - 1],
  /// with the same fields but rgba, passes and timing (its passes are in `passes`, named with
  /// the suffix "#k": "light#1", "volume#1"). `rgba` is the whole frame: every light's diffuse
  /// term added, each where its own shadow test says lit.
  std::vector<RenderResult> otherLights;
};

}  // namespace shadowvol

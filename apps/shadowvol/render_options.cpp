#include "render_options.h"

#include <cmath>
#include <regex>

#include "shadowvol/cube_map.h"
#include "shadowvol/error.h"
#include "shadowvol/memory_budget.h"

namespace shadowvol::cli {
namespace {

std::pair<int, int> parseSize(const std::string& text) {
  static const std::regex re("^([0-9]{1,6})x([0-9]{1,6})$");
  std::smatch m;
  if (!std::regex_match(text, m, re))
    throw InputError("command line", "--size", text, "expected WIDTHxHEIGHT, for example 640x480");
  const int w = std::stoi(m[1]), h = std::stoi(m[2]);
  if (w < 1 || h < 1 || w > 16384 || h > 16384)
    throw InputError("command line", "--size", text, "width and height must be between 1 and 16384");
  return {w, h};
}

// Refuses a frame too large for the machine before the renderer allocates it: the --size given,
// else the scene's camera.
void checkFrameMemory(const RenderCliOptions& o, const Scene& scene) {
  const std::uint64_t need = frameBytes(scene.camera.width, scene.camera.height, o.scored);
  const std::string size = std::to_string(scene.camera.width) + "x" + std::to_string(scene.camera.height);
  if (!o.size.empty())
    checkFitsMemory(need, "command line", "--size", o.size);
  else
    checkFitsMemory(need, scene.source, "/camera/width, /camera/height", size);
}

}  // namespace

void addRenderOptions(CLI::App& cmd, RenderCliOptions& o) {
  addSceneOptions(cmd, o.scene);
  addLightFitOption(cmd, o.scene.fit);
  cmd.add_option("--method", o.method,
                 "hybrid (the shadow volume, z-fail stencil), shadowmap (hardware depth compare), pcf3 / pcf5 "
                 "(percentage-closer filtering over 3x3 / 5x5 texels), silhouette (classic object-space shadow "
                 "volumes of the closed objects; open sheets only receive), dpsm (a point light's dual-paraboloid "
                 "shadow map: two maps of round(N * sqrt(3))^2 texels for --resolution N, the cube map's texel "
                 "count; back or front capture), none (no shadows)")
      ->check(CLI::IsMember(namesIn(kShadowMethodNames)))
      ->capture_default_str();
  cmd.add_option("--volume", o.volume,
                 "hybrid: gpu (drawn straight from the depth texture, no read-back: production), explicit (depth "
                 "read back, the CPU-built mesh uploaded) or auto (gpu; for a point light its GPU cube volume, with "
                 "--refine its six refined face volumes)")
      ->check(CLI::IsMember(namesIn(kVolumeSourceNames, {"auto"})))
      ->capture_default_str();
  cmd.add_option("--gpu-draw", o.gpuDraw,
                 "hybrid with --volume gpu and the exact cap: auto (= indexed with GL 4.3, else kept-quads), indexed "
                 "(the light pass marks the texels it covers, a fragment pass lists the triangles of the quads not "
                 "all on the far plane as texel indices, a vertex shader places each texel's vertex; GL 4.3), "
                 "kept-quads (a transform-feedback pass skips the quads all on the far plane, the geometry shader "
                 "expands the others; GL 3.3), compute-mesh (a compute pass builds the kept quads' triangles, GL "
                 "4.3), all-quads (every quad through the geometry shader); same stencil (docs/gpu.md 'Skipping the "
                 "far quads')")
      ->check(CLI::IsMember(namesIn(kGpuVolumeDrawNames, {}, {GpuVolumeDraw::Refined})))
      ->capture_default_str();
  cmd.add_option("--crossings", o.crossings,
                 "With --refine K: where refinement finds each boundary edge's crossing: rays (K bisection rays "
                 "into the Embree scene; --volume explicit only), gpu-walk (the GPU walks over the scene's "
                 "triangles from the one each texel recorded to the silhouette edge: exact, no rays, K only "
                 "switches it on; GL 4.3, back or front capture, not with --chord-points or --refine-grid; "
                 "docs/gpu.md 'Crossings from a triangle walk') or gpu-rays (--volume gpu only: the same K "
                 "bisection rays as 'rays', cast on the GPU through a hierarchy of the scene's triangles; back, "
                 "front or entry capture; docs/gpu.md 'Crossings from GPU rays'); auto: rays for --volume explicit, "
                 "gpu-rays for --volume gpu")
      ->check(CLI::IsMember(namesIn(kRefineCrossingsNames, {"auto"})))
      ->capture_default_str();
  cmd.add_option("--depth-from", o.depthFrom,
                 "hybrid with --volume explicit: where its depth map comes from: gpu (the light pass, read back), "
                 "rays (one Embree ray per texel centre on the CPU, the rays refinement casts: no light pass, no "
                 "read-back; on a software GL such as llvmpipe cheaper than rasterising the scene once more at "
                 "small maps) or auto (rays with --refine on a software GL where the scene has at least 0.75 "
                 "triangles per texel, else gpu; README 'Depth map from rays')")
      ->check(CLI::IsMember(namesIn(kExplicitDepthNames)))
      ->capture_default_str();
  cmd.add_option("--count", o.count,
                 "hybrid: how the stencil counts the volume: auto (z-pass without the far cap where the camera's "
                 "near rectangle provably lies outside the volume, else z-fail), zfail (always, with the cap), zpass "
                 "(refused where not provably safe); the same stencil where the light reaches (docs/gpu.md)")
      ->check(CLI::IsMember(namesIn(kVolumeCountOptionNames)))
      ->capture_default_str();
  cmd.add_option("--resolution", o.resolution,
                 "Light depth map size N (N x N texels; a point light: six faces of N x N, N up to " +
                     std::to_string(kMaxWindowSide / kCubeFaces) + ")")
      ->capture_default_str();
  addCaptureOption(cmd, o.capture);
  addVolumeOptions(cmd, o.shape);
  cmd.add_option("--size", o.size, "Image size WIDTHxHEIGHT (default: the scene camera's)");
  cmd.add_option("--shadow-bias", o.shadowBias,
                 "Shadow maps: constant depth bias, world units (default: 0 for back and midpoint capture, the texel "
                 "footprint plus depth precision for front and entry capture, as the volume's --bias)");
  cmd.add_option("--shadow-slope", o.shadowSlope,
                 "Shadow maps: slope-scaled bias, in texel footprints x tan(angle to the light)")
      ->capture_default_str();
  cmd.add_option("--dpsm-subdivide", o.dpsmSubdivide,
                 "dpsm: cut each triangle into up to SxS in the light pass (S = 1, 2, 4, 8) so that no edge spans more "
                 "than 0.1 rad seen from the light; 1 = the reference tutorial's pass, whose large triangles bend "
                 "(docs/gpu.md 'Dual-paraboloid maps')")
      ->check(CLI::IsMember({1, 2, 4, 8}))
      ->capture_default_str();
  addPlatformOption(cmd, o.platform);
  cmd.add_option("--shader-dir", o.shaderDir,
                 "Load GLSL from this folder instead of the embedded copies (also: $SHADOWVOL_SHADER_DIR)")
      ->check(CLI::ExistingDirectory);
}

namespace {

constexpr const char* kGpuWalksOnly =
    "the refined GPU volume finds its crossings on the GPU: use --crossings "
    "gpu-rays (or auto) or gpu-walk, or --volume explicit for Embree's rays";
constexpr const char* kGpuCrossingsOnly =
    "needs rays (--volume explicit --crossings rays): the refined GPU volume "
    "refines the boundary edges' crossings alone";

// The flag of the refined GPU volume's refusals (kGpuWalksOnly, kGpuCrossingsOnly) that `o` sets, or null.
const char* refinedGpuConflict(const RenderCliOptions& o) {
  if (o.crossings == "rays") return "--crossings";
  if (o.shape.chordPoints) return "--chord-points";
  if (o.shape.refineGrid > 1) return "--refine-grid";
  if (o.shape.facePrisms) return "--face-prisms";
  return nullptr;
}

}  // namespace

gl::RenderOptions toRenderOptions(const RenderCliOptions& o, Scene& scene, std::string* captureAutoReason) {
  checkResolution("--resolution", o.resolution, o.method == "hybrid" ? DepthMapUse::Volume : DepthMapUse::ShadowMap);
  if (o.shadowBias && (!std::isfinite(*o.shadowBias) || *o.shadowBias < 0.0))
    throw InputError("command line", "--shadow-bias", numberText(*o.shadowBias), "must be finite and >= 0");
  if (!std::isfinite(o.shadowSlope) || o.shadowSlope < 0.0)
    throw InputError("command line", "--shadow-slope", numberText(o.shadowSlope), "must be finite and >= 0");
  gl::RenderOptions ro;
  gl::parseShadowMethod(o.method, ro.method);
  gl::parseVolumeSource(o.volume == "auto" ? "gpu" : o.volume, ro.volume);  // auto: the GPU volume
  parseGpuVolumeDraw(o.gpuDraw, ro.gpuVolumeDraw);
  gl::parseVolumeCount(o.count, ro.volumeCount);
  if (o.crossings != "auto") parseRefineCrossings(o.crossings, ro.refineCrossings);
  parseExplicitDepth(o.depthFrom, ro.explicitDepth);
  ro.depthWidth = ro.depthHeight = o.resolution;
  ro.volumeOptions = toVolumeBuildOptions(o.shape);
  if (o.method != "silhouette" && o.method != "none") {  // those capture no map
    const ResolvedCapture capture = resolveCapture(o.capture, scene, captureUse(ro));
    ro.capture = capture.mode;
    if (captureAutoReason) *captureAutoReason = capture.autoReason;
  }
  ro.shadowBiasConstant = o.shadowBias;
  ro.shadowBiasSlope = o.shadowSlope;
  ro.paraboloidSubdivision = o.dpsmSubdivide;
  if (!o.size.empty()) {
    const auto [w, h] = parseSize(o.size);
    scene.camera.width = w;
    scene.camera.height = h;
  }
  checkFrameMemory(o, scene);
  return ro;
}

gl::RendererOptions toRendererOptions(const RenderCliOptions& o) {
  gl::RendererOptions r;
  r.context.platform = o.platform;
  r.shaderDir = o.shaderDir;
  return r;
}

namespace {

// Options that would change nothing in the frame the other options ask for, refused by name
// rather than ignored (found by an adversarial run: --bias with --method shadowmap, --shadow-bias
// with hybrid, --gpu-draw with the explicit volume were accepted and did nothing). A value equal
// to the default changes nothing either way and is let through.
void checkIneffectiveOptions(const RenderCliOptions& o) {
  const VolumeCliOptions& v = o.shape;
  const VolumeCliOptions none;
  if (o.method != "hybrid") {
    const std::pair<bool, const char*> volumeOnly[] = {{o.volume != "auto", "--volume"},
                                                       {o.gpuDraw != "auto", "--gpu-draw"},
                                                       {o.count != "auto", "--count"},
                                                       {o.crossings != "auto", "--crossings"},
                                                       {v.triangulation != none.triangulation, "--triangulation"},
                                                       {v.blur, "--blur"},
                                                       {v.blurOffset != 0.0, "--blur-offset"},
                                                       {v.bias.has_value(), "--bias"},
                                                       {v.cap != none.cap, "--cap"},
                                                       {v.chordPoints, "--chord-points"},
                                                       {v.refineGrid != none.refineGrid, "--refine-grid"},
                                                       {v.refineGridEverywhere, "--refine-grid-everywhere"},
                                                       {v.noSnap, "--no-snap"},
                                                       {v.noHiddenSearch, "--no-hidden-search"},
                                                       {v.facePrisms, "--face-prisms"}};
    for (const auto& [given, flag] : volumeOnly)
      if (given)
        throw CLI::ValidationError(flag, std::string("shapes or draws only the hybrid method's shadow volume, not --method ") +
                                             o.method + "'s: add --method hybrid or leave out " + flag);
  }
  if (o.method == "hybrid" || o.method == "silhouette" || o.method == "none") {
    if (o.shadowBias)
      throw CLI::ValidationError("--shadow-bias", "offsets a shadow map's depth comparison; --method " + o.method +
                                                      " has no shadow map (the hybrid volume's offset is --bias)");
    if (o.shadowSlope != 1.0)
      throw CLI::ValidationError("--shadow-slope",
                                 "scales a shadow map's bias; --method " + o.method + " has no shadow map");
  }
  if (o.method == "silhouette" || o.method == "none") {
    // A probe's finding: both were accepted and changed nothing. --fit view sizes its margins by
    // the map's texels, so there --resolution still counts.
    const RenderCliOptions defaults;
    if (o.capture != defaults.capture)
      throw CLI::ValidationError("--capture", "chooses what a depth map records; --method " + o.method +
                                                  " captures none: leave out --capture");
    if (o.resolution != defaults.resolution && o.scene.fit != "view")
      throw CLI::ValidationError("--resolution", "sizes the light's depth map; --method " + o.method +
                                                     " captures none (only --fit view sizes its margins by it): "
                                                     "leave out --resolution");
  }
  if (o.dpsmSubdivide != 1 && o.method != "dpsm")
    throw CLI::ValidationError("--dpsm-subdivide", "cuts triangles in the dual-paraboloid pass; --method " + o.method +
                                                       " has none: add --method dpsm or leave it out");
  if (o.method == "hybrid" && o.volume == "explicit" && o.gpuDraw != "auto")
    throw CLI::ValidationError(
        "--gpu-draw", "chooses how the GPU volume is drawn; --volume explicit draws the mesh built on the CPU");
  if (o.method == "hybrid" && v.cap == "quad" && o.gpuDraw != "auto")  // the quad cap draws every quad
    throw CLI::ValidationError("--gpu-draw", "chooses how the exact cap's GPU volume skips far quads; --cap quad "
                                             "draws all of them: leave one out");
  if (o.method == "hybrid" && o.crossings == "rays" && v.refine == 0)
    throw CLI::ValidationError("--crossings", "chooses where refinement finds its crossings: add --refine K");
}

}  // namespace

void checkRenderOptionConflicts(const RenderCliOptions& o) {
  // Before the scene is read: --volume auto is the GPU volume for every scene.
  const bool refinedGpu = o.shape.refine > 0 && o.method == "hybrid" && (o.volume == "gpu" || o.volume == "auto");
  if (const char* flag = refinedGpu ? refinedGpuConflict(o) : nullptr)
    throw CLI::ValidationError(flag, std::string(flag) == "--crossings" ? kGpuWalksOnly : kGpuCrossingsOnly);
  // Regression (a hostile-input probe): --refine with another method was silently ignored.
  if (o.shape.refine > 0 && o.method != "hybrid")
    throw CLI::ValidationError("--refine", "refines a hybrid volume's walls; --method " + o.method +
                                               " has none: add --method hybrid or leave out --refine");
  if (o.crossings == "gpu-walk" && (o.shape.refine == 0 || o.method != "hybrid"))
    throw CLI::ValidationError("--crossings", "gpu-walk refines a hybrid volume: add --method hybrid --refine K");
  if (o.crossings == "gpu-rays" && !refinedGpu)
    throw CLI::ValidationError("--crossings",
                               "gpu-rays refines the GPU volume: add --method hybrid --volume gpu "
                               "--refine K (the explicit volume casts Embree's rays: --crossings rays)");
  if (o.depthFrom == "rays" && (o.method != "hybrid" || o.volume != "explicit"))
    throw CLI::ValidationError("--depth-from",
                               "rays casts the explicit volume's depth map: add --method hybrid "
                               "--volume explicit");
  if (o.depthFrom == "rays" && o.crossings == "gpu-walk")
    throw CLI::ValidationError("--depth-from",
                               "rays leaves out the light pass, whose triangle record the walk "
                               "(--crossings gpu-walk) follows: use --crossings rays");
  if (o.crossings == "gpu-walk" && (o.shape.chordPoints || o.shape.refineGrid > 1 || o.shape.facePrisms))
    throw CLI::ValidationError("--crossings",
                               "gpu-walk gives the boundary edges' crossings alone: --chord-points, --refine-grid "
                               "and --face-prisms need --crossings rays");
  checkIneffectiveOptions(o);
}

std::unique_ptr<EmbreeDepthOracle> attachDepthOracle(const Scene& scene, gl::RenderOptions& ro) {
  if (!needsDepthOracle(ro)) return nullptr;
  auto oracle = std::make_unique<EmbreeDepthOracle>(scene);
  ro.volumeOptions.depthOracle = oracle->oracle();
  ro.volumeOptions.surfaceEnds = oracle->surfaceEnds();
  ro.volumeOptions.nearerSurfaces = oracle->nearerSurfaces();
  ro.volumeOptions.casterFaces = oracle->casterFaces();
  ro.volumeOptions.withoutCasters = oracle->withoutCasters();
  return oracle;
}

}  // namespace shadowvol::cli

#include "shadowvol/bench/sweep.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <tuple>
#include <unistd.h>

#include "shadowvol/bench/shadow_error.h"
#include "shadowvol/embree/embree_depth_oracle.h"
#include "shadowvol/embree/ray_queries.h"
#include "shadowvol/error.h"
#include "shadowvol/mesh_io.h"  // writeAtomically, createFolders
#include "shadowvol/output_lock.h"
#include "shadowvol/volume_builder.h"

namespace shadowvol {
namespace {

// A method key's capture: "-front", "-midpoint", "-entry", nothing for back capture (the default).
std::string captureSuffix(CaptureMode capture) {
  return capture == CaptureMode::Back ? "" : std::string("-") + toString(capture);
}

// A method description's capture: "back capture", "front capture (default bias)", ...
std::string captureWords(CaptureMode capture) {
  return std::string(toString(capture)) + " capture" + (recordsLitSurfaces(capture) ? " (default bias)" : "");
}

SweepMethod hybrid(Triangulation t, bool blur, gl::VolumeSource source, CaptureMode capture = CaptureMode::Back) {
  SweepMethod m;
  const std::string variant = std::string(toString(t)) + (blur ? "-blur" : "") +
                              captureSuffix(capture);
  m.key = "hybrid-" + variant + "/" + gl::toString(source);
  m.family = "hybrid";
  m.options.method = gl::ShadowMethod::Hybrid;
  m.options.volume = source;
  m.options.capture = capture;
  m.options.volumeOptions.triangulation = t;
  m.options.volumeOptions.blur = blur;
  m.options.volumeOptions.cap = FarCap::Exact;
  m.description = "shadow volume from the depth map, " + variant + ", " + gl::toString(source) + " volume, " +
                  captureWords(capture);
  return m;
}

// The refined explicit volume: perfect triangulation, kSweepRefineSteps rays per boundary edge
// into the scene (the depth oracle is attached per scene by runSweep; its rays are part of the
// frame's build pass). Its depth map as the command line takes it (ExplicitDepth::Auto, since
// 2026-12-05): ray-cast on a software GL where the scene has kRayDepthTrianglesPerTexel triangles
// per texel or more, else the light pass (hybrid-refined-lightpass/explicit: the light pass
// always, what these keys measured before).
SweepMethod refined(CaptureMode capture) {
  SweepMethod m = hybrid(Triangulation::Perfect, false, gl::VolumeSource::Explicit, capture);
  m.key = std::string("hybrid-refined") + captureSuffix(capture) +
          "/explicit";
  m.options.volumeOptions.refineSteps = kSweepRefineSteps;
  m.options.explicitDepth = gl::ExplicitDepth::Auto;
  m.description = "explicit volume with sub-texel silhouette refinement (" + std::to_string(kSweepRefineSteps) +
                  " rays per boundary edge, perfect triangulation; its depth map from the light pass, or ray-cast "
                  "where that is expected to cost less), " + captureWords(capture);
  return m;
}

// The refined explicit volume (back capture) with its depth map from one fixed source instead of
// ExplicitDepth::Auto's choice: `key`, and `source` words for the description.
SweepMethod refinedWithDepth(const char* key, gl::ExplicitDepth depth, const std::string& source) {
  SweepMethod m = refined(CaptureMode::Back);
  m.key = key;
  m.options.explicitDepth = depth;
  m.description = "explicit volume with sub-texel silhouette refinement (" + std::to_string(kSweepRefineSteps) +
                  " rays per boundary edge, perfect triangulation), its depth map " + source + ", " +
                  captureWords(CaptureMode::Back);
  return m;
}

// The light pass on every scene (ExplicitDepth::LightPass): hybrid-refined/explicit before 2026-12-05.
SweepMethod refinedLightPass() {
  return refinedWithDepth("hybrid-refined-lightpass/explicit", gl::ExplicitDepth::LightPass,
                          "always from the light pass");
}

// The scene's rays instead of the light pass (ExplicitDepth::Rays: one ray per texel centre on the
// CPU, timed as the frame's light pass).
SweepMethod refinedRayDepth() {
  return refinedWithDepth("hybrid-refined-raycast/explicit", gl::ExplicitDepth::Rays,
                          "ray-cast on the CPU (one ray per texel centre, no light pass)");
}

// The refined explicit volume with its crossings from the GPU's silhouette walk instead of rays
// (RefineCrossings::GpuWalk; the walk's time, with its read-back, is part of the build pass).
SweepMethod refinedWalk(CaptureMode capture) {
  SweepMethod m = refined(capture);
  m.key = std::string("hybrid-refined-walk") + captureSuffix(capture) +
          "/explicit";
  m.options.refineCrossings = gl::RefineCrossings::GpuWalk;
  m.description = "explicit volume with sub-texel silhouette refinement, the crossings from the GPU's walk over the "
                  "scene's triangles (no rays), perfect triangulation, " + captureWords(capture);
  return m;
}

// The refined GPU volume (--volume gpu --refine K: boundary edges, kSweepRefineSteps bisection
// rays per boundary edge cast on the GPU through a BVH of the scene's triangles and the refined
// cells in compute passes, no read-back; the rays are the frame's "crossings" pass). Before
// 2026-12-04 this key was the walk's (hybrid-refined-walk/gpu since).
SweepMethod refinedGpu(CaptureMode capture) {
  SweepMethod m = hybrid(Triangulation::Perfect, false, gl::VolumeSource::Gpu, capture);
  m.key = std::string("hybrid-refined") + captureSuffix(capture) + "/gpu";
  m.options.volumeOptions.refineSteps = kSweepRefineSteps;
  m.description = "GPU volume with sub-texel silhouette refinement, the crossings from " +
                  std::to_string(kSweepRefineSteps) + " bisection rays per boundary edge cast on the GPU, all on the "
                  "GPU without a read-back; perfect triangulation, " + captureWords(capture);
  return m;
}

// The refined GPU volume with the crossings from the GPU's walk (RefineCrossings::GpuWalk; the
// walk's passes are the frame's "crossings" pass).
SweepMethod refinedGpuWalk(CaptureMode capture) {
  SweepMethod m = refinedGpu(capture);
  m.key = std::string("hybrid-refined-walk") + captureSuffix(capture) + "/gpu";
  m.options.refineCrossings = gl::RefineCrossings::GpuWalk;  // K only switches it on: the walk is exact
  m.description = "GPU volume with sub-texel silhouette refinement, the crossings from the GPU's walk over the scene's "
                  "triangles, all on the GPU without a read-back; perfect triangulation, " + captureWords(capture);
  return m;
}

// The refined volume, explicit or GPU, back capture, without the snap (crossing_snap.h,
// VolumeBuildOptions::refineSnap = false): each crossing in the middle of its last bisection
// bracket, as every refined method before 2026-12-04; for what the snap costs and gains.
SweepMethod refinedNoSnap(gl::VolumeSource source) {
  SweepMethod m = source == gl::VolumeSource::Gpu ? refinedGpu(CaptureMode::Back) : refined(CaptureMode::Back);
  m.key = std::string("hybrid-refined-nosnap/") + gl::toString(source);
  m.options.volumeOptions.refineSnap = false;
  m.description += "; no snap (each crossing in the middle of its last bisection bracket)";
  return m;
}

// The refined volume on the sub-grid (S = kSweepRefineSubdivisions per texel side, or `subdivisions`,
// in the quads with a boundary edge, and in those hiding a surface or an open rim between their
// texel centres: the search, on by default, from the oracle's nearerSurfaces that runSweep
// attaches), same steps. Keys: hybrid-refined-grid[-capture]/explicit at the default S, with the S
// after "grid" otherwise (hybrid-refined-grid8-entry/explicit).
SweepMethod refinedGrid(CaptureMode capture, int subdivisions = kSweepRefineSubdivisions) {
  SweepMethod m = refined(capture);
  const std::string s = std::to_string(subdivisions);
  m.key = std::string("hybrid-refined-grid") + (subdivisions == kSweepRefineSubdivisions ? "" : s) +
          captureSuffix(capture) + "/explicit";
  m.options.volumeOptions.refineSubdivisions = subdivisions;
  m.description = "explicit volume with sub-texel silhouette refinement on a " + s + "x" + s +
                  " adaptive sub-grid in the quads with a boundary edge or a surface or gap hidden between the texel "
                  "centres (" + std::to_string(kSweepRefineSteps) + " steps, perfect triangulation), " +
                  captureWords(capture);
  return m;
}

// The refined volume on the sub-grid with the face prisms (docs/volume.md "Face prisms": the closed
// meshes' faces turned towards the light in the refined quads' columns, each region of them whole,
// a second closed part; the oracle's casterFaces that runSweep attaches). Keys:
// hybrid-refined-grid[S]-prisms[-capture]/explicit.
SweepMethod refinedPrisms(CaptureMode capture, int subdivisions = kSweepRefineSubdivisions) {
  SweepMethod m = refinedGrid(capture, subdivisions);
  const std::string s = std::to_string(subdivisions);
  m.key = std::string("hybrid-refined-grid") + (subdivisions == kSweepRefineSubdivisions ? "" : s) + "-prisms" +
          captureSuffix(capture) + "/explicit";
  m.options.volumeOptions.facePrisms = true;
  m.description += "; with the prisms of the closed meshes' faces in the refined quads' columns";
  return m;
}

SweepMethod shadowMap(const std::string& key, gl::ShadowMethod method, CaptureMode capture, const std::string& what) {
  SweepMethod m;
  m.key = key;
  m.family = gl::toString(method);
  m.options.method = method;
  m.options.capture = capture;
  m.description = what;
  return m;
}

// A point light's methods (docs/volume.md "Point lights"): the cube shadow map (one tap, PCF), the
// dual-paraboloid map and the explicit cube volume, each at the resolution of one cube face (the
// dual-paraboloid map at the same texel count).
SweepMethod cubeShadowMap(const std::string& key, gl::ShadowMethod method, const std::string& what) {
  SweepMethod m = shadowMap(key, method, CaptureMode::Back, what);
  m.lights = SweepLights::Point;
  return m;
}

SweepMethod cubeVolume(CaptureMode capture, gl::VolumeSource source) {
  SweepMethod m = hybrid(Triangulation::Perfect, false, source, capture);
  const bool gpu = source == gl::VolumeSource::Gpu;
  m.key = std::string("hybrid-cube") + captureSuffix(capture) +
          (gpu ? "/gpu" : "/explicit");
  m.lights = SweepLights::Point;
  m.description = std::string("a point light's ") +
                  (gpu ? "GPU cube volume drawn straight from its six face maps (no read-back)"
                       : "explicit cube volume from its six face maps") +
                  " (perfect triangulation, far cube cap), " + captureWords(capture);
  return m;
}

// The explicit cube volume refined by kSweepRefineSteps rays per boundary edge (cube_volume.h;
// the depth oracle attached per scene by runSweep, its rays part of the frame's build pass).
SweepMethod cubeRefined(CaptureMode capture) {
  SweepMethod m = cubeVolume(capture, gl::VolumeSource::Explicit);
  m.key = std::string("hybrid-cube-refined") + captureSuffix(capture) +
          "/explicit";
  m.options.volumeOptions.refineSteps = kSweepRefineSteps;
  m.options.explicitDepth = gl::ExplicitDepth::Auto;  // as refined()
  m.description = "a point light's explicit cube volume with sub-texel silhouette refinement (" +
                  std::to_string(kSweepRefineSteps) + " rays per boundary edge, inside the faces and across the cube's "
                  "edges; perfect triangulation, far cube cap), " + captureWords(capture);
  return m;
}

// The refined GPU cube volume (--volume gpu --refine K for a point light): six face volumes, each
// the refined GPU volume of its face with a guard band, every pixel counted against its own face's.
SweepMethod cubeRefinedGpu(CaptureMode capture) {
  SweepMethod m = cubeVolume(capture, gl::VolumeSource::Gpu);
  m.key = std::string("hybrid-cube-refined") + captureSuffix(capture) + "/gpu";
  m.options.volumeOptions.refineSteps = kSweepRefineSteps;
  m.description = "a point light's refined GPU cube volume: per face, the refined GPU volume (bisection rays cast on "
                  "the GPU, no read-back) of the face's frustum widened by a guard band, each pixel counted "
                  "against its own face's volume; perfect triangulation, " + captureWords(capture);
  return m;
}

bool applies(const SweepMethod& m, LightType light) {
  if (m.lights == SweepLights::Any) return true;
  return (m.lights == SweepLights::Point) == (light == LightType::Point);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  if (v.empty()) return 0.0;
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

TimeStat stat(const std::vector<double>& v) {
  TimeStat s;
  s.median = median(v);
  s.min = *std::min_element(v.begin(), v.end());
  s.max = *std::max_element(v.begin(), v.end());
  return s;
}

std::string sceneLabel(const std::filesystem::path& scene) {
  return scene.empty() ? "default" : scene.stem().string();
}

// Every scene's cells, rows and plots are keyed by its label (the file's name): before anything is
// measured, refuse a scene given twice, two files of one name (a resumed sweep would take one's
// rows for the other's) and a name that results.csv cannot hold. Regressions of a hostile-input
// probe: such sweeps merged two scenes, or failed after measuring the scenes before.
void checkSceneNames(const std::vector<std::filesystem::path>& scenes, const std::filesystem::path& csv) {
  std::map<std::string, std::filesystem::path> seen;
  for (const auto& scene : scenes) {
    const std::string label = sceneLabel(scene), shown = scene.empty() ? "(the built-in scene)" : scene.string();
    // A double quote too: an unquoted field holding one is not CSV (RFC 4180; a twenty-second probe).
    if (label.find_first_of(",\"\n\r") != std::string::npos)
      throw InputError("SweepOptions", "scenes", shown,
                       "its name \"" + label + "\" holds a comma, a double quote or a line break, which " +
                           csv.string() + " cannot hold: copy the scene to a file named without them");
    const auto [at, fresh] = seen.emplace(label, scene);
    if (!fresh)
      throw InputError("SweepOptions", "scenes", shown,
                       at->second == scene ? "is given twice"
                                           : "has the name \"" + label + "\" of " +
                                                 (at->second.empty() ? std::string("the built-in scene") : at->second.string()) +
                                                 " too: cells, rows and plots are keyed by it; rename one copy");
  }
}

// The scene's light type, from the loaded scene (its meshes are read once more for the cells).
// The sweep scores one light's shadow: a scene with several is refused (validate checks each).
LightType lightTypeOf(const std::filesystem::path& scene) {
  if (scene.empty()) return defaultScene().light.type;
  const Scene s = loadScene(scene).scene;
  if (s.lightCount() > 1)
    throw InputError(scene.string(), "/lights", std::to_string(s.lightCount()) + " lights",
                     "the sweep measures one light's shadows against its exact shadow; validate checks a scene with "
                     "several lights light by light, and render times its frame");
  return s.light.type;
}

}  // namespace

const std::vector<SweepMethod>& sweepMethods() {
  static const std::vector<SweepMethod> all = [] {
    std::vector<SweepMethod> v;
    v.push_back(shadowMap("shadowmap", gl::ShadowMethod::ShadowMap, CaptureMode::Back,
                          "shadow map, one hardware depth compare, back-face depths (second-depth)"));
    v.push_back(shadowMap("shadowmap-front", gl::ShadowMethod::ShadowMap, CaptureMode::Front,
                          "shadow map of front faces, default constant bias (defaultBias) plus slope-scaled bias"));
    v.push_back(shadowMap("shadowmap-midpoint", gl::ShadowMethod::ShadowMap, CaptureMode::Midpoint,
                          "midpoint shadow map (mean of the first two layers)"));
    v.push_back(shadowMap("pcf3", gl::ShadowMethod::Pcf3, CaptureMode::Back, "PCF over 3 x 3 texels, back faces"));
    v.push_back(shadowMap("pcf5", gl::ShadowMethod::Pcf5, CaptureMode::Back, "PCF over 5 x 5 texels, back faces"));
    for (auto source : {gl::VolumeSource::Gpu, gl::VolumeSource::Explicit})
      for (auto t : {Triangulation::Fixed, Triangulation::Perfect})
        for (bool blur : {false, true}) v.push_back(hybrid(t, blur, source));
    // The capture modes, where they matter: the sheet on the first surface (front, with the
    // default bias) and between the first two (midpoint).
    v.push_back(hybrid(Triangulation::Perfect, false, gl::VolumeSource::Gpu, CaptureMode::Front));
    v.push_back(hybrid(Triangulation::Perfect, false, gl::VolumeSource::Gpu, CaptureMode::Midpoint));
    // The GPU volume's other ways of drawing (gl::GpuVolumeDraw; the default, GL 4.3, lists the
    // kept quads' triangles as texel indices in a fragment pass): the kept quads listed by a
    // transform-feedback pass and expanded by the geometry shader (the GL 3.3 way), every quad
    // through the geometry shader, and the kept quads' triangles built by a compute pass.
    for (auto [how, name, what] :
         {std::tuple{gl::GpuVolumeDraw::KeptQuads, "keptquads",
                     "a transform-feedback pass lists the quads not all on the far plane, the geometry shader expands "
                     "them (GL 3.3)"},
          std::tuple{gl::GpuVolumeDraw::AllQuads, "allquads", "every quad of the map through the geometry shader, none skipped"},
          std::tuple{gl::GpuVolumeDraw::ComputeMesh, "computemesh",
                     "a compute pass writes the triangles of the quads not all on the far plane into a buffer (GL 4.3)"}}) {
      SweepMethod m = hybrid(Triangulation::Perfect, false, gl::VolumeSource::Gpu);
      m.key = std::string("hybrid-perfect-") + name + "/gpu";
      m.options.gpuVolumeDraw = how;
      m.description = std::string("GPU volume, ") + what + "; perfect triangulation, back capture";
      v.push_back(m);
    }
    // Every hybrid method counts with z-pass and no far cap where it is safe (gl::VolumeCount::Auto);
    // this one always with z-fail and the cap, to measure what that saves.
    SweepMethod zfail = hybrid(Triangulation::Perfect, false, gl::VolumeSource::Gpu);
    zfail.key = "hybrid-perfect-zfail/gpu";
    zfail.options.volumeCount = gl::VolumeCount::ZFail;
    zfail.description = "GPU volume always counted with z-fail and its far cap (the others take z-pass without the cap "
                        "where it is safe); perfect triangulation, back capture";
    v.push_back(zfail);
    for (CaptureMode c : {CaptureMode::Back, CaptureMode::Front, CaptureMode::Midpoint}) v.push_back(refined(c));
    v.push_back(refinedRayDepth());
    v.push_back(refinedLightPass());
    for (CaptureMode c : {CaptureMode::Back, CaptureMode::Front, CaptureMode::Entry}) v.push_back(refinedGrid(c));
    // S = 8: what --capture auto takes with the finer sub-grid (entry on closed meshes, front on open ones).
    for (CaptureMode c : {CaptureMode::Front, CaptureMode::Entry}) v.push_back(refinedGrid(c, 8));
    for (int s : {kSweepRefineSubdivisions, 8}) v.push_back(refinedPrisms(CaptureMode::Entry, s));  // closed meshes
    for (CaptureMode c : {CaptureMode::Back, CaptureMode::Front}) v.push_back(refinedWalk(c));
    for (CaptureMode c : {CaptureMode::Back, CaptureMode::Front, CaptureMode::Entry}) v.push_back(refinedGpu(c));
    for (CaptureMode c : {CaptureMode::Back, CaptureMode::Front}) v.push_back(refinedGpuWalk(c));
    for (auto source : {gl::VolumeSource::Explicit, gl::VolumeSource::Gpu}) v.push_back(refinedNoSnap(source));
    v.push_back(cubeShadowMap("cube-shadowmap", gl::ShadowMethod::ShadowMap,
                              "a point light's cube shadow map, one hardware depth compare, back-face depths"));
    v.push_back(cubeShadowMap("cube-pcf3", gl::ShadowMethod::Pcf3,
                              "a point light's cube shadow map, PCF over 3 x 3 texels of the face, back faces"));
    v.push_back(cubeShadowMap("dpsm", gl::ShadowMethod::Dpsm,
                              "a point light's dual-paraboloid shadow map, two maps of the cube map's texel count "
                              "(round(N sqrt 3)^2 each for resolution N), one tap, back faces"));
    SweepMethod subdivided = cubeShadowMap("dpsm-subdivided", gl::ShadowMethod::Dpsm,
                                           "the dual-paraboloid map with each triangle cut into up to 8 x 8 in "
                                           "its light pass (no edge over 0.1 rad), back faces");
    subdivided.options.paraboloidSubdivision = 8;
    v.push_back(subdivided);
    for (CaptureMode c : {CaptureMode::Back, CaptureMode::Front, CaptureMode::Midpoint})
      v.push_back(cubeVolume(c, gl::VolumeSource::Explicit));
    for (CaptureMode c : {CaptureMode::Back, CaptureMode::Front, CaptureMode::Midpoint})
      v.push_back(cubeVolume(c, gl::VolumeSource::Gpu));
    for (CaptureMode c : {CaptureMode::Back, CaptureMode::Front, CaptureMode::Midpoint}) v.push_back(cubeRefined(c));
    for (CaptureMode c : {CaptureMode::Back, CaptureMode::Front}) v.push_back(cubeRefinedGpu(c));
    SweepMethod s;
    s.key = "silhouette";
    s.lights = SweepLights::Any;
    s.family = "silhouette";
    s.options.method = gl::ShadowMethod::Silhouette;
    s.usesResolution = false;
    s.description = "classic silhouette shadow volumes of the closed objects (exact for closed manifolds), any light";
    v.push_back(s);
    return v;
  }();
  return all;
}

std::vector<SweepRow> runSweep(gl::Renderer& renderer, const SweepOptions& o, const std::atomic<bool>& stop,
                               const std::function<void(const SweepProgress&)>& onProgress,
                               std::vector<std::string>& notes) {
  // Which methods.
  std::vector<const SweepMethod*> methods;
  for (const auto& m : sweepMethods())
    if (o.methods.empty() || std::count(o.methods.begin(), o.methods.end(), m.key)) methods.push_back(&m);
  for (const auto& key : o.methods)
    if (std::none_of(methods.begin(), methods.end(), [&](const SweepMethod* m) { return m->key == key; }))
      throw InputError("SweepOptions", "methods", key,
                       "unknown method: `shadowvol bench --list-methods` lists the method keys (sweepMethods() "
                       "in the library)");
  const gl::ContextInfo& gli = renderer.info();
  if (gli.glMajor < 4 || (gli.glMajor == 4 && gli.glMinor < 3))
    std::erase_if(methods, [&](const SweepMethod* m) {
      const gl::RenderOptions& ro = m->options;
      const bool needsCompute = ro.gpuVolumeDraw == gl::GpuVolumeDraw::ComputeMesh ||
                                (ro.volumeOptions.refineSteps > 0 &&
                                 (ro.refineCrossings == gl::RefineCrossings::GpuWalk || ro.volume == gl::VolumeSource::Gpu));
      if (needsCompute) notes.push_back(m->key + " skipped: needs GL 4.3 compute shaders, the context is " + gli.glVersion);
      return needsCompute;
    });
  // Resolutions that fit: the depth map, the explicit volume and the GPU textures, well inside memory.
  std::vector<int> resolutions;
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  const double physical = pages > 0 && pageSize > 0 ? double(pages) * double(pageSize) : 0.0;
  for (int r : o.resolutions) {
    if (r < kMinVolumeMapSide || r > kMaxWindowSide)
      throw InputError("SweepOptions", "resolutions", std::to_string(r),
                       "must be in " + std::to_string(kMinVolumeMapSide) + ".." + std::to_string(kMaxWindowSide) +
                           (r < kMinVolumeMapSide ? " (a 2 x 2 map's volume is all border ring: empty)"
                                                  : " (the largest depth map side)"));
    const double need = double(depthMapBytes(r, r)) * 2.0;  // CPU map + mesh, plus GPU copies
    if (physical > 0 && need > physical / 2) {
      notes.push_back("resolution " + std::to_string(r) + " skipped: needs about " +
                      std::to_string(long(need / 1048576)) + " MiB");
      continue;
    }
    if (std::count(resolutions.begin(), resolutions.end(), r) == 0) resolutions.push_back(r);  // once, as methods
  }
  checkSceneNames(o.scenes, o.out / "results.csv");

  // The cells (every scene loaded first, so that a scene refused or broken leaves no output).
  struct Cell {
    std::size_t scene;
    LightFit fit;
    const SweepMethod* method;
    int resolution;
  };
  std::vector<Cell> cells;
  for (std::size_t s = 0; s < o.scenes.size(); ++s) {
    const LightType light = lightTypeOf(o.scenes[s]);
    std::size_t otherLight = 0;
    for (const LightFit fit : o.fits)
      for (const SweepMethod* m : methods) {
        if (!applies(*m, light)) {
          otherLight += fit == o.fits.front();
          continue;
        }
        if (fit == LightFit::View && light == LightType::Point) continue;  // nothing to fit (fitLightToView)
        if (!m->usesResolution) {
          if (fit == LightFit::Scene) cells.push_back({s, fit, m, 0});  // no depth map: measured once, scene-fitted
          else if (s == 0)
            notes.push_back(m->key + ": no view-fitted cells (it has no depth map; its cells are measured with "
                                     "--fit scene only)");
        } else {
          for (int r : resolutions) cells.push_back({s, fit, m, r});
        }
      }
    if (otherLight > 0)
      notes.push_back(sceneLabel(o.scenes[s]) + ": " + std::to_string(otherLight) + " of the methods are for " +
                      (light == LightType::Point ? "spot and directional lights" : "point lights") +
                      ", not this scene's " + toString(light) + " light: not measured");
    if (light == LightType::Point && std::count(o.fits.begin(), o.fits.end(), LightFit::View))
      notes.push_back(sceneLabel(o.scenes[s]) + ": no view-fitted cells (a point light's cube covers every direction)");
  }
  // The results file: resume what is there.
  createFolders(o.out);
  // One sweep at a time appends to a folder's results (a second one refused at once, not after
  // a wait: a sweep holds its folder for as long as it runs).
  const OutputLock lock(o.out, std::chrono::milliseconds(0));
  const auto csv = o.out / "results.csv";
  std::vector<SweepRow> rows;
  std::set<std::string> done;
  std::error_code ec;
  // An empty file is what a run killed while creating it could leave (before the header was
  // written atomically): start afresh.
  if (std::filesystem::exists(csv) && std::filesystem::file_size(csv, ec) > 0) {
    rows = readSweepCsv(csv);
    for (const auto& r : rows) done.insert(cellKey(r));
    // Drop an interrupted last line so appends start on a fresh line.
    std::ifstream in(csv, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.compare(0, text.find('\n'), sweepCsvHeader()) != 0)
      throw InputError(csv.string(), "header", "", "written by an earlier version (without the volume_quads or volume_count columns): "
                                                   "new rows cannot be appended; use another --out folder");
    if (text.find('\n') == std::string::npos) {
      // The header alone (checked above) without its line end: complete it, or the rows appended
      // next would follow it on its line (regression: the file then failed to read back).
      std::ofstream(csv, std::ios::app) << '\n';
    } else if (text.back() != '\n') {
      std::filesystem::resize_file(csv, text.rfind('\n') + 1);
      notes.push_back("dropped an incomplete last line of " + csv.string());
    }
  } else {
    writeAtomically(csv, [](const std::filesystem::path& tmp) {  // the header whole, or no file
      std::ofstream out(tmp);
      out << sweepCsvHeader() << '\n';
      out.flush();
      if (!out) throw InputError(tmp.string(), "", "", "writing the file failed (disk full?)");
    });
  }
  std::ofstream append(csv, std::ios::app);

  SweepProgress progress;
  progress.total = cells.size();
  const auto start = std::chrono::steady_clock::now();
  auto report = [&](const std::string& cell) {
    progress.cell = cell;
    progress.elapsedSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (onProgress) onProgress(progress);
  };

  // The scene as loaded (per scene file) and as rendered (per scene, fit and, for the view fit,
  // resolution: fitLightToView keeps two texels of the map to spare).
  std::size_t baseIndex = std::size_t(-1);
  Scene base;
  std::tuple<std::size_t, LightFit, int> loaded{std::size_t(-1), LightFit::Scene, 0};
  Scene scene;
  std::unique_ptr<EmbreeDepthOracle> oracle;  // the loaded scene's, for refined methods
  std::string sceneName;
  std::vector<PixelClass> exact;
  for (const Cell& c : cells) {
    if (stop) break;
    // Names first (cheap), so resumed cells skip without loading anything.
    const std::string name = sceneLabel(o.scenes[c.scene]) + (c.fit == LightFit::View ? kViewFitSuffix : "");
    SweepRow row;
    row.scene = name;
    row.method = c.method->key;
    row.resolution = c.resolution;
    row.width = o.width;
    row.height = o.height;
    const std::string label = name + " | " + c.method->key + " | " + std::to_string(c.resolution);
    if (done.count(cellKey(row))) {
      ++progress.done;
      ++progress.skipped;
      report(label + " (resumed: already in results.csv)");
      continue;
    }
    const std::tuple<std::size_t, LightFit, int> key{c.scene, c.fit, c.fit == LightFit::View ? c.resolution : 0};
    if (loaded != key) {
      if (baseIndex != c.scene) {
        base = o.scenes[c.scene].empty() ? defaultScene() : loadScene(o.scenes[c.scene]).scene;
        base.camera.width = o.width;
        base.camera.height = o.height;
        baseIndex = c.scene;
      }
      scene = base;
      if (c.fit == LightFit::View) fitLightToView(scene, c.resolution);
      sceneName = name;
      const EmbreeDevice device;
      std::vector<const TriangleMesh*> meshes;
      for (const auto& obj : scene.objects) meshes.push_back(&obj.mesh);
      const EmbreeScene rt(device, meshes);
      exact = exactShadows(rt, scene, castPrimaryRays(rt, scene.camera));
      renderer.setScene(scene);
      oracle.reset();
      loaded = key;
    }
    report(label);
    gl::RenderOptions ro = c.method->options;
    if (needsDepthOracle(ro)) {
      if (!oracle) oracle = std::make_unique<EmbreeDepthOracle>(scene);
      ro.volumeOptions.depthOracle = oracle->oracle();
      ro.volumeOptions.surfaceEnds = oracle->surfaceEnds();
      ro.volumeOptions.nearerSurfaces = oracle->nearerSurfaces();
      ro.volumeOptions.casterFaces = oracle->casterFaces();
      ro.volumeOptions.withoutCasters = oracle->withoutCasters();
    }
    ro.depthWidth = ro.depthHeight = c.resolution > 0 ? c.resolution : 64;
    ro.readStencil = false;
    ro.readDepthMap = false;
    ro.readVisibility = false;
    // The first warm-up frame (rendered even with warmup 0) also meets a method's refusal of this
    // cell, such as the refined GPU volume's size limit: the cell is noted and left out, as a
    // resolution that does not fit, and the sweep goes on.
    try {
      renderer.render(ro);
    } catch (const InputError& e) {
      notes.push_back(label + " skipped: " + e.what());
      ++progress.done;
      report(label + " (skipped: the method refuses it)");
      continue;
    }
    for (int w = 1; w < o.warmup; ++w) renderer.render(ro);
    std::map<std::string, std::vector<double>> phaseTimes;
    std::vector<std::string> phaseOrder;
    std::vector<double> frameTimes;
    gl::RenderResult result;
    for (int f = 0; f < o.repeat; ++f) {
      result = renderer.render(ro);
      frameTimes.push_back(result.totalMs);
      for (const auto& p : passTotals(result.passes)) {  // a cube volume's per-face passes: their sums
        if (!phaseTimes.count(p.name)) phaseOrder.push_back(p.name);
        phaseTimes[p.name].push_back(p.ms);
      }
    }
    // One more frame, not timed, for the method's own shadow test.
    gl::RenderOptions vis = ro;
    vis.readVisibility = true;
    const gl::RenderResult v = renderer.render(vis);
    std::vector<std::uint8_t> shadowed(v.visibility.size());
    for (std::size_t k = 0; k < shadowed.size(); ++k) shadowed[k] = v.visibility[k] < 128;
    const ShadowErrorMetrics m = measureShadowError(v.width, v.height, exact, shadowed, kBoundaryBand);

    row.triangles = scene.triangleCount();
    row.family = c.method->family;
    row.capture = c.method->usesResolution ? toString(ro.capture) : "";
    row.timing = gl::toString(result.timing);
    row.frames = o.repeat;
    row.frame = stat(frameTimes);
    for (const auto& name : phaseOrder) row.phases.push_back({name, stat(phaseTimes[name])});
    row.volumeTriangles = result.volumeTriangles;
    row.volumeQuads = result.gpuVolumeQuads;
    row.volumeQuadsDrawn = result.gpuVolumeQuadsDrawn;
    const gl::ShadowMethod family = c.method->options.method;
    if (drawsShadowVolume(family)) row.volumeCount = gl::toString(result.volumeCountUsed);
    row.pixels = m.pixels;
    row.error = m.pixels ? double(m.leak + m.acne) / double(m.pixels) : 0.0;
    row.leak = m.pixels ? double(m.leak) / double(m.pixels) : 0.0;
    row.acne = m.pixels ? double(m.acne) / double(m.pixels) : 0.0;
    row.bandPixels = m.bandPixels;
    row.bandError = m.bandPixels ? double(m.bandLeak + m.bandAcne) / double(m.bandPixels) : 0.0;
    row.bandLeak = m.bandPixels ? double(m.bandLeak) / double(m.bandPixels) : 0.0;
    row.bandAcne = m.bandPixels ? double(m.bandAcne) / double(m.bandPixels) : 0.0;
    row.distMean = m.distMean;
    row.distP99 = m.distP99;
    row.distMax = m.distMax;
    append << toCsv(row) << '\n';  // one line, flushed at once: an interruption loses at most this cell
    append.flush();
    if (!append) throw InputError(csv.string(), "", "", "appending to the results file failed (disk full?)");
    rows.push_back(row);
    ++progress.done;
    report(label);
  }
  if (progress.skipped > 0)
    notes.push_back("resumed: " + std::to_string(progress.skipped) + " of " + std::to_string(progress.total) +
                    " cells were already in " + csv.string() + " and were not measured again");
  return rows;
}

}  // namespace shadowvol

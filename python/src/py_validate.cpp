// Python: render() and validate(): a frame through EGL + OpenGL, and its check by ray casting
// (the same checks and report fields as `shadowvol validate`). GL builds only; without GL both
// raise InputError.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "py_common.h"
#include "shadowvol/memory_budget.h"
#include "shadowvol/capture_choice.h"
#include "shadowvol/capture_warnings.h"
#include "shadowvol/error.h"
#ifdef SHADOWVOL_WITH_GL
#include "shadowvol/embree/embree_depth_oracle.h"
#include "shadowvol/gl/renderer.h"
#include "shadowvol/image_io.h"
#include "shadowvol/output_lock.h"
#include "shadowvol/temporary_files.h"
#include "shadowvol/report_json.h"
#include "shadowvol/version.h"
#include "shadowvol/validate/gl_frame.h"
#include "shadowvol/validate/report_folder.h"
#include "shadowvol/validate/validation_report.h"
#endif

namespace shadowvol::python {

#ifdef SHADOWVOL_WITH_GL
namespace {

// A frame's arguments; the defaults are the Python functions' (registerValidate), against which
// the arguments a method would ignore are refused.
struct FrameArgs {
  std::string method = "hybrid", volume = "gpu", capture = "auto", triangulation = "perfect", cap = "exact",
              platform = "auto", count = "auto", crossings = "auto";
  int resolution = 512, refine = 0, refineGrid = 1;
  bool blur = false, chordPoints = false;
  double blurOffset = 0.0;
  std::optional<double> bias;
  std::optional<std::pair<int, int>> size;
};

gl::RenderOptions renderOptions(const FrameArgs& a, Scene& scene, bool scored) {
  gl::RenderOptions ro;
  if (!gl::parseShadowMethod(a.method, ro.method))
    throw InputError("python", "method", a.method, "expected " + choicesText(namesIn(kShadowMethodNames)));
  if (!gl::parseVolumeSource(a.volume, ro.volume)) throw InputError("python", "volume", a.volume, "expected " + choicesText(namesIn(kVolumeSourceNames)));
  checkResolutionArg(a.resolution, "resolution");
  checkWindowMapSize(a.resolution, a.resolution, "python", "resolution",
                     ro.method == gl::ShadowMethod::Hybrid ? DepthMapUse::Volume : DepthMapUse::ShadowMap);
  ro.depthWidth = ro.depthHeight = a.resolution;
  if (!gl::parseVolumeCount(a.count, ro.volumeCount)) throw InputError("python", "count", a.count, "expected " + choicesText(namesIn(kVolumeCountOptionNames)));
  if (a.crossings != "auto" && !parseRefineCrossings(a.crossings, ro.refineCrossings))
    throw InputError("python", "crossings", a.crossings,
                     "expected " + choicesText(namesIn(kRefineCrossingsNames, {"auto"})));
  // Arguments the method would ignore are refused, as the command line refuses their flags.
  const bool hybrid = ro.method == gl::ShadowMethod::Hybrid;
  const bool capturing = ro.method != gl::ShadowMethod::Silhouette && ro.method != gl::ShadowMethod::None;
  const FrameArgs defaults;
  const std::pair<bool, const char*> volumeOnly[] = {
      {a.blur, "blur"},   {a.refine != 0, "refine"},       {a.cap != "exact", "cap"},
      {a.triangulation != "perfect", "triangulation"},   {a.volume != defaults.volume, "volume"},
      {a.count != defaults.count, "count"},      {a.blurOffset != 0.0, "blur_offset"},
      {a.bias.has_value(), "bias"},               {a.refineGrid != 1, "refine_grid"},
      {a.chordPoints, "chord_points"},        {a.crossings != defaults.crossings, "crossings"}};
  for (const auto& [given, name] : volumeOnly)
    if (given && !hybrid)
      throw InputError("python", name, "", "shapes only the hybrid method's shadow volume, not method " + a.method + "'s");
  if (hybrid && a.crossings != defaults.crossings && a.refine == 0)  // as the command line's --crossings
    throw InputError("python", "crossings", a.crossings, "chooses where refinement finds its crossings: add refine=K");
  if (hybrid && a.crossings == "rays" && a.refine > 0 && a.volume == "gpu")  // as the command line's --crossings rays
    throw InputError("python", "crossings", a.crossings,
                     "the refined GPU volume finds its crossings on the GPU: use crossings gpu-rays (or auto) or "
                     "gpu-walk, or volume explicit for Embree's rays");
  for (const auto& [given, name] : {std::pair{a.refineGrid != 1, "refine_grid"}, std::pair{a.chordPoints, "chord_points"}})
    if (hybrid && given && a.refine > 0 && a.volume == "gpu")  // as the command line's
      throw InputError("python", name, "",
                       "needs rays (volume explicit, crossings rays): the refined GPU volume refines the boundary "
                       "edges' crossings alone");
  if (!capturing && a.capture != defaults.capture)
    throw InputError("python", "capture", a.capture, "chooses what a depth map records; method " + a.method + " captures none");
  if (!capturing && a.resolution != defaults.resolution)  // as the command line (without --fit view)
    throw InputError("python", "resolution", std::to_string(a.resolution),
                     "sizes the light's depth map; method " + a.method + " captures none");
  ro.volumeOptions = volumeOptionsArg(a.triangulation, a.blur, a.blurOffset, a.bias, a.cap, true, a.refine,
                                      a.chordPoints, a.refineGrid);
  ro.capture = capturing ? captureModeArg(a.capture, &scene, captureUse(ro)) : CaptureMode::Back;
  if (a.size) {
    const auto [w, h] = *a.size;
    if (w < 1 || h < 1 || w > 16384 || h > 16384)
      throw InputError("python", "size", std::to_string(w) + " x " + std::to_string(h), "each must be between 1 and 16384");
    scene.camera.width = w;
    scene.camera.height = h;
  }
  // As the command line: a frame too large for the machine is refused before it is allocated (a
  // probe's 16384 x 16384 ran 50 s into std::bad_alloc).
  checkFitsMemory(frameBytes(scene.camera.width, scene.camera.height, scored), "python", a.size ? "size" : "scene camera",
                  std::to_string(scene.camera.width) + " x " + std::to_string(scene.camera.height));
  return ro;
}

/// What the frame's depth maps record and why, and what they will miss (capture_warnings.h), as
/// validate's report.json says it: {"capture", "captureAuto" (auto's reason)}, and the warnings.
void describeCapture(const Scene& scene, const FrameArgs& a, const gl::RenderOptions& ro, nlohmann::json& options,
                     std::vector<std::string>& warnings) {
  if (ro.method == gl::ShadowMethod::Silhouette || ro.method == gl::ShadowMethod::None) return;
  options["capture"] = toString(ro.capture);
  if (a.capture == "auto") options["captureAuto"] = chooseCapture(scene, captureUse(ro)).reason;
  warnings = captureWarnings(scene, ro.depthWidth, ro.depthHeight, ro.capture);
}

/// The renderer of one call, with the scene's Embree rays when the options refine (the oracle must
/// outlive the render and the validation, which rebuilds the explicit volume).
struct FrameRenderer {
  std::unique_ptr<EmbreeDepthOracle> oracle;
  gl::Renderer renderer;

  FrameRenderer(const Scene& scene, gl::RenderOptions& ro, const std::string& platform)
  try : renderer(rendererOptions(platform)) {
    if (ro.volumeOptions.refineSteps > 0) {
      oracle = std::make_unique<EmbreeDepthOracle>(scene);
      ro.volumeOptions.depthOracle = oracle->oracle();
      ro.volumeOptions.surfaceEnds = oracle->surfaceEnds();  // the snap, as the command line
      ro.volumeOptions.nearerSurfaces = oracle->nearerSurfaces();  // the hidden-surface search, as the command line
      ro.volumeOptions.casterFaces = oracle->casterFaces();        // as the command line (no keyword sets it yet)
      ro.volumeOptions.withoutCasters = oracle->withoutCasters();  // the sheet hands their columns over
    }
    renderer.setScene(scene);
  } catch (const InputError& e) {  // the context's options (platform) by this module's keywords
    throw asPythonArgumentError(e);
  }
  static gl::RendererOptions rendererOptions(const std::string& platform) {
    gl::RendererOptions r;
    r.context.platform = platform;
    return r;
  }
};

// A frame, its options' refusals (RenderOptions, volume options) naming this module's keywords.
gl::RenderResult renderNamed(gl::Renderer& renderer, const gl::RenderOptions& ro) {
  try {
    return renderer.render(ro);
  } catch (const InputError& e) {
    throw asPythonArgumentError(e);
  }
}

py::array_t<std::uint8_t> imageArray(const std::vector<std::uint8_t>& bytes, int w, int h, int channels) {
  py::array_t<std::uint8_t> a(channels == 1 ? std::vector<py::ssize_t>{h, w} : std::vector<py::ssize_t>{h, w, channels});
  std::copy(bytes.begin(), bytes.end(), a.mutable_data());
  return a;
}

py::dict renderFrame(const PyScene& s, const FrameArgs& a) {
  Scene scene = s.scene;
  gl::RenderOptions ro = renderOptions(a, scene, false);
  gl::RenderResult result;
  std::string device;
  {
    py::gil_scoped_release release;
    FrameRenderer r(scene, ro, a.platform);
    result = renderNamed(r.renderer, ro);
    device = r.renderer.info().glRenderer;
  }
  py::dict d;
  d["image"] = imageArray(result.rgba, result.width, result.height, 4);
  if (!result.stencil.empty()) d["stencil"] = imageArray(result.stencil, result.width, result.height, 1);
  py::list others;  // a scene with several lights: the stencil of each light after the first
  for (const auto& l : result.otherLights)
    if (!l.stencil.empty()) others.append(imageArray(l.stencil, result.width, result.height, 1));
  if (!result.otherLights.empty()) d["other_stencils"] = others;
  py::dict passes;
  for (const auto& p : shadowvol::passTotals(result.passes)) passes[py::str(p.name)] = p.ms;  // per-face passes summed
  d["passes_ms"] = passes;
  d["total_ms"] = result.totalMs;
  d["timing"] = toString(result.timing);
  d["volume_triangles"] = result.volumeTriangles;
  // None where no volume is drawn (a shadow map), as `render --json` says null.
  d["volume_count"] = drawsShadowVolume(ro.method) ? py::object(py::str(gl::toString(result.volumeCountUsed)))
                                                       : py::object(py::none());
  d["gl_renderer"] = device;
  if (result.volumeStats) d["volume"] = toPython(describeVolumeStats(*result.volumeStats));
  nlohmann::json options;
  std::vector<std::string> warnings;
  describeCapture(scene, a, ro, options, warnings);
  d["options"] = toPython(options);
  d["warnings"] = toPython(warnings);
  return d;
}

// The report folder as `shadowvol validate --report` leaves it: an earlier report's files removed
// (a link among them replaced, not written through: a fifteenth probe's finding), each light's
// images, then report.json last; under the folder's lock, and none of this run's files left when
// a write fails or a signal ends the process half-way.
void writeReportFolder(const std::filesystem::path& dir, const std::vector<LightValidation>& lights,
                       const gl::RenderResult& frame, const nlohmann::json& report) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw InputError("python", "report_dir", dir.string(), "cannot create the folder" + (ec ? ": " + ec.message() : ""));
  const OutputLock lock(dir);
  removeReportFiles(dir);
  const OutputSetGuard set;
  try {
    if (lights.size() > 1) writePng(dir / "frame.png", frame.width, frame.height, 4, frame.rgba);  // every light's
    for (std::size_t k = 0; k < lights.size(); ++k) {
      const std::filesystem::path sub = lights.size() == 1 ? dir : lightReportFolder(dir, k);
      std::filesystem::create_directories(sub, ec);
      if (ec || !std::filesystem::is_directory(sub))
        throw InputError("python", "report_dir", dir.string(),
                         "cannot create the folder " + sub.string() + (ec ? ": " + ec.message() : ""));
      writeValidationImages(sub, lights[k].validation, lights[k].frame);
    }
    writeReportJson(dir, report);
  } catch (...) {
    removeReportFiles(dir);
    throw;
  }
}

py::dict validateFrameArgs(const PyScene& s, const FrameArgs& a, double maxError, double maxMissed,
                           bool selfIntersections, const std::optional<std::filesystem::path>& reportDir) {
  Scene scene = s.scene;
  gl::RenderOptions ro = validationRenderOptions(renderOptions(a, scene, true));
  ValidationOptions vo;
  vo.selfIntersections = selfIntersections;
  if (!(maxError >= 0.0 && maxError <= 1.0)) throw InputError("python", "max_error", numberText(maxError), "must be in [0, 1]");
  if (!(maxMissed >= 0.0 && maxMissed <= 1.0)) throw InputError("python", "max_missed", numberText(maxMissed), "must be in [0, 1]");
  vo.maxError = maxError;
  vo.maxMissedShare = maxMissed;
  if (reportDir && reportDir->empty())  // before the work, as the command line's --report ""
    throw InputError("python", "report_dir", "\"\"", "an output folder is required (or None: no report files)");
  if (reportDir && scene.lightCount() > 1)  // before the work, as the command line
    for (std::size_t k = 0; k < scene.lightCount(); ++k) lightReportFolder(*reportDir, k);
  if (reportDir) {
    std::error_code ec;
    if (std::filesystem::exists(*reportDir, ec) && !std::filesystem::is_directory(*reportDir, ec))
      throw InputError("python", "report_dir", reportDir->string(), "exists and is not a folder");
  }
  if (reportDir && std::filesystem::is_directory(*reportDir)) {  // an earlier report goes before the work
    py::gil_scoped_release release;  // other threads run while another run's lock is waited for
    const OutputLock lock(*reportDir);
    removeReportFiles(*reportDir);
  }
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    FrameRenderer r(scene, ro, a.platform);
    const gl::RenderResult result = renderNamed(r.renderer, ro);
    const std::vector<LightValidation> lights = validateEveryLight(scene, ro, result, vo);
    if (lights.size() == 1) {
      j = describeLightValidation(lights[0], ro, vo);
    } else {  // as validate's report.json: one section per light, the verdict over all
      bool passed = true;
      j["lights"] = nlohmann::json::array();
      for (std::size_t k = 0; k < lights.size(); ++k) {
        j["lights"].push_back(describeLightSection(scene, k, lights[k], ro, describeLightValidation(lights[k], ro, vo)));
        passed = passed && lights[k].validation.passed;
      }
      describeSeveralLightsVerdict(passed, j);
    }
    j["scene"] = describeScene(scene);
    j["gl"] = gl::describeContext(r.renderer.info());  // as the command line's report
    j["sceneWarnings"] = s.warnings;
    j["shadowvolVersion"] = SHADOWVOL_VERSION;
    nlohmann::json options = nlohmann::json::object();
    std::vector<std::string> warnings;
    describeCapture(scene, a, ro, options, warnings);
    j["options"] = options;
    j["warnings"] = warnings;
    if (reportDir) {
      {  // a Ctrl-C during the work: no files (a fifteenth probe's wrote them all, then raised)
        py::gil_scoped_acquire gil;
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      }
      writeReportFolder(*reportDir, lights, result, j);
    }
  }
  return toPython(j).cast<py::dict>();
}

}  // namespace
#endif

void registerValidate(py::module_& m) {
#ifdef SHADOWVOL_WITH_GL
  auto frameArgs = [](std::string method, std::string volume, StrictInt resolution, std::string capture,
                      std::string triangulation, bool blur, std::string cap, StrictInt refine,
                      std::optional<std::pair<StrictInt, StrictInt>> size, std::string platform, std::string count,
                      double blurOffset, std::optional<double> bias, StrictInt refineGrid, bool chordPoints,
                      std::string crossings) {
    FrameArgs a;
    a.method = std::move(method);
    a.volume = std::move(volume);
    a.resolution = resolution;
    a.capture = std::move(capture);
    a.triangulation = std::move(triangulation);
    a.blur = blur;
    a.cap = std::move(cap);
    a.refine = refine;
    a.size = size;
    a.platform = std::move(platform);
    a.count = std::move(count);
    a.blurOffset = blurOffset;
    a.bias = bias;
    a.refineGrid = refineGrid;
    a.chordPoints = chordPoints;
    a.crossings = std::move(crossings);
    return a;
  };
  m.def(
      "render",
      [frameArgs](const PyScene& s, std::string method, std::string volume, StrictInt resolution, std::string capture,
                  std::string triangulation, bool blur, std::string cap, StrictInt refine,
                  std::optional<std::pair<StrictInt, StrictInt>> size, std::string platform, std::string count,
                  double blurOffset, std::optional<double> bias, StrictInt refineGrid, bool chordPoints,
                  std::string crossings) {
        return renderFrame(s, frameArgs(method, volume, resolution, capture, triangulation, blur, cap, refine, size,
                                        platform, count, blurOffset, bias, refineGrid, chordPoints, crossings));
      },
      py::arg("scene"), py::kw_only(), py::arg("method") = "hybrid", py::arg("volume") = "gpu",
      py::arg("resolution") = 512, py::arg("capture") = "auto", py::arg("triangulation") = "perfect",
      py::arg("blur").noconvert() = false, py::arg("cap") = "exact", py::arg("refine") = 0, py::arg("size") = py::none(),
      py::arg("platform") = "auto", py::arg("count") = "auto", py::arg("blur_offset") = 0.0,
      py::arg("bias") = py::none(), py::arg("refine_grid") = 1, py::arg("chord_points").noconvert() = false,
      py::arg("crossings") = "auto",
      "Renders one frame with the scene's camera (headless EGL + OpenGL), as `shadowvol render` does. Returns a "
      "dict: image (H x W x 4 uint8, top row first), stencil (H x W uint8, shadow-volume methods), passes_ms, "
      "total_ms, timing, volume_triangles, volume_count (z-pass or z-fail; None for a method that draws no volume), gl_renderer, volume (explicit volume's "
      "build stats), options (capture, and captureAuto: why capture='auto', the default, chose it), warnings (what "
      "the depth map will miss), and with several lights other_stencils (each further light's stencil; `stencil` is the first's, "
      "the image every light's). size=(W, H); count: auto, zfail or zpass (`--count`); blur_offset, bias, refine_grid "
      "and chord_points shape the hybrid volume as build_volume's do (`--blur-offset`, `--bias`, `--refine-grid`, "
      "`--chord-points`); crossings: where refinement finds its crossings (`--crossings`: auto, rays, gpu-walk or "
      "gpu-rays).");
  m.def(
      "validate",
      [frameArgs](const PyScene& s, std::string method, std::string volume, StrictInt resolution, std::string capture,
                  std::string triangulation, bool blur, std::string cap, StrictInt refine,
                  std::optional<std::pair<StrictInt, StrictInt>> size, std::string platform, std::string count, double maxError,
                  double maxMissed, bool selfIntersections, std::optional<std::filesystem::path> reportDir,
                  double blurOffset, std::optional<double> bias, StrictInt refineGrid, bool chordPoints,
                  std::string crossings) {
        return validateFrameArgs(s,
                                 frameArgs(method, volume, resolution, capture, triangulation, blur, cap, refine, size,
                                           platform, count, blurOffset, bias, refineGrid, chordPoints, crossings),
                                 maxError, maxMissed, selfIntersections, reportDir);
      },
      py::arg("scene"), py::kw_only(), py::arg("method") = "hybrid", py::arg("volume") = "gpu",
      py::arg("resolution") = 512, py::arg("capture") = "auto", py::arg("triangulation") = "perfect",
      py::arg("blur").noconvert() = false, py::arg("cap") = "exact", py::arg("refine") = 0, py::arg("size") = py::none(),
      py::arg("platform") = "auto", py::arg("count") = "auto", py::arg("max_error") = kDefaultMaxError,
      py::arg("max_missed") = kDefaultMaxMissedShare, py::arg("self_intersections").noconvert() = false,
      py::arg("report_dir") = py::none(), py::arg("blur_offset") = 0.0, py::arg("bias") = py::none(),
      py::arg("refine_grid") = 1, py::arg("chord_points").noconvert() = false, py::arg("crossings") = "auto",
      "Renders a frame and checks it by ray casting, as `shadowvol validate` does: returns the report as a dict "
      "(pixels, meshChecks, stencilVsCount, zfailVsZpass, againstExact, errorCauses, leaks, verdict, passed, scene, volume, options: "
      "capture and captureAuto, warnings); capture='auto' (the default) as `--capture auto`; with "
      "several lights those checks are per light in `lights` (index, pointer, type, ...) and `passed` is over all. "
      "report_dir: also write the report there as `shadowvol validate --report` does (an earlier report's "
      "files removed; the PNGs: exact, stencil, count, overlay, frame, light-K/ per light; report.json, this dict, "
      "last); a Ctrl-C during the work writes nothing.");
#else
  m.def(
      "validate", [](py::args, py::kwargs) -> py::dict {
        throw InputError("python", "validate", "", "this shadowvol was built without GL (SHADOWVOL_BUILD_GL=OFF)");
      });
  m.def(
      "render", [](py::args, py::kwargs) -> py::dict {
        throw InputError("python", "render", "", "this shadowvol was built without GL (SHADOWVOL_BUILD_GL=OFF)");
      });
#endif
}

}  // namespace shadowvol::python

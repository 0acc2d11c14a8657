// shadowvol validate: render a frame on the GPU, then check it by ray casting (Embree) and the
// volume by CGAL; writes DIR/report.json and pictures. Exit 0 when the stencil and the crossing
// counts agree on >= 99.99 % of visible pixels and the mesh checks pass, 3 otherwise.
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "cli_verbosity.h"
#include "render_options.h"
#include "shadowvol/dual_paraboloid.h"
#include "shadowvol/error.h"
#include "shadowvol/image_io.h"
#include "shadowvol/mesh_io.h"
#include "shadowvol/output_lock.h"
#include "shadowvol/report_json.h"
#include "shadowvol/temporary_files.h"
#include "shadowvol/validate/frame_validation.h"
#include "shadowvol/validate/gl_frame.h"
#include "shadowvol/validate/report_folder.h"
#include "shadowvol/validate/validation_report.h"
#include "shadowvol/version.h"

namespace shadowvol::cli {
namespace {

// Where this frame's refinement found its crossings ("none" without refinement: a report holds no
// null, which reads as a non-finite number): the explicit
// volume's choice, or the refined GPU volume's (the walk, or its own rays for any other choice).
nlohmann::json crossingsUsed(const gl::RenderOptions& ro) {
  if (ro.method != gl::ShadowMethod::Hybrid || ro.volumeOptions.refineSteps == 0) return "none";
  if (ro.volume == gl::VolumeSource::Explicit) return gl::toString(ro.refineCrossings);
  return ro.refineCrossings == gl::RefineCrossings::GpuWalk ? "gpu-walk" : "gpu-rays";
}

// One light's checks as text (`j`: its describeLightValidation).
void printLightValidation(const LightValidation& c, const gl::RenderOptions& ro, const nlohmann::json& j) {
  const gl::RenderResult& result = *c.result;
  const FrameValidation& v = c.validation;
  std::printf("  pixels: %zu visible, %zu facing away, %zu outside the light, %zu background\n", v.visible,
              v.facingAway, v.outsideLight, v.background);
  if (result.gpuVolumeDrawUsed == gl::GpuVolumeDraw::Refined && result.volumeStats)
    std::printf(
        "  refinement on the GPU: %zu boundary edges refined, %zu without a crossing found; the CPU "
        "mesh has the GPU's edges (%zu, %zu of them without a crossing), the CPU rule on the read-back "
        "map differs on %zu\n",
        result.gpuBoundaryEdges, result.gpuCrossingFallbacks, result.volumeStats->boundaryEdges,
        result.volumeStats->crossingFallbacks, result.cpuRuleEdgeDifferences);
  else if (result.gpuVolumeDrawUsed == gl::GpuVolumeDraw::Refined)  // a point light's six face volumes
    std::printf(
        "  refinement on the GPU, %zu face volumes: %zu boundary edges refined, %zu without a crossing "
        "found; the CPU rule on the read-back maps differs on %zu\n",
        result.faceVolumes.size(), result.gpuBoundaryEdges, result.gpuCrossingFallbacks, result.cpuRuleEdgeDifferences);
  else if (result.volumeStats && result.volumeStats->refinedCells > 0)
    std::printf(
        "  refinement: %zu boundary edges, %zu rays, %zu without a crossing found, %zu crossings snapped, "
        "%.2f ms\n",
        result.volumeStats->boundaryEdges, result.volumeStats->raysCast, result.volumeStats->crossingFallbacks,
        result.volumeStats->snappedCrossings, result.volumeStats->msRefine);
  if (v.meshCheck) {
    std::printf("  mesh: %s\n", v.meshCheck->summary().c_str());
    if (v.gpuMeshCheck) std::printf("  GPU volume's own mesh: %s\n", v.gpuMeshCheck->summary().c_str());
    std::printf(
        "  stencil (%s) vs count: %.4f%% agree (%zu of %zu%s, %zu of them ties on the visible surface, "
        "%zu in the image plane)\n",
        gl::toString(result.volumeCountUsed), 100 * v.stencilVsCount.fraction(), v.stencilVsCount.agree,
        v.stencilVsCount.pixels, v.stencilOverLitFrustumOnly ? " inside the light's frustum" : "",
        v.stencilVsCount.ties - v.stencilVsCount.imagePlaneTies, v.stencilVsCount.imagePlaneTies);
    for (const Agreement::Miss& m : v.stencilVsCount.firstMisses)
      std::printf("    disagrees at pixel (%d, %d) (row 0 at the top): stencil %d, count %d (admissible %d to %d)\n",
                  m.x, m.row, m.stencil, m.zfail, m.zfailMin, m.zfailMax);
    if (v.zfailVsZpass)
      std::printf("  z-fail vs z-pass: %.4f%% agree\n", 100 * v.zfailVsZpass->fraction());
    else
      std::printf("  z-fail vs z-pass: not applicable (the eye is inside the volume)\n");
  }
  std::printf("  against exact: missed %zu (%.3f%%), false %zu (%.3f%%) of %zu pixels facing the light\n",
              v.methodError.missed, 100 * v.methodError.missedFraction(), v.methodError.falseShadow,
              100 * v.methodError.falseFraction(), v.methodError.pixels);
  if (v.lostShadows.missedSelf + v.lostShadows.missedOnOthers > 0)
    std::printf("  missed by place: %zu on the object that shadows them (self-shadows), %zu on other objects\n",
                v.lostShadows.missedSelf, v.lostShadows.missedOnOthers);
  if (v.errorCauses) {
    std::printf(
        "  errors by cause: %zu of resolution (the same capture at unlimited resolution gets them right: a "
        "finer map, refinement or --fit view can help), %zu of capture (it gets them wrong too: capture mode, "
        "bias or mesh)",
        v.errorCauses->resolution, v.errorCauses->capture);
    if (v.errorCauses->border > 0)
      std::printf(", %zu at the light window's border (the volume's outermost texel ring lies on the far plane: "
                  "a wider light window, extent or fov, or a finer map narrows that band; refinement does not)",
                  v.errorCauses->border);
    std::printf("\n");
  }
  if (v.leaks && v.leaks->deep > 0)
    std::printf("  missed deep inside the exact shadow: %zu pixels (at most %zu allowed: further from the outline than "
                "the method's texels and depth offset reach)\n",
                v.leaks->deep, kMaxLeakPixels);
  if (ro.method == gl::ShadowMethod::Dpsm) {
    const nlohmann::json& d = j["dualParaboloid"];
    std::printf(
        "  dual-paraboloid maps: 2 x %d^2 texels, %.1f%% in use, texel solid angle %.3g to %.3g sr "
        "(x%.2f); the cube map at %d^2: %.3g to %.3g sr (x%.2f); coarsest texel x%.2f the cube's\n",
        d["side"].get<int>(), 100 * d["usedFraction"].get<double>(), d["smallestTexelSr"].get<double>(),
        d["largestTexelSr"].get<double>(), d["largestOverSmallest"].get<double>(), ro.depthWidth,
        d["cubeMap"]["smallestTexelSr"].get<double>(), d["cubeMap"]["largestTexelSr"].get<double>(),
        d["cubeMap"]["largestOverSmallest"].get<double>(), d["largestTexelOverCubes"].get<double>());
  }
  if (ro.method == gl::ShadowMethod::Silhouette && !result.receiversOnly.empty()) {
    std::printf("  cast no silhouette shadow (open, receivers only):");
    for (const auto& name : result.receiversOnly) std::printf(" \"%s\"", name.c_str());
    std::printf("\n");
  }
  if (!v.meshChecksNotApplicable.empty()) std::printf("  not applicable: %s\n", v.meshChecksNotApplicable.c_str());
  for (const auto& f : v.failures) std::printf("  failed: %s\n", f.c_str());
}

}  // namespace

void registerValidateCommand(CLI::App& app, Runner& run) {
  struct Options {
    RenderCliOptions render;
    std::string reportDir;
    bool selfIntersections = false;
    double maxError = kDefaultMaxError;
    double maxMissedShare = kDefaultMaxMissedShare;
    double exactOffsetScale = 0.0;
  };
  auto o = std::make_shared<Options>();
  o->render.scored = true;  // the frame is scored against exact shadow rays (memory a pixel)
  auto* cmd = app.add_subcommand(
      "validate",
      "Render a frame on the GPU and check it by ray casting: Embree's signed crossing counts of the explicit volume "
      "against the GPU stencil, z-fail against z-pass, and every shadow test against exact shadow rays; CGAL checks "
      "of the volume. Writes DIR/report.json and PNGs. Exit 0 when the frame is consistent (stencil and counts "
      "agree on >= 99.99% of visible pixels, the mesh checks pass) and accurate (the method's error within "
      "--max-error and --max-missed, over the whole shadow and over each object's shadow of at least 32 pixels; no "
      "hole: at most 16 missed pixels deep inside the exact shadow, further from its outline than the method's "
      "texels and depth offset reach; and for a shadow volume at most 16 missed in the band the light window's "
      "border ring lights), 3 otherwise, naming what failed");
  addRenderOptions(*cmd, o->render);
  cmd->add_option("--report", o->reportDir, "Folder for report.json and the images (created if missing)")->required();
  cmd->add_flag("--self-intersections", o->selfIntersections,
                "Also run CGAL's self-intersection check of the volume (slow on large meshes)");
  cmd->add_option("--max-error", o->maxError,
                  "Accuracy verdict: the largest fraction of the pixels facing the light that the method may "
                  "misclassify against exact shadows (every shipped scene meets the default with the default method)")
      ->check(finiteRange(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--max-missed", o->maxMissedShare,
                  "Accuracy verdict: the largest share of the exact shadow's pixels the method may miss (judged when "
                  "the exact shadow has at least 100 pixels; an empty volume misses all of it), and of each object's "
                  "shadow of at least 32 pixels (the object its exact shadow ray meets first: a thin occluder's lost "
                  "shadow)")
      ->check(finiteRange(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--exact-offset-scale", o->exactOffsetScale,
                  "The exact shadow rays' start off the surface, as a multiple in [0, 1] of the legacy offset (1e-4 "
                  "of the scene's radius). 0 = the sharp reference (rays start just above round-off and skip the "
                  "triangle they leave); 1 repeats figures measured before 2026-12-06, whose offset called lit a "
                  "band of shadowed points along shadows' outlines (docs/results/reference-offset)")
      ->check(finiteRange(0.0, 1.0))
      ->capture_default_str();
  cmd->callback([&run, o] {
    checkRenderOptionConflicts(o->render);
    run = [o] {
      const std::filesystem::path dir(o->reportDir);
      checkOutputFolder("--report", o->reportDir);
      std::vector<std::string> sceneWarnings;  // what loading noticed, kept in the report
      Scene scene = loadSceneOrDefault(o->render.scene.scene, &sceneWarnings);
      for (const char* name : reportFileNames())
        checkNotAnInput("--report", o->reportDir, dir / name, scene.files, "its file");
      if (scene.lightCount() > 1)  // before the work (a second reader's finding)
        for (std::size_t k = 0; k < scene.lightCount(); ++k) lightReportFolder(dir, k);
      std::string captureAuto;
      gl::RenderOptions ro = toRenderOptions(o->render, scene, &captureAuto);
      const nlohmann::json lightFit = applyLightFit(scene, o->render.scene, o->render.resolution);
      const auto oracle = attachDepthOracle(scene, ro);
      std::vector<std::string> warnings;
      if (capturesMap(ro)) warnings = warnAboutCapture(scene, ro.depthWidth, ro.depthHeight, ro.capture, &ro.volumeOptions);
      ro = validationRenderOptions(ro);
      // An earlier run's report goes before the work (a probe's finding: a crash left the last
      // run's PASSED in place for a script to read); the inputs are checked by now.
      if (std::filesystem::is_directory(dir)) {
        const OutputLock lock(dir);  // not while another run writes its set here
        removeReportFiles(dir);
      }
      gl::Renderer renderer(toRendererOptions(o->render));
      verboseNote("GL context: %s, %s (EGL platform %s)", renderer.info().glRenderer.c_str(),
                  renderer.info().glVersion.c_str(), renderer.info().platform.c_str());
      renderer.setScene(scene);
      const gl::RenderResult result = renderer.render(ro);
      ValidationOptions vo;
      vo.selfIntersections = o->selfIntersections;
      vo.maxError = o->maxError;
      vo.maxMissedShare = o->maxMissedShare;
      vo.exactOffsetScale = o->exactOffsetScale;
      // Each light's checks on a scene with that light alone (the shadows are per light; the
      // image is the frame's, every light's diffuse term added).
      const std::vector<LightValidation> checks = validateEveryLight(scene, ro, result, vo);
      bool passed = true;
      for (const LightValidation& c : checks) passed = passed && c.validation.passed;
      const bool hybrid = checks[0].frame.hybrid;

      nlohmann::json j;
      j["scene"] = describeScene(scene);
      j["gl"] = gl::describeContext(renderer.info());
      j["options"] = {{"method", o->render.method},
                      {"volume", hybrid ? nlohmann::json(gl::toString(ro.volume)) : nlohmann::json()},
                      {"depthFrom", depthFromUsed(o->render, ro, result)},
                      {"resolution", o->render.resolution},
                      
                      {"triangulation", o->render.shape.triangulation},
                      {"blur", o->render.shape.blur},
                      {"blurOffset", o->render.shape.blurOffset},
                      {"bias", result.biasUsed},
                      {"cap", o->render.shape.cap},
                      {"refine", o->render.shape.refine},
                      {"crossings", crossingsUsed(ro)},
                      {"shadowBias", shadowMapBias(scene.light, ro)},
                      {"shadowSlope", o->render.shadowSlope},
                      {"dpsmSubdivide", o->render.dpsmSubdivide},
                      {"selfIntersections", o->selfIntersections},
                      {"exactOffsetScale", o->exactOffsetScale}};
      if (capturesMap(ro)) j["options"]["capture"] = toString(ro.capture);  // silhouette and none capture no map
      if (!captureAuto.empty()) j["options"]["captureAuto"] = captureAuto;   // --capture auto's reason
      if (o->render.shape.refineGrid > 1) {  // the sub-grid, and whether it searched for hidden surfaces
        j["options"]["refineGrid"] = o->render.shape.refineGrid;
        j["options"]["refineHidden"] = !o->render.shape.noHiddenSearch;
      }
      std::vector<std::string> images = {"frame.png", "exact.png",   "stencil.png",
                                         "count.png", "overlay.png", "overlay.svg"};
      if (!hybrid) images = {"frame.png", "exact.png", "overlay.png", "overlay.svg"};
      std::vector<nlohmann::json> sections;
      for (std::size_t k = 0; k < checks.size(); ++k) sections.push_back(describeLightValidation(checks[k], ro, vo));
      if (checks.size() == 1) {
        j.update(sections[0]);
      } else {
        // Several lights: one section per light (its images in light-K/), the verdict over all.
        j["lights"] = nlohmann::json::array();
        for (std::size_t k = 0; k < checks.size(); ++k)
          j["lights"].push_back(describeLightSection(scene, k, checks[k], ro, sections[k]));
        describeSeveralLightsVerdict(passed, j);
      }
      j["warnings"] = warnings;
      j["sceneWarnings"] = sceneWarnings;
      j["lightFit"] = lightFit;
      j["shadowvolVersion"] = SHADOWVOL_VERSION;
      j["images"] = checks.size() == 1 ? images : std::vector<std::string>{"frame.png"};

      // Everything is computed; now write. A previous run's files go first (its report before
      // its images), then the images, the report last (its presence means done); a write that
      // fails takes this run's files with it.
      createFolders(dir);
      const OutputLock lock(dir);  // another run's set is written before or after this one, not amid it
      removeReportFiles(dir);
      const OutputSetGuard set;  // a signal that ends the run half-way removes this run's files too
      try {
        if (checks.size() == 1) {
          writeValidationImages(dir, checks[0].validation, checks[0].frame);
        } else {
          writePng(dir / "frame.png", result.width, result.height, 4, result.rgba);
          for (std::size_t k = 0; k < checks.size(); ++k) {
            const std::filesystem::path sub = lightReportFolder(dir, k);
            createFolders(sub);
            writeValidationImages(sub, checks[k].validation, checks[k].frame);
          }
        }
        writeReportJson(dir, j);
      } catch (...) {
        removeReportFiles(dir);
        throw;
      }
      if (o->render.scene.json) {
        std::cout << jsonText(j) << '\n';
      } else {
        std::printf("validate %s (%s%s%s) on %s\n", scene.source.c_str(), o->render.method.c_str(), hybrid ? ", " : "",
                    hybrid ? gl::toString(ro.volume) : "", renderer.info().glRenderer.c_str());
        for (std::size_t k = 0; k < checks.size(); ++k) {
          if (checks.size() > 1)
            std::printf(" light %zu (%s, %s): %s\n", k, toString(scene.lightAt(k).type), scene.lightPointer(k).c_str(),
                        checks[k].validation.passed ? "passed" : "failed");
          printLightValidation(checks[k], ro, checks.size() == 1 ? j : j["lights"][k]);
        }
        std::printf("%s: wrote %s\n", passed ? "PASSED" : "FAILED", (dir / "report.json").string().c_str());
      }
      return passed ? kOk : kValidationFailed;
    };
  });
}

}  // namespace shadowvol::cli

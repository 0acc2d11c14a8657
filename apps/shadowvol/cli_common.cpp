#include "cli_common.h"
#include "cli_errors.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>

#include <fcntl.h>
#include <unistd.h>

#include "shadowvol/volume_builder.h"
#include "shadowvol/capture_choice.h"
#include "shadowvol/capture_warnings.h"
#include "cli_verbosity.h"
#include "shadowvol/error.h"

namespace shadowvol::cli {

void addJsonOption(CLI::App& cmd, bool& json) {
  cmd.add_flag("--json", json, "Print one JSON document with the results on stdout (text otherwise)");
}

void addSceneOptions(CLI::App& cmd, SceneOptions& o) {
  cmd.add_option("--scene", o.scene,
                 "Scene file (JSON, see README 'Scene files'); without it, the built-in default scene "
                 "(a sphere floating above a ground plane under a spot light)")
      ->check(CLI::Validator(
          [](std::string& path) -> std::string {
            return path.empty() ? "an empty path: name a scene file, or leave --scene out for the built-in scene" : "";
          },
          "FILE"));
  addJsonOption(cmd, o.json);
}

void addLightFitOption(CLI::App& cmd, std::string& fit) {
  cmd.add_option("--fit", fit,
                 "Light frustum: scene (fitted to the whole scene) or view (narrowed to the receivers the camera "
                 "sees: a spot light re-aims and narrows inside its cone, a directional light shrinks its window; "
                 "more texels where they show, a volume that depends on the camera)")
      ->check(CLI::IsMember(namesIn(kLightFitNames)))
      ->capture_default_str();
}

namespace {

// applyLightFit for the scene's light (Scene::light); `label` names it in the text ("light",
// "light 1").
nlohmann::json applyLightFitToOne(Scene& scene, const SceneOptions& o, int resolution, const std::string& label) {
  LightFit fit = LightFit::Scene;
  parseLightFit(o.fit, fit);
  nlohmann::json j = {{"fit", o.fit}};
  if (fit == LightFit::View) {
    const LightFitResult r = fitLightToView(scene, resolution);
    j["changed"] = r.changed;
    j["note"] = r.note;
    j[scene.light.type == LightType::Spot ? "fovBefore" : "extentBefore"] = r.windowBefore;
    verboseNote("%s", r.note.c_str());
  }
  const auto texel = receiverTexelSize(scene, resolution);
  j["texelOnReceivers"] = texel ? nlohmann::json::array({texel->first, texel->second}) : nlohmann::json();
  if (!o.json) {
    std::printf("%s (--fit %s)%s%s: texel on the receivers ", label.c_str(), o.fit.c_str(),
                j.contains("note") ? ", " : "", j.contains("note") ? j["note"].get<std::string>().c_str() : "");
    if (texel) std::printf("%.3g to %.3g world units at %d x %d\n", texel->first, texel->second, resolution, resolution);
    else std::printf("unknown (the camera sees none of the lit scene)\n");
  }
  return j;
}

}  // namespace

nlohmann::json applyLightFit(Scene& scene, const SceneOptions& o, int resolution) {
  if (scene.lightCount() == 1) return applyLightFitToOne(scene, o, resolution, "light");
  nlohmann::json j = {{"fit", o.fit}, {"lights", nlohmann::json::array()}};
  forEachLight(scene, [&](std::size_t k) {
    j["lights"].push_back(applyLightFitToOne(scene, o, resolution, "light " + std::to_string(k)));
  });
  return j;
}

void addLightChoiceOption(CLI::App& cmd, int& light) {
  cmd.add_option("--light", light,
                 "Which light of a scene with several (its index in the scene's `lights`, from 0): this command "
                 "works on one light's depth map")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            char* end = nullptr;
            const long v = std::strtol(text.c_str(), &end, 10);
            if (text.empty() || *end != '\0') return "not a light index (a whole number from 0): " + text;
            if (v < 0) return "a light index counts from 0, not " + text;
            return {};
          },
          "INDEX"))
      ->capture_default_str();
}

CLI::Validator finiteRange(double lo, double hi) {
  std::ostringstream name;
  name << "FLOAT in [" << lo << " - " << hi << "]";
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size()) return "not a number: " + text;
        if (!(v >= lo && v <= hi)) {  // NaN fails both comparisons
          std::ostringstream why;
          why << "value " << text << " not in range [" << lo << " - " << hi << "]";
          return why.str();
        }
        return {};
      },
      name.str());
}

void chooseLight(Scene& scene, int light) {
  if (std::size_t(light) >= scene.lightCount())
    throw InputError("command line", "--light", std::to_string(light),
                     "the scene has " + std::to_string(scene.lightCount()) + (scene.lightCount() == 1 ? " light" : " lights") +
                         " (0 to " + std::to_string(scene.lightCount() - 1) + ")");
  if (scene.lightCount() > 1 && light == 0)
    std::fprintf(stderr, "shadowvol: note: %s has %zu lights; this command takes light 0 (--light K picks another)\n",
                 scene.source.c_str(), scene.lightCount());
  if (scene.lightCount() > 1) scene = scene.withOnlyLight(std::size_t(light));
}

CLI::Option* addVolumeOptions(CLI::App& cmd, VolumeCliOptions& o) {
  cmd.add_option("--triangulation", o.triangulation,
                 "Quad diagonals: perfect (per quad, the diagonal avoids the odd vertex: smoother shadow edges) or "
                 "fixed (one diagonal everywhere, the thesis's strips)")
      ->check(CLI::IsMember(namesIn(kTriangulationNames)))
      ->capture_default_str();
  cmd.add_flag("--blur", o.blur, "Depth blurring: each depth becomes the mean of 9 bilinear samples 1.5 texels apart");
  cmd.add_option("--blur-offset", o.blurOffset,
                 "World units (>= 0) added to blurred depths, away from the light (with --blur)")
      ->capture_default_str();
  cmd.add_option("--bias", o.bias,
                 "World units pushing the sheet away from the light; default: 0 for back and midpoint capture, the "
                 "texel footprint plus depth precision for front and entry capture (README 'Volume mesh')");
  cmd.add_option("--cap", o.cap,
                 "Far cap: exact (drop far-plane parts, close each region with a flattened far cap) or quad (the "
                 "thesis's far rectangle; closed but with coincident faces, for comparison)")
      ->check(CLI::IsMember(namesIn(kFarCapNames)))
      ->capture_default_str();
  cmd.add_flag("--chord-points", o.chordPoints,
               "With --refine: bend the wall of each quad with two boundary edges at one more crossing inside it (K "
               "more rays per such quad), so it follows curved outlines: less error on real meshes, more rays, cap "
               "vertices and wall triangles; not with --refine-grid above 1, which bends walls its own way (README "
               "'Silhouette refinement')");
  cmd.add_option("--refine-grid", o.refineGrid,
                 "With --refine: sample the depth at the corners of S x S sub-cells (S = 2, 4 or 8; 1 = off) in each "
                 "quad with a boundary edge, and where those samples or one more crossing show that the quad's "
                 "straight wall misses the outline, cut the quad into the sub-cells and refine each, so the wall "
                 "follows an outline that bends inside a texel; about S^2 more rays in each such quad, S^2 more "
                 "triangles in the cut ones; not with --chord-points, nor for a point light (docs/volume.md 'Sub-grid')")
      ->check(CLI::IsMember({1, 2, 4, 8}))
      ->capture_default_str();
  cmd.add_flag("--refine-grid-everywhere", o.refineGridEverywhere,
               "With --refine-grid: cut every quad with a boundary edge, also those whose straight wall already lies "
               "on the sub-grid's samples (which the default leaves plain); for comparison, more triangles");
  cmd.add_flag("--no-hidden-search", o.noHiddenSearch,
               "With --refine-grid: do not look for surfaces hidden between the texel centres (an occluder thinner "
               "than a texel that no sample sees: a limb, a wire, a ridge) or for gaps there (an open mesh's rim: "
               "a hole, a sheet's edge), which by default also go on the sub-grid, found from the scene's "
               "triangles without rays; for comparison (docs/volume.md 'Hidden surfaces')");
  cmd.add_flag("--face-prisms", o.facePrisms,
               "With --refine: add the prisms of the closed meshes' faces turned towards the light in the columns "
               "of the refined quads (each region of such faces whole), from each face to the far plane, as a "
               "second closed part of the volume, and hand those columns over to them (the sheet records the "
               "scene without those meshes there): the mesh's own shadow where the sheet between texel centres "
               "cannot follow it (a thin part's self-shadow, an outline); more triangles, set by the faces "
               "taken; spot and directional lights (docs/volume.md 'Face prisms')");
  cmd.add_flag("--no-snap", o.noSnap,
               "With --refine: leave each crossing in the middle of its last bisection bracket (within 2^-(K+1) "
               "texel of the outline) instead of moving it to where the triangle recorded on its near side ends "
               "(found by up to 6 more rays; exact on polygonal meshes), for comparison (docs/volume.md 'Snap')");
  return cmd
      .add_option("--refine", o.refine,
                  "Sub-texel silhouette refinement: K bisection rays (Embree, into the same scene) per boundary edge "
                  "put each wall on the light ray within 2^-(K+1) texel of where the surface ends; 0 = off, 6 is what "
                  "the sweep uses (README 'Silhouette refinement'). Needs --cap exact (docs/volume.md "
                  "'Refinement'). In render and validate with --volume gpu the GPU casts the same K rays per edge "
                  "itself (bench: hybrid-refined/gpu), or walks over the scene's triangles with --crossings "
                  "gpu-walk (exact: K > 0 only switches it on; bench: hybrid-refined-walk/gpu); back, front or entry "
                  "capture (the walk: back or front) (docs/gpu.md 'The refined GPU volume')")
      ->check(CLI::Range(0, kMaxRefineSteps))
      ->capture_default_str();
}

VolumeBuildOptions toVolumeBuildOptions(const VolumeCliOptions& o) {
  VolumeBuildOptions v;
  v.refineSteps = o.refine;
  v.refineChords = o.chordPoints;
  v.refineSubdivisions = o.refineGrid;
  v.refineGridEverywhere = o.refineGridEverywhere;
  v.refineSnap = !o.noSnap;
  v.refineHidden = !o.noHiddenSearch;
  v.facePrisms = o.facePrisms;
  parseTriangulation(o.triangulation, v.triangulation);
  parseFarCap(o.cap, v.cap);
  v.blur = o.blur;
  v.blurOffset = o.blurOffset;
  v.bias = o.bias;
  checkUserVolumeOptions(v);  // the rules the Python module applies too, named by flag in main
  return v;
}

Scene loadSceneOrDefault(const std::string& path, std::vector<std::string>* warnings, SceneUse use) {
  SceneLoadResult r;
  if (path.empty()) r.scene = defaultScene();
  else r = loadScene(path);
  if (use == SceneUse::LightsOnly)  // a probe's finding: build printed the camera's moved planes
    std::erase_if(r.warnings, [&](const std::string& w) {
      return std::find(r.cameraWarnings.begin(), r.cameraWarnings.end(), w) != r.cameraWarnings.end();
    });
  for (const auto& w : r.warnings) std::fprintf(stderr, "shadowvol: warning: %s\n", w.c_str());
  if (warnings) warnings->insert(warnings->end(), r.warnings.begin(), r.warnings.end());
  const Scene& s = r.scene;
  verboseNote("scene %s: %zu objects, %zu triangles; light near %.6g far %.6g; camera %dx%d near %.6g far %.6g",
              s.source.c_str(), s.objects.size(), s.triangleCount(), s.light.nearPlane, s.light.farPlane,
              s.camera.width, s.camera.height, s.camera.nearPlane, s.camera.farPlane);
  return std::move(r.scene);
}

CLI::Option* addCaptureOption(CLI::App& cmd, std::string& capture) {
  return cmd
      .add_option("--capture", capture,
                  "Which surface each texel records: auto (front when a mesh object is open, and a note names "
                  "it; else entry for a refined volume (--refine K > 0) and back otherwise), back (the first "
                  "back face: the thesis's default, no bias; "
                  "single-sided geometry facing the light is skipped, so an open mesh's shadow leaks), front (the "
                  "first surface, pushed back by a bias: records open meshes), midpoint (the mean of the first two "
                  "surfaces; the far plane stands in for a missing second one) or entry (front capture's surface "
                  "where a back face lies behind it, else nothing: closed occluders' lit sides without the lit ground, "
                  "front capture's accuracy with the sub-grid at less cost; a face lit nearly edge-on, N.L below "
                  "1/256, is passed over for the back face behind it; on the GPU two light passes) (README 'Capture "
                  "modes')")
      ->check(CLI::IsMember(namesIn(kCaptureModeNames, {"auto"})))
      ->capture_default_str();
}

ResolvedCapture resolveCapture(const std::string& capture, const Scene& scene, CaptureUse use) {
  ResolvedCapture r;
  if (capture != "auto") {
    if (!parseCaptureMode(capture, r.mode))
      throw InputError("command line", "--capture", capture,
                       "must be " + choicesText(namesIn(kCaptureModeNames, {"auto"})));
    return r;
  }
  const CaptureChoice c = chooseCapture(scene, use);
  r.mode = c.mode;
  r.autoReason = c.reason;
  if (!c.openMeshes.empty() || c.deepSpot)  // what differs from the rule of thumb is said
    std::fprintf(stderr, "shadowvol: note: %s: --capture auto chose %s\n",
                 scene.source.c_str(), c.reason.c_str());
  return r;
}

std::vector<std::string> warnAboutCapture(const Scene& scene, int width, int height, CaptureMode capture,
                                          const VolumeBuildOptions* volume) {
  const bool search = volume && volume->refineSteps > 0 && volume->refineSubdivisions > 1 && volume->refineHidden;
  std::vector<std::string> w = captureWarnings(scene, width, height, capture, search ? volume->refineSubdivisions : 1);
  for (const auto& s : w) std::fprintf(stderr, "shadowvol: warning: %s: %s\n", scene.source.c_str(), s.c_str());
  return w;
}

void checkResolution(const std::string& option, int resolution, DepthMapUse use) {
  // checkDepthMapSize names the others; a depth file is made for a volume too.
  if (resolution < kMinVolumeMapSide)
    throw InputError("command line", option, std::to_string(resolution),
                     "must be at least " + std::to_string(kMinVolumeMapSide) +
                         ": a map's outermost ring of texels lies on the far plane, so a smaller map's volume is empty");
  if (resolution > kMaxResolution)
    throw InputError("command line", option, std::to_string(resolution),
                     "above the limit of " + std::to_string(kMaxResolution) + " texels a side");
  checkWindowMapSize(resolution, resolution, "command line", option, use);  // a volume's: with its guard band
}

namespace {

// Whether a file can be made in the folder `existing` (a read-only or virtual file system, an
// immutable folder, no write permission), found before the work rather than after it: by creating
// an empty file of a name no one holds (O_EXCL) and removing it. InputError naming `option` and
// the reason.
void probeWritableFolder(const std::filesystem::path& existing, const std::string& option, const std::string& path) {
  for (int attempt = 0; attempt < 8; ++attempt) {
    const std::filesystem::path probe =
        existing / (".shadowvol-probe-" + std::to_string(::getpid()) + "-" + std::to_string(attempt));
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd >= 0) {
      ::close(fd);
      ::unlink(probe.c_str());
      return;
    }
    if (errno != EEXIST)
      throw InputError("command line", option, path,
                       "cannot create anything in " + existing.string() + ": " + std::strerror(errno));
  }
}

}  // namespace

void checkOutputPath(const std::string& option, const std::string& path) {
  if (path.empty()) throw InputError("command line", option, "\"\"", "an output path is required");
  const std::filesystem::path p(path);
  const auto dir = p.has_parent_path() ? p.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw InputError("command line", option, path,
                     std::filesystem::exists(dir, ec) ? dir.string() + " is not a folder"
                                                      : "the folder " + dir.string() + " does not exist");
  if (std::filesystem::is_directory(p, ec)) throw InputError("command line", option, path, "is a folder, not a file");
  // Where the file will be written: beside the file a link names, as writeAtomically writes through.
  const auto target = std::filesystem::is_symlink(p, ec) ? std::filesystem::weakly_canonical(p, ec) : p;
  probeWritableFolder(!ec && target.has_parent_path() ? target.parent_path() : dir, option, path);  // a probe
  // found an unwritable folder only after minutes of work
}

void checkNotAnInput(const std::string& option, const std::string& value, const std::filesystem::path& output,
                     const std::vector<std::filesystem::path>& inputs, const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::exists(output, ec)) return;  // a file not there yet is read by no one
  for (const auto& input : inputs)
    if (std::filesystem::equivalent(output, input, ec))
      throw InputError("command line", option, value,
                       (what.empty() ? std::string("is") : what + " " + output.string() + " is") +
                           " an input of this command (" + input.string() +
                           "): writing it would destroy it; choose another output path");
}

namespace {
std::string gCommandLine = "shadowvol";
}

const std::string& commandLine() { return gCommandLine; }

void setCommandLine(int argc, char** argv) {
  gCommandLine = "shadowvol";
  for (int k = 1; k < argc; ++k) gCommandLine += std::string(" ") + argv[k];
}

void checkOutputFolder(const std::string& option, const std::string& path) {
  if (path.empty()) throw InputError("command line", option, "\"\"", "an output folder is required");
  // Missing folders, parents included, are created when the results are written; the nearest one
  // that exists must be a folder.
  const std::filesystem::path dir = std::filesystem::absolute(path);
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec))
    throw InputError("command line", option, path, "exists and is not a folder");
  std::filesystem::path existing = dir;
  while (!std::filesystem::exists(existing, ec) && existing.has_parent_path() && existing != existing.parent_path())
    existing = existing.parent_path();
  if (!std::filesystem::is_directory(existing, ec))
    throw InputError("command line", option, path, existing.string() + " is not a folder");
  probeWritableFolder(existing, option, path);
}

void addPlatformOption(CLI::App& cmd, std::string& platform, const std::string& when) {
  cmd.add_option("--platform", platform,
                 when + "EGL platform: auto (device, then Mesa surfaceless, then the default display), device, "
                        "surfaceless, default")
      ->check(CLI::IsMember({"auto", "device", "surfaceless", "default"}))
      ->capture_default_str();
}

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace shadowvol::cli

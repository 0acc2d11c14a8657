// Plumbing shared by the shadowvol subcommands: scene loading, option checks, JSON output,
// exit codes (0 ok, 1 bad input, 2 usage, 3 validation failed, 4 runtime failure such as no EGL
// display or an Embree error).
#pragma once

#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <filesystem>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "shadowvol/capture_choice.h"
#include "shadowvol/depth_map.h"
#include "shadowvol/report_json.h"
#include "shadowvol/scene.h"
#include "shadowvol/volume_builder.h"

namespace shadowvol::cli {

enum ExitCode { kOk = 0, kBadInput = 1, kUsage = 2, kValidationFailed = 3, kRuntimeFailure = 4, kInterrupted = 130 };

/// Options most subcommands share.
struct SceneOptions {
  std::string scene;       ///< path; empty = the built-in default scene
  bool json = false;       ///< print one JSON document on stdout instead of text
  std::string fit = "scene";  ///< --fit (subcommands with a depth map): scene | view
};

void addSceneOptions(CLI::App& cmd, SceneOptions& o);

/// Adds --fit scene|view (the light fitted to the whole scene, or to what the camera sees).
void addLightFitOption(CLI::App& cmd, std::string& fit);

/// Applies --fit to the loaded scene (after the camera's size is final) for a map of
/// `resolution` texels, and describes the light as used: the fit, what it changed and the texel
/// size on the receivers (JSON for --json; the same as one line on stdout otherwise).
/// With several lights each is fitted, and the JSON is {"fit", "lights": [one per light]}.
nlohmann::json applyLightFit(Scene& scene, const SceneOptions& o, int resolution);

/// Adds --light K (build, depth: the commands that work on one light's depth map).
void addLightChoiceOption(CLI::App& cmd, int& light);

/// A check for a real option in [lo, hi] that also refuses NaN (CLI::Range lets NaN through: a
/// --max-error of nan passed every frame).
CLI::Validator finiteRange(double lo, double hi);

/// Keeps light `light` of the scene alone (Scene::withOnlyLight); an InputError naming --light
/// when there is no such light. With several lights and K = 0 a note on stderr says so.
void chooseLight(Scene& scene, int light);

/// Adds --platform (the EGL platform: auto, device, surfaceless, default); `when` prefixes the
/// help ("With --device gpu, ") where the option does not always apply.
void addPlatformOption(CLI::App& cmd, std::string& platform, const std::string& when = "");

/// Options of the volume (build, render, validate): --triangulation, --blur, --blur-offset, --bias,
/// --cap, --refine.
struct VolumeCliOptions {
  std::string triangulation = "perfect";
  bool blur = false;
  double blurOffset = 0.0;
  std::optional<double> bias;
  std::string cap = "exact";
  int refine = 0;  ///< --refine K: silhouette refinement steps (0 = off)
  bool chordPoints = false;  ///< --chord-points: refinement with chord points (refineChords)
  int refineGrid = 1;        ///< --refine-grid S: the sub-grid (refineSubdivisions; 1 = off)
  bool refineGridEverywhere = false;  ///< --refine-grid-everywhere (refineGridEverywhere)
  bool noSnap = false;                ///< --no-snap (refineSnap = false)
  bool noHiddenSearch = false;        ///< --no-hidden-search (refineHidden = false)
  bool facePrisms = false;            ///< --face-prisms (facePrisms)
};
/// Adds the options; returns --refine's option (for excludes).
CLI::Option* addVolumeOptions(CLI::App& cmd, VolumeCliOptions& o);
/// Checks the values (InputError naming the option) and fills the builder's options. With
/// --refine the caller sets the depth oracle (the scene's Embree rays).
VolumeBuildOptions toVolumeBuildOptions(const VolumeCliOptions& o);
void addJsonOption(CLI::App& cmd, bool& json);

/// What a command uses of a scene: commands that render no image (build, depth) are not warned
/// about the camera, unless --fit view fits the light to what the camera sees.
enum class SceneUse { WithCamera, LightsOnly };

/// The scene's use by build or depth: LightsOnly, WithCamera with --fit view.
inline SceneUse sceneUse(const SceneOptions& o) { return o.fit == "view" ? SceneUse::WithCamera : SceneUse::LightsOnly; }

/// Loads the scene (or the default one), printing its warnings to stderr (and appending them to
/// `warnings` when given: validate's report keeps them); the camera's only for SceneUse::WithCamera.
Scene loadSceneOrDefault(const std::string& path, std::vector<std::string>* warnings = nullptr,
                         SceneUse use = SceneUse::WithCamera);

/// Adds --capture (auto, back, front, midpoint, entry; default auto), one help text for every command.
CLI::Option* addCaptureOption(CLI::App& cmd, std::string& capture);

/// --capture's value for `scene`: back, front, midpoint or entry as given; auto (the default) chosen by
/// chooseCapture (capture_choice.h) for a map used as `use`, with a note on stderr when it picks
/// front (an open mesh). `autoReason` is chooseCapture's sentence, empty when the mode was given.
struct ResolvedCapture {
  CaptureMode mode = CaptureMode::Back;
  std::string autoReason;
};
ResolvedCapture resolveCapture(const std::string& capture, const Scene& scene, CaptureUse use);

/// Prints captureWarnings (capture_warnings.h) for a W x H map to stderr and returns them; `volume`
/// (the volume the map is for, if any) says whether a sub-grid searches for hidden surfaces.
std::vector<std::string> warnAboutCapture(const Scene& scene, int width, int height, CaptureMode capture,
                                          const VolumeBuildOptions* volume = nullptr);

/// Largest side accepted for a depth map (texels).
inline constexpr int kMaxResolution = kMaxWindowSide;

/// checkDepthMapSize (depth_map.h) of an N x N map for `use` (its memory), naming the option, and
/// N >= kMinVolumeMapSide (volume_builder.h): a smaller map's volume is empty (a depth file's too).
void checkResolution(const std::string& option, int resolution, DepthMapUse use = DepthMapUse::Volume);

/// Refuses an output path whose folder does not exist (before any work is done).
void checkOutputPath(const std::string& option, const std::string& path);

/// Refuses to write `output` (named by `option`) where it is one of the command's input files (the
/// same file, through any path or link): writing would destroy the input. A regression of a
/// hostile-input probe: `depth --out X.pfm` replaced a scene file X.pfm.json, `build --out` a mesh
/// the scene reads.
/// `what` names a file the option's value implies (its side file, say) when `output` is that file.
void checkNotAnInput(const std::string& option, const std::string& value, const std::filesystem::path& output,
                     const std::vector<std::filesystem::path>& inputs, const std::string& what = "");

/// The command line as typed (set by main), for reports that say how to reproduce them.
const std::string& commandLine();
void setCommandLine(int argc, char** argv);

/// Refuses an output folder (created later, parents included, if missing) that exists and is not a
/// folder, or whose nearest existing ancestor is not a folder. Throws InputError naming the option.
void checkOutputFolder(const std::string& option, const std::string& path);

/// Milliseconds since `start`.
double msSince(std::chrono::steady_clock::time_point start);

/// Registers the subcommand `name` whose body runs `run` and returns an exit code.
using Runner = std::function<int()>;

void registerSceneCommand(CLI::App& app, Runner& run);
void registerDepthCommand(CLI::App& app, Runner& run);
void registerBuildCommand(CLI::App& app, Runner& run);
void registerCheckCommand(CLI::App& app, Runner& run);
#ifdef SHADOWVOL_WITH_GL
void registerRenderCommand(CLI::App& app, Runner& run);
void registerValidateCommand(CLI::App& app, Runner& run);
void registerBenchCommand(CLI::App& app, Runner& run);
#endif

}  // namespace shadowvol::cli

// The time-against-error sweep: every scene x method x depth-map resolution, timed on
// the GPU renderer and scored against exact (ray-traced) shadows. Rows go to DIR/results.csv as
// they are measured, so an interrupted sweep resumes where it stopped.
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "shadowvol/bench/sweep_results.h"
#include "shadowvol/gl/renderer.h"
#include "shadowvol/scene.h"

namespace shadowvol {

/// Which lights a sweep method renders: the spot and directional lights' one depth map, a point
/// light's cube of six, or both (methods without a depth map). A cell of a method for the other
/// kind of light is not a cell of the sweep.
enum class SweepLights { Frustum, Point, Any };

/// A method of the sweep: its key (the CSV's `method`) and how to render it.
struct SweepMethod {
  std::string key;                  ///< e.g. "pcf3", "hybrid-perfect-blur/gpu", "silhouette"
  std::string family;               ///< shadowmap | pcf3 | pcf5 | dpsm | hybrid | silhouette
  gl::RenderOptions options;        ///< method, volume source, capture, volume options
  bool usesResolution = true;       ///< false for silhouette (no depth map): one cell per scene;
                                    ///< for a point light the resolution is each cube face's side
  SweepLights lights = SweepLights::Frustum;
  std::string description;          ///< one line for --help and the report
};

/// Refinement steps of the sweep's hybrid-refined methods.
inline constexpr int kSweepRefineSteps = kRecommendedRefineSteps;
/// Sub-grid of the sweep's hybrid-refined-grid methods.
inline constexpr int kSweepRefineSubdivisions = kRecommendedRefineSubdivisions;

/// Every method the sweep knows, in report order.
const std::vector<SweepMethod>& sweepMethods();

struct SweepOptions {
  std::vector<std::filesystem::path> scenes;  ///< scene files; an empty path = the built-in default scene
  std::vector<std::string> methods;           ///< keys of sweepMethods(); empty = all
  std::vector<int> resolutions = {64, 128, 256, 512, 1024, 2048, 4096};
  int width = 640, height = 480;              ///< image size (replaces each scene camera's)
  int repeat = 5;                             ///< measured frames per cell (median, min, max)
  int warmup = 1;                             ///< frames rendered and discarded first (at least one: it finds a refused cell)
  std::filesystem::path out;                  ///< folder for results.csv (created)
  /// How the light is fitted, each a set of cells: View fits each scene's light to its camera for
  /// each resolution (fitLightToView) and names the scene "<scene>@view" in the results, so both
  /// fits sit side by side in one results file (methods without a depth map: Scene only).
  std::vector<LightFit> fits = {LightFit::Scene};
};

/// The suffix of a scene's name in the results when its light was fitted to the view.
inline constexpr const char* kViewFitSuffix = "@view";

/// Progress of the sweep, for a progress bar or plain lines.
struct SweepProgress {
  std::size_t done = 0, total = 0, skipped = 0;  ///< cells: measured or resumed so far, all, resumed
  std::string cell;                              ///< scene | method | resolution of the current cell
  double elapsedSeconds = 0.0;
};

/// Runs the sweep, appending each finished cell to out/results.csv (created with its header if
/// missing; cells already in it are skipped). Stops after the current cell when `stop` becomes
/// true. Throws InputError for unknown methods, a results file of another version, or scenes that
/// fail to load; a resolution whose buffers would not fit in memory is skipped with a note.
/// Returns all rows of results.csv afterwards.
std::vector<SweepRow> runSweep(gl::Renderer& renderer, const SweepOptions& options, const std::atomic<bool>& stop,
                               const std::function<void(const SweepProgress&)>& onProgress,
                               std::vector<std::string>& notes);

}  // namespace shadowvol

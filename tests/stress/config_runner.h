// Runs one stress configuration through the real shadowvol binary, one subprocess per command
// (so a crash is isolated and counted): validate with the explicit volume, with the GPU volume,
// with front capture, and build to a PLY, as the configuration asks; collects what each left.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ply_check.h"
#include "process_runner.h"
#include "stress_config.h"

namespace shadowvol::stress {

/// What is run: `validate --volume explicit`, `--volume gpu`, `--volume explicit --capture front`, `build`.
enum class RunKind { Explicit, Gpu, Front, Refined, Walk, RayDepth, GpuRefined, Entry, GpuEntry, Build };
const char* runName(RunKind k);

struct RunSettings {
  std::filesystem::path shadowvol;  ///< the CLI binary
  std::filesystem::path outDir;     ///< scenes in OUT/scenes, each run's files in OUT/runs/<config>/<run>
  int timeoutSeconds = 120;         ///< per command; past it the command counts as a crash
  int resolution = 128;             ///< --resolution: the light's depth map is N x N
  std::string size = "160x120";     ///< --size: the validated frame
};

struct RunOutcome {
  RunKind kind = RunKind::Explicit;
  std::vector<std::string> argv;  ///< the command line, for the report
  ProcessResult process;
  std::optional<nlohmann::json> report;      ///< validate: DIR/report.json, when it exists and parses
  std::string reportProblem;                 ///< validate: why report.json, present, did not parse
  bool leftOutput = false;                   ///< report.json (validate) or the .ply (build) exists afterwards
  std::optional<PlyCheck> ply;               ///< build: the written volume, checked
  std::optional<nlohmann::json> stdoutJson;  ///< the --json document on stdout, when it parses
};

struct ConfigOutcome {
  std::vector<RunOutcome> runs;
  double seconds = 0;  ///< wall time of all its runs
  const RunOutcome* find(RunKind k) const;
};

/// Writes the configuration's scene file (OUT/scenes/<name>.json) and returns its path.
std::filesystem::path writeScene(const StressConfig& c, const std::filesystem::path& outDir);

/// Runs every command the configuration asks for on its scene file (written by writeScene);
/// clears OUT/runs/<name> first so nothing stale is read.
ConfigOutcome runConfig(const StressConfig& c, const std::filesystem::path& sceneFile, const RunSettings& s);

}  // namespace shadowvol::stress

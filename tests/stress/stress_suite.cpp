// stress_suite: the numerical-robustness stress suite. It writes several hundred scene files that
// push one thing each to an extreme, runs the real shadowvol binary on each, one subprocess per
// command, and judges the results against the goal. It exits 0 only when every configuration
// meets the goal.
//
//   stress_suite --shadowvol PATH --out DIR [--quick] [--only CATEGORY] [--timeout S]
//
// Every legal configuration runs `validate --resolution 128 --size 160x120 --volume explicit`,
// `validate ... --volume gpu`, and `build --resolution 128 --out volume.ply`. Every third one of
// each category (and its twin) also runs `validate ... --capture front`. A refused configuration
// runs validate and build. Files: OUT/scenes/<config>.json; OUT/runs/<config>/<run>/ (stdout.txt,
// stderr.txt, report/, volume.ply); OUT/summary.json and OUT/summary.md.
//
// THE GOAL, as judged here. Each failure is counted in one table column; a configuration can
// count in several.
// - crashes: a signal, the time limit (--timeout, 120 s), exit 4 (runtime failure), or a
//   command that could not be started. This holds in every category.
// - non-finite: a null in report.json or in build's --json output (nlohmann writes NaN and inf
//   as null; meshChecks.notApplicable, null by design, is skipped), meshChecks.nonFiniteVertices
//   > 0, or a non-finite vertex in volume.ply.
// - not closed/outward: the explicit exact-cap volume fails meshChecks.closedManifold or
//   .outward (an empty volume, 0 triangles, is closed and outward does not apply, as in
//   validate's verdict), or volume.ply, read back here, has an edge not shared by exactly two
//   faces in opposite directions, or a signed volume <= 0.
// - agree < 99.99%: stencilVsCount.fraction < 0.9999, for every validate run.
// - z-fail != z-pass: wherever validate finds the eye outside the volume (eyeInsideVolume false),
//   zfailVsZpass must agree on every pixel. Where the geometry leaves no doubt that the eye is
//   outside (camera-in-volume, eye-outside-*) and validate says inside, that fails too: the
//   comparison was skipped.
// - offset twin (offset category only): against the same scene at the origin (its twin), per
//   validate run, the exact-shadow pixel count (pixels.exactShadowed) within 2 % of the twin's or
//   1 pixel, and the method's error (againstExact.method.errorFraction) at most 1.5 x the twin's
//   + 0.001. The slack: the default view at 160x120 has about 7,800 pixels facing the light, so
//   0.001 is about 8 pixels. It covers the case where the twin's error is 0 or a few pixels, so
//   1.5 x would allow none.
// - refused wrong (refused category): the command must exit 1. Its stderr must name the scene
//   file and the field's JSON pointer, and report.json and volume.ply must not exist. For a value
//   JSON cannot carry (1e400 overflows a double; NaN and Infinity are not JSON), "line " (the
//   location of malformed text) is accepted instead of the pointer. In the other categories, a
//   legal scene refused with exit 1 or 2 counts here too.
// - other: validate's exit status and report.json's "passed" disagree; exit 0/3 without a
//   report; a report without mesh checks; an unreadable volume.ply; an exit status not listed.
//
// PER CATEGORY (all but refused: a legal scene; validate may exit 0 or 3):
// - An accuracy failure alone (exit 3 because the method misclassifies more than --max-error or
//   misses more than --max-missed) is not a robustness failure: tiny, thin and grazing objects
//   legitimately cover no texel. It is listed in summary.json's notes. The checks above still
//   apply to the frame.
// - scale, light-depth-range, camera-depth-range: the twin comparison (same picture expected)
//   runs too, but only as a note. The goal requires it of offset configs only.
// - camera-in-volume: z-fail vs z-pass is skipped where validate finds the eye inside (z-pass
//   from the eye is then wrong by design); stencil vs count must still hold.
// - degenerate, light-inside, grazing, spot-fov: the checks above, nothing more.
#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <string>

#include "config_runner.h"
#include "stress_configs.h"
#include "stress_judge.h"
#include "stress_summary.h"

namespace fs = std::filesystem;
using namespace shadowvol::stress;

namespace {

struct Arguments {
  fs::path shadowvol, out;
  bool quick = false;
  std::optional<std::string> only;
  int timeoutSeconds = 120;
};

/// Prints the problem and the usage; parseArguments then gives up (exit 2).
std::nullopt_t usage(const std::string& problem) {
  std::cerr << "stress_suite: " << problem << "\n"
            << "usage: stress_suite --shadowvol PATH --out DIR [--quick] [--only CATEGORY] [--timeout SECONDS]\n"
            << "categories:";
  for (const auto& c : kCategories) std::cerr << " " << c;
  std::cerr << "\n";
  return std::nullopt;
}

/// Parses the command line; nullopt after printing the usage.
std::optional<Arguments> parseArguments(int argc, char** argv) {
  Arguments a;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    const bool hasValue = k + 1 < argc;
    if (arg == "--quick")
      a.quick = true;
    else if (arg == "--shadowvol" && hasValue)
      a.shadowvol = argv[++k];
    else if (arg == "--out" && hasValue)
      a.out = argv[++k];
    else if (arg == "--only" && hasValue)
      a.only = argv[++k];
    else if (arg == "--timeout" && hasValue)
      a.timeoutSeconds = std::atoi(argv[++k]);
    else
      return usage("unknown or incomplete option " + arg);
  }
  if (a.shadowvol.empty() || a.out.empty()) return usage("--shadowvol and --out are required");
  if (!fs::is_regular_file(a.shadowvol)) return usage("no such binary: " + a.shadowvol.string());
  if (a.only && std::find(kCategories.begin(), kCategories.end(), *a.only) == kCategories.end())
    return usage("unknown category " + *a.only);
  if (a.timeoutSeconds < 1) return usage("--timeout must be at least 1");
  return a;
}

/// One line per configuration while the suite runs.
void progress(std::size_t k, std::size_t n, const ConfigResult& r) {
  std::printf("[%3zu/%3zu] %-44s %s (%.1f s)\n", k + 1, n, r.config.name.c_str(), r.judgement.passed() ? "ok" : "FAIL",
              r.outcome.seconds);
  std::fflush(stdout);
}

bool interrupted(const ConfigOutcome& o) {
  for (const auto& r : o.runs)
    if (r.process.signal == SIGINT) return true;
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  const auto args = parseArguments(argc, argv);
  if (!args) return 2;
  const auto start = std::chrono::steady_clock::now();
  std::vector<StressConfig> configs = selectConfigs(generateConfigs(), args->quick, args->only);

  SuiteRun run;
  run.mode = std::string(args->quick ? "quick" : "full") + (args->only ? " --only " + *args->only : "");
  run.shadowvol = fs::absolute(args->shadowvol);
  run.settings.shadowvol = run.shadowvol;
  run.settings.outDir = fs::absolute(args->out);
  run.settings.timeoutSeconds = args->timeoutSeconds;
  for (const char* sub : {"scenes", "runs"}) fs::remove_all(run.settings.outDir / sub);
  fs::create_directories(run.settings.outDir);

  // Twins come before the configurations compared with them (generateConfigs' order), so each
  // configuration is judged as soon as it has run.
  std::map<std::string, std::size_t> index;
  for (std::size_t k = 0; k < configs.size(); ++k) {
    StressConfig& c = configs[k];
    const fs::path scene = writeScene(c, run.settings.outDir);
    ConfigOutcome outcome = runConfig(c, scene, run.settings);
    if (interrupted(outcome)) {
      std::fprintf(stderr, "stress_suite: interrupted\n");
      return 130;
    }
    const ConfigOutcome* twin = nullptr;
    if (c.twin && index.count(*c.twin)) twin = &run.results[index.at(*c.twin)].outcome;
    Judgement judgement = judgeConfig(c, outcome, twin, run.settings);
    index[c.name] = run.results.size();
    run.results.push_back({std::move(c), std::move(outcome), std::move(judgement)});
    progress(k, configs.size(), run.results.back());
  }
  run.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::cout << "\n";
  printSummary(run, std::cout);
  writeSummaryJson(run, run.settings.outDir / "summary.json");
  writeSummaryMarkdown(run, run.settings.outDir / "summary.md");
  std::cout << "wrote " << (run.settings.outDir / "summary.json").string() << " and summary.md\n";
  return run.passed() ? 0 : 1;
}

// shadowvol bench: the time-against-error sweep over scenes x methods x depth-map resolutions.
// Writes DIR/results.csv cell by cell (resumable) and DIR/report.md with SVG plots.
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <thread>
#include <unistd.h>

#include "cli_verbosity.h"
#include "render_options.h"
#include "shadowvol/report_json.h"
#include "shadowvol/version.h"
#include "shadowvol/bench/sweep.h"
#include "shadowvol/bench/sweep_report.h"
#include "shadowvol/error.h"

namespace shadowvol::cli {
namespace {

// Whether the file's last byte is not a line end (an interrupted run's partial row).
bool endsMidLine(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in || in.tellg() <= 0) return false;
  in.seekg(-1, std::ios::end);
  return in.get() != '\n';
}

std::atomic<bool> gStop{false};
void onSigint(int) { gStop = true; }

std::string machineDescription() {
  std::string model = "unknown CPU";
  std::ifstream cpu("/proc/cpuinfo");
  for (std::string line; std::getline(cpu, line);)
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  const double gib = pages > 0 && pageSize > 0 ? double(pages) * double(pageSize) / 1073741824.0 : 0.0;
  char buf[256];
  std::snprintf(buf, sizeof buf, "%u cores, %s, %.0f GiB", std::thread::hardware_concurrency(), model.c_str(), gib);
  return buf;
}


// One cell of results.csv as JSON (the same fields; times in ms, fractions of the pixels).
nlohmann::json rowJson(const SweepRow& r) {
  nlohmann::json phases = nlohmann::json::object();
  for (const auto& [name, t] : r.phases) phases[name] = t.median;
  auto optional = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); };
  return {{"scene", r.scene},
          {"triangles", r.triangles},
          {"method", r.method},
          {"family", r.family},
          {"capture", r.capture},
          {"resolution", r.resolution},
          {"size", {r.width, r.height}},
          {"timing", r.timing},
          {"frames", r.frames},
          {"frameMs", {{"median", r.frame.median}, {"min", r.frame.min}, {"max", r.frame.max}}},
          {"phasesMs", phases},
          {"volumeTriangles", r.volumeTriangles},
          {"volumeQuads", r.volumeQuads},
          {"volumeQuadsDrawn", r.volumeQuadsDrawn},
          {"volumeCount", r.volumeCount.empty() ? nlohmann::json() : nlohmann::json(r.volumeCount)},
          {"pixels", r.pixels},
          {"error", r.error},
          {"leak", r.leak},
          {"acne", r.acne},
          {"bandPixels", r.bandPixels},
          {"bandError", r.bandError},
          {"distMean", optional(r.distMean)},
          {"distP99", optional(r.distP99)},
          {"distMax", optional(r.distMax)}};
}

// What bench prints: with --json one document (the cells of results.csv, the notes and the files
// written), else a "wrote" line a file.
void printBenchOutput(bool json, const std::string& out, const SweepReportInfo& info, bool interrupted,
                      const std::vector<std::string>& notes, const std::vector<std::filesystem::path>& written,
                      const std::vector<SweepRow>& rows) {
  if (!json) {
    for (const auto& p : written) std::printf("wrote %s\n", p.string().c_str());
    return;
  }
  nlohmann::json cells = nlohmann::json::array();
  for (const auto& r : rows) cells.push_back(rowJson(r));
  nlohmann::json files = nlohmann::json::array();
  for (const auto& p : written) files.push_back(p.string());
  const nlohmann::json j = {{"shadowvolVersion", SHADOWVOL_VERSION}, {"out", out},
                            {"machine", info.machine},                 {"glRenderer", info.glRenderer},
                            {"interrupted", interrupted},              {"notes", notes},
                            {"files", files},                          {"cells", cells}};
  std::cout << jsonText(j) << '\n';
}


// --report-only --methods: the report and plots of these methods only (each must be in the results).
std::vector<SweepRow> onlyMethods(std::vector<SweepRow> rows, const std::vector<std::string>& methods) {
  for (const auto& m : methods)
    if (std::none_of(rows.begin(), rows.end(), [&](const SweepRow& r) { return r.method == m; }))
      throw InputError("command line", "--methods", m, "no cell of this method in results.csv");
  std::erase_if(rows, [&](const SweepRow& r) { return std::find(methods.begin(), methods.end(), r.method) == methods.end(); });
  return rows;
}

}  // namespace

void registerBenchCommand(CLI::App& app, Runner& run) {
  struct Options {
    std::vector<std::string> scenes;
    std::vector<std::string> methods;
    std::vector<std::string> fits;
    std::vector<int> resolutions = {64, 128, 256, 512, 1024, 2048, 4096};
    std::string size = "640x480";
    int repeat = 5;
    int warmup = 1;
    std::string out;
    bool reportOnly = false;
    bool listMethods = false;
    bool json = false;
    std::string platform = "auto";
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "bench",
      "Time against error: every scene x method x depth-map resolution, timed on the GPU (median of --repeat frames "
      "after --warmup) and scored against exact shadow rays. Writes DIR/results.csv cell by cell (run the same "
      "command again to resume an interrupted sweep; Ctrl-C stops after the current cell) and DIR/report.md with "
      "SVG plots");
  cmd->add_option("--scenes", o->scenes, "Scene files (default: every data/scenes/*.json; 'default' = built-in scene)");
  cmd->add_option("--methods", o->methods, "Method keys, separated by spaces or commas (default: all; see --list-methods); with --report-only: the methods the report and plots show")
      ->delimiter(',');
  cmd->add_option("--fit", o->fits,
                  "Light fits, each a set of cells, separated by spaces or commas: scene (default), view (the light "
                  "fitted to each scene's camera for each resolution; results name the scene <scene>@view)")
      ->delimiter(',')
      ->check(CLI::IsMember(namesIn(kLightFitNames)));
  cmd->add_option("--resolutions", o->resolutions, "Depth-map sizes N (N x N; for a point light each cube face is N x N), separated by spaces or commas")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--repeat", o->repeat, "Measured frames per cell (median, min, max)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_option("--warmup", o->warmup,
                  "Frames rendered and discarded before measuring (at least one is: the first also finds a method "
                  "that refuses the cell, which is then skipped with a note)")
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  addPlatformOption(*cmd, o->platform);
  cmd->add_option("--out", o->out, "Output folder (results.csv, report.md, plots/); required unless --list-methods");
  cmd->add_flag("--report-only", o->reportOnly, "Only rewrite report.md and the plots from DIR/results.csv");
  cmd->add_flag("--list-methods", o->listMethods, "Print the method keys and exit");
  cmd->add_flag("--json", o->json,
                "Print one JSON document on stdout: the cells of this results.csv (finished earlier ones too), the "
                "notes and the files written; progress stays on stderr");
  cmd->callback([&run, o, cmd] {
    // Options that would change nothing are refused by name, not ignored (a probe's finding:
    // --report-only took --resolutions, --size and --repeat, --list-methods --out, without a word).
    std::vector<const char*> inert = {"--scenes", "--fit", "--resolutions", "--size", "--repeat", "--warmup",
                                      "--platform"};
    if (o->listMethods) inert.insert(inert.end(), {"--out", "--methods", "--report-only"});
    if (o->listMethods || o->reportOnly)
      for (const char* flag : inert)
        if (cmd->count(flag) > 0)
          throw CLI::ValidationError(flag, o->listMethods ? "changes nothing with --list-methods, which only prints "
                                                            "the method keys: leave one out"
                                                          : "changes nothing with --report-only, which rewrites the "
                                                            "report from DIR/results.csv: leave one out");
    // A missing folder is a usage error (exit 2), as for every other required option.
    if (!o->listMethods && o->out.empty()) throw CLI::RequiredError("--out (the output folder)");
    run = [o] {
      if (o->listMethods) {
        if (o->json) {
          nlohmann::json methods = nlohmann::json::array();
          for (const auto& m : sweepMethods()) methods.push_back({{"key", m.key}, {"description", m.description}});
          std::cout << jsonText(methods) << '\n';
        } else {
          for (const auto& m : sweepMethods()) std::printf("%-26s %s\n", m.key.c_str(), m.description.c_str());
        }
        return kOk;
      }
      checkOutputFolder("--out", o->out);
      for (const auto& m : o->methods)  // a probe's finding: "--methods ," took the next option as a method
        if (m.empty() || m.rfind("--", 0) == 0)
          throw InputError("command line", "--methods", m.empty() ? "\"\"" : m,
                           "not a method key (an empty key from a stray comma, or the next option taken as one)");
      const std::filesystem::path dir(o->out);
      SweepReportInfo info;
      info.machine = machineDescription();
      info.command = commandLine();
      if (o->reportOnly) {
        auto rows = readSweepCsv(dir / "results.csv");
        std::vector<std::string> notes;
        if (endsMidLine(dir / "results.csv")) {  // a second probe's finding: the resume said so, this did not
          notes.push_back("the last line of " + (dir / "results.csv").string() +
                          " is incomplete (an interrupted run?) and is left out of the report");
          std::fprintf(stderr, "shadowvol: note: %s\n", notes.back().c_str());
        }
        if (!o->methods.empty()) rows = onlyMethods(std::move(rows), o->methods);
        info.timing = rows.empty() ? "" : rows.front().timing;
        info.glRenderer = "see results";
        printBenchOutput(o->json, o->out, info, false, notes, writeSweepReport(rows, info, dir), rows);
        return kOk;
      }
      SweepOptions so;
      if (o->scenes.empty()) {
        std::filesystem::path sceneDir = std::filesystem::path(SHADOWVOL_SOURCE_DIR) / "data/scenes";
        if (!std::filesystem::is_directory(sceneDir)) sceneDir = "data/scenes";
        if (!std::filesystem::is_directory(sceneDir))
          throw InputError("command line", "--scenes", "", "no data/scenes folder here: name the scene files");
        for (const auto& e : std::filesystem::directory_iterator(sceneDir))
          if (e.path().extension() == ".json") so.scenes.push_back(e.path());
        std::sort(so.scenes.begin(), so.scenes.end());
      } else {
        for (const auto& s : o->scenes) {
          if (s == "default") {
            so.scenes.emplace_back();
            continue;
          }
          if (!std::filesystem::is_regular_file(s))
            throw InputError("command line", "--scenes", s, "no such scene file");
          so.scenes.emplace_back(s);
        }
      }
      so.methods = o->methods;
      if (!o->fits.empty()) {
        so.fits.clear();
        for (const auto& f : o->fits) {
          LightFit fit;
          parseLightFit(f, fit);
          if (std::find(so.fits.begin(), so.fits.end(), fit) == so.fits.end()) so.fits.push_back(fit);
        }
      }
      so.resolutions = o->resolutions;
      Scene sizeScene;
      RenderCliOptions sizeOnly;
      sizeOnly.size = o->size;
      sizeOnly.scored = true;  // every cell is scored against exact shadow rays
      toRenderOptions(sizeOnly, sizeScene);  // checks --size
      so.width = sizeScene.camera.width;
      so.height = sizeScene.camera.height;
      so.repeat = o->repeat;
      so.warmup = o->warmup;
      so.out = dir;

      gl::RendererOptions ropt;
      ropt.context.platform = o->platform;
      gl::Renderer renderer(ropt);
      info.glRenderer = renderer.info().glRenderer;
      verboseNote("GL context: %s, %s (EGL platform %s)", renderer.info().glRenderer.c_str(),
                  renderer.info().glVersion.c_str(), renderer.info().platform.c_str());
      const bool tty = isatty(fileno(stderr)) && verbosity() == Verbosity::Normal;
      std::signal(SIGINT, onSigint);
      std::vector<std::string> notes;
      const auto rows = runSweep(renderer, so, gStop, [tty](const SweepProgress& p) {
        if (verbosity() == Verbosity::Quiet) return;
        const double eta = p.done > p.skipped ? p.elapsedSeconds / double(p.done - p.skipped) * double(p.total - p.done) : 0.0;
        if (tty) {
          const int width = 30, filled = p.total ? int(width * p.done / p.total) : width;
          std::fprintf(stderr, "\r[%s%s] %zu/%zu  %4.0f s, ETA %4.0f s  %-60.60s", std::string(filled, '#').c_str(),
                       std::string(width - filled, '.').c_str(), p.done, p.total, p.elapsedSeconds, eta, p.cell.c_str());
          if (p.done == p.total) std::fputc('\n', stderr);
        } else {
          std::fprintf(stderr, "bench %zu/%zu  %.0f s elapsed, ETA %.0f s  %s\n", p.done, p.total, p.elapsedSeconds, eta,
                       p.cell.c_str());
        }
      }, notes);
      std::signal(SIGINT, SIG_DFL);
      for (const auto& n : notes) std::fprintf(stderr, "shadowvol: note: %s\n", n.c_str());
      info.timing = rows.empty() ? "" : rows.back().timing;
      printBenchOutput(o->json, o->out, info, bool(gStop), notes, writeSweepReport(rows, info, dir), rows);
      if (gStop) {
        std::fprintf(stderr, "interrupted: %zu cells in %s; run the same command to resume\n", rows.size(),
                     (dir / "results.csv").string().c_str());
        return kInterrupted;
      }
      return kOk;
    };
  });
}

}  // namespace shadowvol::cli

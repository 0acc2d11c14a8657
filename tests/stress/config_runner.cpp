#include "config_runner.h"

#include <fstream>
#include <sstream>

namespace shadowvol::stress {
namespace {

namespace fs = std::filesystem;

std::optional<nlohmann::json> parseJson(const std::string& text) {
  nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return std::nullopt;
  return j;
}

bool pointLight(const StressConfig& c) {
  return c.scene.contains("light") && c.scene["light"].is_object() && c.scene["light"].value("type", "") == "point";
}

std::vector<RunKind> runsOf(const StressConfig& c) {
  std::vector<RunKind> runs = {RunKind::Explicit};
  if (c.gpu && !c.refused) runs.push_back(RunKind::Gpu);
  if (c.front && !c.refused) runs.push_back(RunKind::Front);
  if (c.refined && !c.refused) runs.push_back(RunKind::Refined);
  if (c.refined && !c.refused && !pointLight(c)) runs.push_back(RunKind::Walk);  // rays only for the cube
  if (c.refined && !c.refused) runs.push_back(RunKind::RayDepth);  // the map from rays, too (a point light's six)
  if (c.refined && !c.refused) runs.push_back(RunKind::GpuRefined);  // a point light's: its face volumes
  if (c.refined && !c.refused) runs.push_back(RunKind::Entry);  // entry capture, refined as Refined
  if (c.refined && !c.refused) runs.push_back(RunKind::GpuEntry);  // entry capture, refined as GpuRefined
  runs.push_back(RunKind::Build);
  return runs;
}

RunOutcome runOne(RunKind kind, const fs::path& scene, bool point, const fs::path& dir, const RunSettings& s) {
  fs::create_directories(dir);
  RunOutcome r;
  r.kind = kind;
  const fs::path reportDir = dir / "report", ply = dir / "volume.ply";
  const std::string resolution = std::to_string(s.resolution);
  if (kind == RunKind::Build) {
    r.argv = {s.shadowvol.string(), "build", "--scene",    scene.string(), "--resolution",
              resolution,           "--out", ply.string(), "--json"};
  } else {
    r.argv = {
        s.shadowvol.string(), "validate",         "--scene", scene.string(), "--resolution",
        resolution,           "--size",           s.size,    "--volume",
        kind == RunKind::Gpu || kind == RunKind::GpuRefined || kind == RunKind::GpuEntry ? "gpu" : "explicit",
        "--report",           reportDir.string(), "--json"};
    if (kind == RunKind::Front || kind == RunKind::Entry || kind == RunKind::GpuEntry) {
      r.argv.push_back("--capture");
      r.argv.push_back(kind == RunKind::Front ? "front" : "entry");
    }
    const bool refined = kind == RunKind::Refined || kind == RunKind::Entry;
    if (refined && point)  // the cube volume's refinement: rays alone
      for (const char* a : {"--refine", "6"}) r.argv.push_back(a);
    else if (refined)  // silhouette refinement on the sub-grid: the rays go to the same scene
      for (const char* a : {"--refine", "6", "--refine-grid", "4"}) r.argv.push_back(a);
    if (kind == RunKind::Walk)  // refinement with the crossings from the GPU's walk over the triangles
      for (const char* a : {"--refine", "6", "--crossings", "gpu-walk"}) r.argv.push_back(a);
    if (kind == RunKind::RayDepth)  // refinement of a depth map ray-cast on the CPU (no light pass)
      for (const char* a : {"--refine", "6", "--depth-from", "rays"}) r.argv.push_back(a);
    if (kind == RunKind::GpuRefined || kind == RunKind::GpuEntry)  // the refined GPU volume: edges, rays, cells
      for (const char* a : {"--refine", "6"}) r.argv.push_back(a);
  }
  r.process = runProcess(r.argv, dir / "stdout.txt", dir / "stderr.txt", s.timeoutSeconds);
  r.stdoutJson = parseJson(r.process.stdoutText);
  if (kind == RunKind::Build) {
    r.leftOutput = fs::exists(ply);
    if (r.leftOutput && r.process.exitCode == 0) r.ply = checkPly(ply);
  } else {
    const fs::path report = reportDir / "report.json";
    r.leftOutput = fs::exists(report);
    if (r.leftOutput) {
      std::ifstream in(report);
      std::ostringstream ss;
      ss << in.rdbuf();
      r.report = parseJson(ss.str());
      if (!r.report) r.reportProblem = "report.json does not parse";
    }
  }
  return r;
}

}  // namespace

const char* runName(RunKind k) {
  switch (k) {
    case RunKind::Explicit:
      return "explicit";
    case RunKind::Gpu:
      return "gpu";
    case RunKind::Front:
      return "front";
    case RunKind::Refined:
      return "refined";
    case RunKind::Walk:
      return "walk";
    case RunKind::RayDepth:
      return "ray-depth";
    case RunKind::GpuRefined:
      return "gpu-refined";
    case RunKind::Entry:
      return "entry";
    case RunKind::GpuEntry:
      return "gpu-entry";
    case RunKind::Build:
      return "build";
  }
  return "?";
}

const RunOutcome* ConfigOutcome::find(RunKind k) const {
  for (const auto& r : runs)
    if (r.kind == k) return &r;
  return nullptr;
}

fs::path writeScene(const StressConfig& c, const fs::path& outDir) {
  const fs::path file = outDir / "scenes" / (c.name + ".json");
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << (c.sceneText.empty() ? c.scene.dump(2) : c.sceneText) << '\n';
  return file;
}

ConfigOutcome runConfig(const StressConfig& c, const fs::path& sceneFile, const RunSettings& s) {
  const fs::path dir = s.outDir / "runs" / c.name;
  fs::remove_all(dir);
  ConfigOutcome out;
  for (RunKind k : runsOf(c)) {
    out.runs.push_back(runOne(k, sceneFile, pointLight(c), dir / runName(k), s));
    out.seconds += out.runs.back().process.seconds;
  }
  return out;
}

}  // namespace shadowvol::stress

#include "cli_common.h"

#include <cstdio>
#include <filesystem>
#include <unistd.h>

#include "shadowvol/error.h"

namespace shadowvol::cli {

void addJsonOption(CLI::App& cmd, bool& json) {
  cmd.add_flag("--json", json, "Print one JSON document with the results on stdout (text otherwise)");
}

void addSceneOptions(CLI::App& cmd, SceneOptions& o) {
  cmd.add_option("--scene", o.scene,
                 "Scene file (JSON, see README 'Scene files'); without it, the built-in default scene "
                 "(a sphere floating above a ground plane under a spot light)")
      ->check(CLI::ExistingFile);
  addJsonOption(cmd, o.json);
}

Scene loadSceneOrDefault(const std::string& path) {
  if (path.empty()) return defaultScene();
  SceneLoadResult r = loadScene(path);
  for (const auto& w : r.warnings) std::fprintf(stderr, "shadowvol: warning: %s\n", w.c_str());
  return std::move(r.scene);
}

void checkResolution(const std::string& option, int resolution) {
  if (resolution < 2)
    throw InputError("command line", option, std::to_string(resolution), "the resolution must be at least 2");
  if (resolution > kMaxResolution)
    throw InputError("command line", option, std::to_string(resolution),
                     "above the limit of " + std::to_string(kMaxResolution) + " texels a side");
  const std::uint64_t need = depthMapBytes(resolution, resolution);
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  const std::uint64_t physical = pages > 0 && pageSize > 0 ? std::uint64_t(pages) * std::uint64_t(pageSize) : 0;
  if (physical > 0 && need > physical / 2)
    throw InputError("command line", option, std::to_string(resolution),
                     "needs about " + std::to_string(need >> 20) + " MiB, more than half of this machine's " +
                         std::to_string(physical >> 20) + " MiB");
}

void checkOutputPath(const std::string& option, const std::string& path) {
  if (path.empty()) throw InputError("command line", option, "\"\"", "an output path is required");
  const std::filesystem::path p(path);
  const auto dir = p.has_parent_path() ? p.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw InputError("command line", option, path, "the folder " + dir.string() + " does not exist");
  if (std::filesystem::is_directory(p, ec)) throw InputError("command line", option, path, "is a folder, not a file");
}

namespace {
std::string gCommandLine = "shadowvol";
}

const std::string& commandLine() { return gCommandLine; }

void setCommandLine(int argc, char** argv) {
  gCommandLine = "shadowvol";
  for (int k = 1; k < argc; ++k) gCommandLine += std::string(" ") + argv[k];
}

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

nlohmann::json describeScene(const Scene& s) {
  auto v3 = [](const glm::dvec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); };
  nlohmann::json light = {{"type", s.light.type == LightType::Spot ? "spot" : "directional"},
                          {"position", v3(s.light.position)},
                          {"direction", v3(s.light.direction)},
                          {"up", v3(lightUp(s.light))},
                          {"near", s.light.nearPlane},
                          {"far", s.light.farPlane}};
  if (s.light.type == LightType::Spot) light["fov"] = s.light.fovYDegrees;
  else light["extent"] = s.light.halfExtent;
  const Bounds3 b = s.bounds();
  return {{"source", s.source},
          {"objects", s.objects.size()},
          {"triangles", s.triangleCount()},
          {"bounds", {{"min", v3(b.min)}, {"max", v3(b.max)}}},
          {"light", light},
          {"camera",
           {{"eye", v3(s.camera.eye)},
            {"target", v3(s.camera.target)},
            {"up", v3(s.camera.up)},
            {"fov", s.camera.fovYDegrees},
            {"width", s.camera.width},
            {"height", s.camera.height},
            {"near", s.camera.nearPlane},
            {"far", s.camera.farPlane}}}};
}

}  // namespace shadowvol::cli

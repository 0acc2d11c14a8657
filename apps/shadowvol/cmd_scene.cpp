// shadowvol scene: describe a scene as loaded (fitted light and camera included), export its triangles.
#include <cstdio>
#include <iostream>

#include "cli_common.h"
#include "shadowvol/mesh_io.h"

namespace shadowvol::cli {

void registerSceneCommand(CLI::App& app, Runner& run) {
  auto* cmd = app.add_subcommand("scene", "Load a scene, print what was loaded (triangles, bounds, the light and "
                                          "camera with fitted near/far) and optionally export its geometry");
  auto opts = std::make_shared<SceneOptions>();
  auto exportPath = std::make_shared<std::string>();
  addSceneOptions(*cmd, *opts);
  cmd->add_option("--export", *exportPath,
                  "Write the scene's world-space triangles to this file (.ply binary, .obj, .off or .stl), "
                  "exactly the geometry the other subcommands use");
  cmd->callback([&run, opts, exportPath] {
    run = [opts, exportPath] {
      if (!exportPath->empty()) checkOutputPath("--export", *exportPath);
      const Scene scene = loadSceneOrDefault(opts->scene);
      if (!exportPath->empty()) exportSceneMesh(scene, *exportPath);
      nlohmann::json j = describeScene(scene);
      if (!exportPath->empty()) j["export"] = *exportPath;
      if (opts->json) {
        std::cout << j.dump(2) << '\n';
      } else {
        std::printf("scene %s: %zu objects, %zu triangles\n", scene.source.c_str(), scene.objects.size(),
                    scene.triangleCount());
        for (const auto& o : scene.objects)
          std::printf("  %-16s %-10s %8zu triangles\n", o.name.c_str(), o.type.c_str(), o.mesh.triangleCount());
        std::printf("light  %s\ncamera %s\n", j["light"].dump().c_str(), j["camera"].dump().c_str());
        if (!exportPath->empty()) std::printf("wrote %s\n", exportPath->c_str());
      }
      return kOk;
    };
  });
}

}  // namespace shadowvol::cli

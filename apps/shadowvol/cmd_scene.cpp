// shadowvol scene: describe a scene as loaded (fitted light and camera included), export its triangles.
#include <cstdio>
#include <iostream>

#include "cli_common.h"
#include "shadowvol/report_json.h"
#include "shadowvol/version.h"
#include "shadowvol/mesh_io.h"

namespace shadowvol::cli {

void registerSceneCommand(CLI::App& app, Runner& run) {
  auto* cmd = app.add_subcommand("scene", "Load a scene, print what was loaded (triangles, bounds, the light and "
                                          "camera with fitted near/far) and optionally export its geometry");
  auto opts = std::make_shared<SceneOptions>();
  auto exportPath = std::make_shared<std::string>();
  auto worldCoords = std::make_shared<bool>(false);
  addSceneOptions(*cmd, *opts);
  cmd->add_option("--export", *exportPath,
                  "Write the scene's world-space triangles to this file (.ply binary, .obj, .off, .stl, .gltf or .glb), "
                  "exactly the geometry the other subcommands use");
  cmd->add_flag("--world-coords", *worldCoords,
                "With --export: world coordinates in double precision (PLY double properties, OBJ/OFF 17 digits; "
                "not STL) instead of coordinates relative to the scene's local origin (README 'Far from the origin')");
  cmd->callback([&run, opts, exportPath, worldCoords] {
    run = [opts, exportPath, worldCoords] {
      if (!exportPath->empty()) checkOutputPath("--export", *exportPath);
      const Scene scene = loadSceneOrDefault(opts->scene);
      if (!exportPath->empty()) checkNotAnInput("--export", *exportPath, *exportPath, scene.files);
      if (!exportPath->empty()) exportSceneMesh(scene, *exportPath, *worldCoords);
      nlohmann::json j = describeScene(scene);
      j["shadowvolVersion"] = SHADOWVOL_VERSION;
      if (!exportPath->empty()) j["export"] = *exportPath;
      if (opts->json) {
        std::cout << jsonText(j) << '\n';
      } else {
        std::printf("scene %s: %zu objects, %zu triangles\n", scene.source.c_str(), scene.objects.size(),
                    scene.triangleCount());
        for (const auto& o : scene.objects)
          std::printf("  %-16s %-10s %8zu triangles\n", o.name.c_str(), o.type.c_str(), o.mesh.triangleCount());
        std::printf("bounds %s\norigin %s%s\n", j["bounds"].dump().c_str(), j["origin"].dump().c_str(),
                    scene.origin == glm::dvec3(0.0) ? "" : " (stored and exported coordinates are relative to it)");
        if (j.contains("lights"))
          for (std::size_t k = 0; k < j["lights"].size(); ++k)
            std::printf("light %zu %s\n", k, j["lights"][k].dump().c_str());
        else
          std::printf("light  %s\n", j["light"].dump().c_str());
        std::printf("camera %s\n", j["camera"].dump().c_str());
        if (!exportPath->empty()) std::printf("wrote %s\n", exportPath->c_str());
      }
      return kOk;
    };
  });
}

}  // namespace shadowvol::cli

// shadowvol depth: capture the light's depth map (Embree on the CPU, or the GPU's light pass) and
// write it as PFM + JSON.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "capture_device.h"
#include "cli_common.h"
#include "shadowvol/report_json.h"
#include "shadowvol/depth_map_io.h"
#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/error.h"
#include "shadowvol/version.h"

namespace shadowvol::cli {

void registerDepthCommand(CLI::App& app, Runner& run) {
  struct Options {
    SceneOptions scene;
    int resolution = 512;
    int light = 0;
    int guard = kVolumeGuardTexels;
    std::string capture = "auto";
    std::string out;
    CaptureDeviceOptions device;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand("depth",
                                 "Capture the light's depth map (by ray casting with Embree, or on the GPU "
                                 "with --device gpu) and write it as a PFM with a JSON side file (matrices, "
                                 "near/far, capture mode)");
  addSceneOptions(*cmd, o->scene);
  addLightFitOption(*cmd, o->scene.fit);
  addLightChoiceOption(*cmd, o->light);
  cmd->add_option("--resolution", o->resolution,
                  "Depth map size N (N x N texels), " + std::to_string(kMinVolumeMapSide) + ".." +
                      std::to_string(kMaxResolution))
      ->capture_default_str();
  cmd->add_option("--guard", o->guard,
                  "Texels the map reaches past the light's window on every side, the window's texels kept (the map "
                  "is N + 2 G a side): a volume built from it puts the map's outermost ring, on the far plane, "
                  "outside the window, so a shadow crossing the window's edge is not lit along it. The default is "
                  "what build and render use; 0: the window's N x N texels alone")
      ->check(CLI::Range(0, kMaxGuardTexels))
      ->capture_default_str();
  addCaptureOption(*cmd, o->capture);
  addCaptureDeviceOptions(*cmd, o->device);
  cmd->add_option("--out", o->out, "Output PFM (the side file is written beside it as <out>.json)")->required();
  cmd->callback([&run, o] {
    checkCaptureDeviceOptions(o->device, false);
    run = [o] {
      checkResolution("--resolution", o->resolution, DepthMapUse::MapOnly);
      checkGuardedDepthMapSize(o->resolution, o->resolution, o->guard, "command line", "--resolution", DepthMapUse::MapOnly);
      checkOutputPath("--out", o->out);
      checkDepthMapPath(o->out, "command line", "--out");
      Scene scene = loadSceneOrDefault(o->scene.scene, nullptr, sceneUse(o->scene));
      checkOneMapLight(scene, std::size_t(std::max(o->light, 0)));  // by its pointer, before any note
      // An unrefined volume's map, as build --depth reads it.
      const ResolvedCapture capture = resolveCapture(o->capture, scene, CaptureUse::Volume);
      const CaptureMode mode = capture.mode;
      checkNotAnInput("--out", o->out, o->out, scene.files);
      checkNotAnInput("--out", o->out, depthSidecarPath(o->out), scene.files, "its side file");
      chooseLight(scene, o->light);
      const nlohmann::json lightFit = applyLightFit(scene, o->scene, o->resolution);
      const auto warnings = warnAboutCapture(scene, o->resolution, o->resolution, mode);
      const auto t0 = std::chrono::steady_clock::now();
      const DepthMap map = captureOnDevice(o->device, scene, o->resolution, o->resolution, mode, o->guard);
      const double msCapture = msSince(t0);
      writeDepthMap(map, o->out);
      float lo = DepthMap::kNoHit, hi = 0.0f;
      for (float d : map.depth)
        if (!DepthMap::isNoHit(d)) {
          lo = std::min(lo, d);
          hi = std::max(hi, d);
        }
      const std::size_t hits = map.hitCount();
      nlohmann::json j = {{"scene", describeScene(scene)},
                          {"lightFit", lightFit},
                          {"resolution", o->resolution},
                          {"guard", o->guard},
                          {"width", map.width},
                          {"height", map.height},
                          {"capture", toString(mode)},

                          {"device", o->device.device},
                          {"texels", map.depth.size()},
                          {"hits", hits},
                          {"depthMin", hits ? nlohmann::json(lo) : nlohmann::json()},
                          {"depthMax", hits ? nlohmann::json(hi) : nlohmann::json()},
                          {"msCapture", msCapture},
                          {"out", o->out},
                          {"sidecar", depthSidecarPath(o->out).string()},
                          {"warnings", warnings},
                          {"shadowvolVersion", SHADOWVOL_VERSION}};
      if (!capture.autoReason.empty()) j["captureAuto"] = capture.autoReason;  // --capture auto's reason
      if (o->scene.json) {
        std::cout << jsonText(j) << '\n';
      } else {
        std::printf("depth %dx%d (%s capture, %s) of %s", o->resolution, o->resolution, toString(mode),
                    o->device.device.c_str(), scene.source.c_str());
        if (o->guard > 0) std::printf(", with a guard band of %d texels a side: %dx%d", o->guard, map.width, map.height);
        std::printf(": %zu of %zu texels hit", hits, map.depth.size());
        if (hits) std::printf(", depth %.6g .. %.6g", lo, hi);
        std::printf("\ncapture %.1f ms\nwrote %s and %s\n", msCapture, o->out.c_str(),
                    depthSidecarPath(o->out).string().c_str());
      }
      return kOk;
    };
  });
}

}  // namespace shadowvol::cli

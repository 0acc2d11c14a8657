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
  addCaptureOption(*cmd, o->capture);
  addCaptureDeviceOptions(*cmd, o->device);
  cmd->add_option("--out", o->out, "Output PFM (the side file is written beside it as <out>.json)")->required();
  cmd->callback([&run, o] {
    checkCaptureDeviceOptions(o->device, false);
    run = [o] {
      checkResolution("--resolution", o->resolution, DepthMapUse::MapOnly);
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
      const DepthMap map = captureOnDevice(o->device, scene, o->resolution, o->resolution, mode);
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
        std::printf("depth %dx%d (%s capture, %s) of %s: %zu of %zu texels hit", o->resolution, o->resolution,
                    toString(mode), o->device.device.c_str(), scene.source.c_str(), hits, map.depth.size());
        if (hits) std::printf(", depth %.6g .. %.6g", lo, hi);
        std::printf("\ncapture %.1f ms\nwrote %s and %s\n", msCapture, o->out.c_str(),
                    depthSidecarPath(o->out).string().c_str());
      }
      return kOk;
    };
  });
}

}  // namespace shadowvol::cli

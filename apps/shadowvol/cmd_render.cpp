// shadowvol render: the GPU production path (headless EGL + OpenGL): light pass, camera pass,
// shadows by the chosen method; writes the image (PNG) and the stencil counts.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

#include "cli_verbosity.h"
#include "render_options.h"
#include "shadowvol/report_json.h"
#include "shadowvol/version.h"
#include "shadowvol/error.h"
#include "shadowvol/image_io.h"
#include "shadowvol/gl/renderer.h"
#include "shadowvol/output_lock.h"
#include "shadowvol/temporary_files.h"

namespace shadowvol::cli {

namespace {

// "s.png" -> "s-light2.png": where light k's stencil goes (k >= 1; light 0's at the path given).
std::filesystem::path lightStencilPath(const std::filesystem::path& picture, std::size_t k) {
  std::filesystem::path p = picture;
  p.replace_filename(picture.stem().string() + "-light" + std::to_string(k) + picture.extension().string());
  return p;
}

// "s.png" -> "s-counts.png": where --stencil's raw counts go.
std::filesystem::path stencilCountsPath(const std::filesystem::path& picture) {
  std::filesystem::path p = picture;
  return p.replace_filename(picture.stem().string() + "-counts" + picture.extension().string());
}

// The images are PNG: another extension would hold PNG bytes under a misleading name.
void checkPngPath(const char* option, const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (auto& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".png") throw InputError("command line", option, path, "must end in .png (the images are PNG)");
}

}  // namespace

void registerRenderCommand(CLI::App& app, Runner& run) {
  struct Options {
    RenderCliOptions render;
    int frames = 1;
    std::string out;
    std::string stencil;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "render", "Render the scene on the GPU (headless EGL + OpenGL core): light depth pass, camera pass, shadows by "
                "the chosen method; write the image as PNG (top row first) and optionally the stencil counts");
  addRenderOptions(*cmd, o->render);
  cmd->add_option("--frames", o->frames, "Render this many frames and report the median time of each pass")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_option("--out", o->out, "Output image (PNG, RGBA, top row first)")->required();
  cmd->add_option("--stencil", o->stencil,
                  "hybrid, silhouette: also write the stencil as a picture (RGB PNG: 0 = lit black, +1 grey, more "
                  "brighter, negative red) and the raw counts beside it as <name>-counts.png (8-bit grey, value = "
                  "count, wrapping); with several lights, light K's beside them as <name>-lightK.png and "
                  "<name>-lightK-counts.png");
  cmd->callback([&run, o] {
    checkRenderOptionConflicts(o->render);
    run = [o] {
      checkOutputPath("--out", o->out);
      checkPngPath("--out", o->out);
      if (!o->stencil.empty()) {
        checkOutputPath("--stencil", o->stencil);
        checkPngPath("--stencil", o->stencil);
        if (o->render.method != "hybrid" && o->render.method != "silhouette")
          throw OptionConflict("command line", "--stencil", o->stencil, "only hybrid and silhouette use the stencil");
      }
      Scene scene = loadSceneOrDefault(o->render.scene.scene);
      checkNotAnInput("--out", o->out, o->out, scene.files);
      if (!o->stencil.empty()) {
        // Every light's picture and counts: none may be the image or one of the scene's files.
        const std::filesystem::path out = std::filesystem::weakly_canonical(o->out);
        for (std::size_t k = 0; k < scene.lightCount(); ++k) {
          const std::filesystem::path picture = k == 0 ? std::filesystem::path(o->stencil) : lightStencilPath(o->stencil, k);
          for (const auto& file : {picture, stencilCountsPath(picture)}) {
            if (out == std::filesystem::weakly_canonical(file))
              throw InputError("command line", "--stencil", o->stencil,
                               "would overwrite the image (--out " + o->out + ") with " + file.string() +
                                   ": name another file");
            checkNotAnInput("--stencil", o->stencil, file, scene.files, file == picture ? "" : "its counts file");
          }
        }
      }
      std::string captureAuto;
      gl::RenderOptions ro = toRenderOptions(o->render, scene, &captureAuto);
      const nlohmann::json lightFit = applyLightFit(scene, o->render.scene, o->render.resolution);
      const auto oracle = attachDepthOracle(scene, ro);
      std::vector<std::string> warnings;
      if (capturesMap(ro)) warnings = warnAboutCapture(scene, ro.depthWidth, ro.depthHeight, ro.capture, &ro.volumeOptions);
      ro.readStencil = !o->stencil.empty() || drawsShadowVolume(ro.method);
      gl::Renderer renderer(toRendererOptions(o->render));
      verboseNote("GL context: %s, %s (EGL platform %s)", renderer.info().glRenderer.c_str(),
                  renderer.info().glVersion.c_str(), renderer.info().platform.c_str());
      renderer.setScene(scene);

      std::map<std::string, std::vector<double>> times;
      std::vector<std::string> order;
      std::vector<double> totals;
      gl::RenderResult result;
      for (int f = 0; f < o->frames; ++f) {
        result = renderer.render(ro);
        for (const auto& p : shadowvol::passTotals(result.passes)) {  // a cube volume's per-face passes: their sums
          if (!times.count(p.name)) order.push_back(p.name);
          times[p.name].push_back(p.ms);
        }
        totals.push_back(result.totalMs);
      }
      auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v.empty() ? 0.0 : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
      };
      // The image, then the stencil files: a write that fails (a full disk, a folder in the way)
      // takes the files this run wrote before it along, so no half set is left behind.
      // A signal that ends the command half-way takes them along too (OutputSetGuard). Another run
      // writing the same set waits for this one, or this one for it (OutputLock).
      std::optional<OutputLocks> locks;
      if (!o->stencil.empty()) locks.emplace(std::vector{folderOf(o->out), folderOf(o->stencil)});
      const OutputSetGuard set;
      std::vector<std::filesystem::path> written;
      written.reserve(2 + 2 * result.otherLights.size() + 1);  // no allocation between a write and its record
      auto png = [&](const std::filesystem::path& path, int width, int height, int channels,
                     const std::vector<std::uint8_t>& pixels) {
        writePng(path, width, height, channels, pixels);
        written.push_back(path);
      };
      try {
        png(o->out, result.width, result.height, 4, result.rgba);
        if (!o->stencil.empty()) {
          png(o->stencil, result.width, result.height, 3, stencilPicture(result.stencil));
          png(stencilCountsPath(o->stencil), result.width, result.height, 1, result.stencil);
          // Each further light's stencil beside it (a second probe's finding: only light 0's was written).
          for (std::size_t k = 0; k < result.otherLights.size(); ++k) {
            const auto& other = result.otherLights[k];
            if (other.stencil.empty()) continue;
            const std::filesystem::path picture = lightStencilPath(o->stencil, k + 1);
            png(picture, other.width, other.height, 3, stencilPicture(other.stencil));
            png(stencilCountsPath(picture), other.width, other.height, 1, other.stencil);
          }
        }
      } catch (...) {
        std::error_code ec;
        for (const auto& path : written) std::filesystem::remove(path, ec);
        throw;
      }
      std::size_t shadowed = 0;
      for (auto s : result.stencil) shadowed += s != 0;

      const gl::ContextInfo& info = renderer.info();
      nlohmann::json passes = nlohmann::json::array();
      for (const auto& name : order) {
        const auto& v = times[name];
        passes.push_back({{"name", name},
                          {"ms", median(v)},
                          {"min", *std::min_element(v.begin(), v.end())},
                          {"max", *std::max_element(v.begin(), v.end())}});
      }
      const bool stencilMethod = drawsShadowVolume(ro.method);
      nlohmann::json j = {
          {"scene", describeScene(scene)},
          {"lightFit", lightFit},
          {"gl", gl::describeContext(info)},
          {"method", o->render.method},
          {"volume", o->render.method == "hybrid" ? nlohmann::json(gl::toString(ro.volume)) : nlohmann::json()},
          {"depthFrom", depthFromUsed(o->render, ro, result)},
          {"resolution", o->render.resolution},
          
          {"triangulation", o->render.shape.triangulation},
          {"blur", o->render.shape.blur},
          {"cap", o->render.shape.cap},
          {"refine", o->render.shape.refine},
          {"bias", result.biasUsed},
          {"size", {result.width, result.height}},
          {"frames", o->frames},
          {"timing", gl::toString(result.timing)},
          {"passes", passes},
          {"frameMs", median(totals)},
          {"volumeTriangles", result.volumeTriangles},
          {"volumeQuads", result.gpuVolumeQuads},
          {"volumeQuadsDrawn", result.gpuVolumeQuadsDrawn},
          {"volumeDraw", result.gpuVolumeQuads ? nlohmann::json(gl::toString(result.gpuVolumeDrawUsed)) : nlohmann::json()},
          {"volumeCount", stencilMethod ? nlohmann::json(gl::toString(result.volumeCountUsed)) : nlohmann::json()},
          {"zPassRefused", result.zPassRefused.empty() ? nlohmann::json() : nlohmann::json(result.zPassRefused)},
          {"stencilNonZeroPixels", result.stencil.empty() ? nlohmann::json() : nlohmann::json(shadowed)},
          {"receiversOnly", result.receiversOnly},
          {"warnings", warnings},
          {"skippedCasters", result.skippedCasters},
          {"out", o->out},
          {"stencil", o->stencil.empty() ? nlohmann::json() : nlohmann::json(o->stencil)}};
      j["capture"] = capturesMap(ro) ? nlohmann::json(toString(ro.capture)) : nlohmann::json();
      if (!captureAuto.empty()) j["captureAuto"] = captureAuto;  // --capture auto's reason
      if (result.gpuVolumeDrawUsed == gl::GpuVolumeDraw::Refined)
        j["gpuRefinement"] = {{"boundaryEdges", result.gpuBoundaryEdges},
                              {"crossingFallbacks", result.gpuCrossingFallbacks}};
      j["shadowvolVersion"] = SHADOWVOL_VERSION;
      if (result.volumeStats) j["volumeBuild"] = describeVolumeStats(*result.volumeStats);
      if (o->render.scene.json) {
        std::cout << jsonText(j) << '\n';
      } else {
        std::printf("GL: %s on %s (%s, EGL platform %s%s%s)\n", info.glVersion.c_str(), info.glRenderer.c_str(),
                    info.glVendor.c_str(), info.platform.c_str(), info.device.empty() ? "" : ", device ",
                    info.device.c_str());
        // A spot or directional light's volume map has a guard band (light.h).
        const bool band = o->render.method == "hybrid" && scene.light.type != LightType::Point;
        std::printf("%s of %s: %dx%d image, %dx%d depth map%s%s, %s capture", o->render.method.c_str(),
                    scene.source.c_str(), result.width, result.height, o->render.resolution, o->render.resolution,
                    band ? (" and a guard band of " + std::to_string(kVolumeGuardTexels) + " texels a side").c_str() : "",
                    result.explicitDepthUsed == gl::ExplicitDepth::Rays && ro.volume == gl::VolumeSource::Explicit ? " (ray-cast)" : "", capturesMap(ro) ? toString(ro.capture) : "no");
        if (o->render.method == "hybrid")
          std::printf(", %s volume, %s triangulation%s, %s cap, %zu volume triangles, %zu stencil pixels != 0",
                      gl::toString(ro.volume), o->render.shape.triangulation.c_str(), o->render.shape.blur ? ", blur" : "", o->render.shape.cap.c_str(),
                      result.volumeTriangles, shadowed);
        if (result.gpuVolumeQuads > 0)
          std::printf(", %zu of %zu quads drawn (%s)", result.gpuVolumeQuadsDrawn, result.gpuVolumeQuads,
                      gl::toString(result.gpuVolumeDrawUsed));
        if (stencilMethod)
          std::printf(", %s%s%s", gl::toString(result.volumeCountUsed), result.zPassRefused.empty() ? "" : " (z-pass not safe: ",
                      result.zPassRefused.empty() ? "" : (result.zPassRefused + ")").c_str());
        if (result.volumeStats && result.volumeStats->refinedCells > 0)
          std::printf(", refined: %zu boundary edges, %zu rays, %zu without a crossing found (crossings: %s)",
                      result.volumeStats->boundaryEdges, result.volumeStats->raysCast,
                      result.volumeStats->crossingFallbacks, gl::toString(ro.refineCrossings));
        if (result.gpuVolumeDrawUsed == gl::GpuVolumeDraw::Refined)
          std::printf(", refined on the GPU: %zu boundary edges, %zu without a crossing found (crossings: gpu-walk)",
                      result.gpuBoundaryEdges, result.gpuCrossingFallbacks);
        if (!result.receiversOnly.empty()) {
          std::printf("\nreceivers only (open, cast no silhouette shadow):");
          for (const auto& r : result.receiversOnly) std::printf(" %s", r.c_str());
        }
        if (!result.skippedCasters.empty()) {
          std::printf("\nskipped casters (behind the spot light):");
          for (const auto& r : result.skippedCasters) std::printf(" %s", r.c_str());
        }
        std::printf("\npass times (%s, median of %d frame%s):", gl::toString(result.timing), o->frames,
                    o->frames > 1 ? "s" : "");
        for (const auto& p : passes) std::printf(" %s %.2f ms,", p["name"].get<std::string>().c_str(), p["ms"].get<double>());
        std::printf(" frame %.2f ms\nwrote %s%s%s\n", median(totals), o->out.c_str(), o->stencil.empty() ? "" : " and ",
                    o->stencil.c_str());
      }
      return kOk;
    };
  });
}

}  // namespace shadowvol::cli

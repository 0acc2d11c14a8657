// shadowvol render: the GPU production path (headless EGL + OpenGL): light pass, camera pass,
// shadows by the chosen method; writes the image (PNG) and the stencil counts.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <regex>

#include "cli_common.h"
#include "shadowvol/error.h"
#include "shadowvol/image_io.h"
#include "shadowvol/gl/renderer.h"

namespace shadowvol::cli {

namespace {

std::pair<int, int> parseSize(const std::string& text) {
  static const std::regex re("^([0-9]{1,6})x([0-9]{1,6})$");
  std::smatch m;
  if (!std::regex_match(text, m, re))
    throw InputError("command line", "--size", text, "expected WIDTHxHEIGHT, for example 640x480");
  const int w = std::stoi(m[1]), h = std::stoi(m[2]);
  if (w < 1 || h < 1 || w > 16384 || h > 16384)
    throw InputError("command line", "--size", text, "width and height must be between 1 and 16384");
  return {w, h};
}

}  // namespace

void registerRenderCommand(CLI::App& app, Runner& run) {
  struct Options {
    SceneOptions scene;
    std::string method = "hybrid";
    std::string volume = "gpu";
    int resolution = 512;
    std::string capture = "back";
    std::string triangulation = "perfect";
    bool blur = false;
    double blurOffset = 0.0;
    std::optional<double> bias;
    std::string cap = "exact";
    std::string size;
    double shadowBias = 0.0;
    double shadowSlope = 1.0;
    int frames = 1;
    std::string platform = "auto";
    std::string shaderDir;
    std::string out;
    std::string stencil;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "render", "Render the scene on the GPU (headless EGL + OpenGL core): light depth pass, camera pass, shadows by "
                "the chosen method; write the image as PNG (top row first) and optionally the stencil counts");
  addSceneOptions(*cmd, o->scene);
  cmd->add_option("--method", o->method,
                  "hybrid (the shadow volume, z-fail stencil), shadowmap (hardware depth compare), pcf3 / pcf5 "
                  "(percentage-closer filtering over 3x3 / 5x5 texels), none (no shadows)")
      ->check(CLI::IsMember({"hybrid", "shadowmap", "pcf3", "pcf5", "none"}))
      ->capture_default_str();
  cmd->add_option("--volume", o->volume,
                  "hybrid: gpu (drawn straight from the depth texture, no read-back: production) or explicit (depth "
                  "read back, the CPU-built mesh uploaded)")
      ->check(CLI::IsMember({"gpu", "explicit"}))
      ->capture_default_str();
  cmd->add_option("--resolution", o->resolution, "Light depth map size N (N x N texels)")->capture_default_str();
  cmd->add_option("--capture", o->capture, "back, front or midpoint (see 'shadowvol depth --help')")
      ->check(CLI::IsMember({"back", "front", "midpoint"}))
      ->capture_default_str();
  cmd->add_option("--triangulation", o->triangulation, "hybrid: perfect or fixed quad diagonals")
      ->check(CLI::IsMember({"fixed", "perfect"}))
      ->capture_default_str();
  cmd->add_flag("--blur", o->blur, "hybrid: depth blurring (9 bilinear samples 1.5 texels apart)");
  cmd->add_option("--blur-offset", o->blurOffset, "hybrid: world units added to blurred depths")->capture_default_str();
  cmd->add_option("--bias", o->bias, "hybrid: world units pushing the sheet away from the light (default: README 'Bias')");
  cmd->add_option("--cap", o->cap, "hybrid: exact (far-plane parts dropped, exact cap) or quad (the thesis's far rectangle)")
      ->check(CLI::IsMember({"exact", "quad"}))
      ->capture_default_str();
  cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT (default: the scene camera's)");
  cmd->add_option("--shadow-bias", o->shadowBias, "Shadow maps: constant depth bias, world units")->capture_default_str();
  cmd->add_option("--shadow-slope", o->shadowSlope,
                  "Shadow maps: slope-scaled bias, in texel footprints x tan(angle to the light)")
      ->capture_default_str();
  cmd->add_option("--frames", o->frames, "Render this many frames and report the median time of each pass")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_option("--platform", o->platform,
                  "EGL platform: auto (device, then Mesa surfaceless, then the default display), device, "
                  "surfaceless, default")
      ->check(CLI::IsMember({"auto", "device", "surfaceless", "default"}))
      ->capture_default_str();
  cmd->add_option("--shader-dir", o->shaderDir,
                  "Load GLSL from this folder instead of the embedded copies (also: $SHADOWVOL_SHADER_DIR)")
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--out", o->out, "Output image (PNG, RGBA, top row first)")->required();
  cmd->add_option("--stencil", o->stencil,
                  "hybrid: also write the stencil counts as an 8-bit grey PNG (value = count, wrapping; 0 = lit)");
  cmd->callback([&run, o] {
    run = [o] {
      checkOutputPath("--out", o->out);
      if (!o->stencil.empty()) {
        checkOutputPath("--stencil", o->stencil);
        if (o->method != "hybrid")
          throw InputError("command line", "--stencil", o->stencil, "only the hybrid method uses the stencil");
      }
      checkResolution("--resolution", o->resolution);
      if (o->blurOffset != 0.0 && !o->blur)
        throw InputError("command line", "--blur-offset", std::to_string(o->blurOffset), "needs --blur");
      if (o->bias && (!std::isfinite(*o->bias) || *o->bias < 0.0))
        throw InputError("command line", "--bias", std::to_string(*o->bias), "must be finite and >= 0");
      if (!std::isfinite(o->shadowBias) || !std::isfinite(o->shadowSlope) || o->shadowSlope < 0.0)
        throw InputError("command line", "--shadow-slope", std::to_string(o->shadowSlope), "must be finite and >= 0");

      gl::RenderOptions ro;
      gl::parseShadowMethod(o->method, ro.method);
      gl::parseVolumeSource(o->volume, ro.volume);
      ro.depthWidth = ro.depthHeight = o->resolution;
      parseCaptureMode(o->capture, ro.capture);
      parseTriangulation(o->triangulation, ro.volumeOptions.triangulation);
      parseFarCap(o->cap, ro.volumeOptions.cap);
      ro.volumeOptions.blur = o->blur;
      ro.volumeOptions.blurOffset = o->blurOffset;
      ro.volumeOptions.bias = o->bias;
      ro.shadowBiasConstant = o->shadowBias;
      ro.shadowBiasSlope = o->shadowSlope;
      ro.readStencil = !o->stencil.empty() || o->method == "hybrid";
      if (!o->size.empty()) std::tie(ro.imageWidth, ro.imageHeight) = parseSize(o->size);

      const Scene scene = loadSceneOrDefault(o->scene.scene);
      gl::RendererOptions rendererOptions;
      rendererOptions.context.platform = o->platform;
      rendererOptions.shaderDir = o->shaderDir;
      gl::Renderer renderer(rendererOptions);
      renderer.setScene(scene);

      std::map<std::string, std::vector<double>> times;
      std::vector<std::string> order;
      std::vector<double> totals;
      gl::RenderResult result;
      for (int f = 0; f < o->frames; ++f) {
        result = renderer.render(ro);
        for (const auto& p : result.passes) {
          if (!times.count(p.name)) order.push_back(p.name);
          times[p.name].push_back(p.ms);
        }
        totals.push_back(result.totalMs);
      }
      auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v.empty() ? 0.0 : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
      };
      writePng(o->out, result.width, result.height, 4, result.rgba);
      std::size_t shadowed = 0;
      if (!o->stencil.empty()) writePng(o->stencil, result.width, result.height, 1, result.stencil);
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
      nlohmann::json j = {
          {"scene", describeScene(scene)},
          {"gl",
           {{"platform", info.platform}, {"device", info.device}, {"eglVendor", info.eglVendor},
            {"glVendor", info.glVendor}, {"glRenderer", info.glRenderer}, {"glVersion", info.glVersion}}},
          {"method", o->method},
          {"volume", o->method == "hybrid" ? nlohmann::json(o->volume) : nlohmann::json()},
          {"resolution", o->resolution},
          {"capture", o->capture},
          {"triangulation", o->triangulation},
          {"blur", o->blur},
          {"cap", o->cap},
          {"bias", result.biasUsed},
          {"size", {result.width, result.height}},
          {"frames", o->frames},
          {"timing", gl::toString(result.timing)},
          {"passes", passes},
          {"frameMs", median(totals)},
          {"volumeTriangles", result.volumeTriangles},
          {"stencilNonZeroPixels", o->method == "hybrid" ? nlohmann::json(shadowed) : nlohmann::json()},
          {"out", o->out},
          {"stencil", o->stencil.empty() ? nlohmann::json() : nlohmann::json(o->stencil)}};
      if (o->scene.json) {
        std::cout << j.dump(2) << '\n';
      } else {
        std::printf("GL: %s on %s (%s, EGL platform %s%s%s)\n", info.glVersion.c_str(), info.glRenderer.c_str(),
                    info.glVendor.c_str(), info.platform.c_str(), info.device.empty() ? "" : ", device ",
                    info.device.c_str());
        std::printf("%s of %s: %dx%d image, %dx%d depth map, %s capture", o->method.c_str(), scene.source.c_str(),
                    result.width, result.height, o->resolution, o->resolution, o->capture.c_str());
        if (o->method == "hybrid")
          std::printf(", %s volume, %s triangulation%s, %s cap, %zu volume triangles, %zu stencil pixels != 0",
                      o->volume.c_str(), o->triangulation.c_str(), o->blur ? ", blur" : "", o->cap.c_str(),
                      result.volumeTriangles, shadowed);
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

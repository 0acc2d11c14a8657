// shadowvol build: depth map -> closed shadow-volume mesh, exported as PLY/OBJ/OFF/STL.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "capture_device.h"
#include "cli_common.h"
#include "shadowvol/report_json.h"
#include "shadowvol/version.h"
#include "shadowvol/cube_map.h"
#include "shadowvol/cube_volume.h"
#include "shadowvol/depth_map_io.h"
#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/embree/embree_depth_oracle.h"
#include "shadowvol/error.h"
#include "shadowvol/mesh_io.h"
#include "shadowvol/volume_builder.h"

namespace shadowvol::cli {

void registerBuildCommand(CLI::App& app, Runner& run) {
  struct Options {
    SceneOptions scene;
    std::string depth;
    int resolution = 512;
    int light = 0;
    std::string capture = "auto";
    VolumeCliOptions volume;
    bool noFlatten = false;
    bool worldCoords = false;
    std::string out;
    CaptureDeviceOptions device;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "build", "Build the explicit shadow volume of the light: capture the depth map (Embree, or the GPU with --device "
               "gpu) or read one, turn it "
               "into a closed, outward-oriented triangle mesh and write it (.ply binary, .obj, .off, .stl, .gltf, .glb)");
  addSceneOptions(*cmd, o->scene);
  addLightFitOption(*cmd, o->scene.fit);
  addLightChoiceOption(*cmd, o->light);
  auto* depthOpt = cmd->add_option("--depth", o->depth,
                                   "Build from this depth map (PFM + side file from 'shadowvol depth') instead of "
                                   "capturing one from the scene");
  auto* resOpt = cmd->add_option("--resolution", o->resolution,
                                 "Depth map size N (N x N texels), " + std::to_string(kMinVolumeMapSide) + ".." + std::to_string(kMaxResolution) +
                                     " (a point light: six faces of N x N, N up to " +
                                     std::to_string(kMaxResolution / kCubeFaces) + ")")
                     ->capture_default_str();
  auto* capOpt = addCaptureOption(*cmd, o->capture);
  addCaptureDeviceOptions(*cmd, o->device);
  depthOpt->excludes(resOpt)->excludes(cmd->get_option("--device"));
  cmd->get_option("--scene")->excludes(depthOpt);
  cmd->get_option("--light")->excludes(depthOpt);
  cmd->get_option("--fit")->excludes(depthOpt);  // the depth file's side file holds its light frustum
  addVolumeOptions(*cmd, o->volume)->excludes(depthOpt);  // refinement casts rays into the scene
  cmd->add_flag("--no-flatten", o->noFlatten, "Keep two cap triangles per kept quad instead of the flattened cap");
  cmd->add_option("--out", o->out, "Output mesh: .ply (binary), .obj, .off, .stl, .gltf (one JSON file) or .glb (binary glTF)")->required();
  cmd->add_flag("--world-coords", o->worldCoords,
                "Write world coordinates in double precision (PLY double properties, OBJ/OFF 17 digits; not STL; glTF "
                "keeps float positions and the local origin as its node's translation). "
                "Without it a scene far from the origin is written relative to its local origin, which the output "
                "and the PLY/OBJ/STL header name (README 'Far from the origin')");
  cmd->callback([&run, o, capOpt] {
    checkCaptureDeviceOptions(o->device, !o->depth.empty());
    // --capture auto is the default, so it goes with --depth (a probe found it refused); a mode is not.
    if (!o->depth.empty() && capOpt->count() > 0 && o->capture != "auto")
      throw CLI::ValidationError("--capture", "the depth file records its own capture mode (its side file's "
                                              "\"capture\"): leave out --capture with --depth");
    if (o->noFlatten && o->volume.cap == "quad")
      throw CLI::ValidationError("--no-flatten", "keeps the exact cap unflattened; --cap quad has one far rectangle, "
                                                 "nothing to flatten: leave out --no-flatten");
    run = [o] {
      checkOutputPath("--out", o->out);
      std::string ext = std::filesystem::path(o->out).extension().string();
      for (auto& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));  // .PLY works as .ply
      if (!isMeshOutputFormat(o->out))
        throw InputError("command line", "--out", o->out,
                         std::string("unsupported mesh format (use ") + kMeshOutputFormats + ")");
      if (o->worldCoords && ext == ".stl")
        throw InputError("command line", "--world-coords", o->out,
                         "STL stores single-precision coordinates only: write world coordinates as .ply, .obj or .off");
      VolumeBuildOptions options = toVolumeBuildOptions(o->volume);
      options.flattenCap = !o->noFlatten;
      if (options.refineSubdivisions > 1 && !options.flattenCap)
        throw OptionConflict("command line", "--no-flatten", "",
                         "not with --refine-grid: the sub-grid needs the flattened cap");

      nlohmann::json j;
      DepthMap map;
      std::optional<CubeDepthMap> cube;  // a point light's six faces
      Scene scene;
      double msCapture = 0.0;
      if (!o->depth.empty()) {
        checkNotAnInput("--out", o->out, o->out, {o->depth, depthSidecarPath(o->depth)});
        map = readDepthMap(o->depth);
        if (map.width < kMinVolumeMapSide || map.height < kMinVolumeMapSide)
          throw InputError(o->depth, "size", std::to_string(map.width) + "x" + std::to_string(map.height),
                           "a volume needs a map of at least " + std::to_string(kMinVolumeMapSide) + " x " +
                               std::to_string(kMinVolumeMapSide) +
                               " texels: the outermost ring lies on the far plane, so a smaller map's volume is empty");
        j["depth"] = o->depth;
      } else {
        checkResolution("--resolution", o->resolution);
        scene = loadSceneOrDefault(o->scene.scene, nullptr, sceneUse(o->scene));
        const ResolvedCapture capture = resolveCapture(o->capture, scene, volumeUse(options.refineSteps));
        const CaptureMode mode = capture.mode;
        if (!capture.autoReason.empty()) j["captureAuto"] = capture.autoReason;
        checkNotAnInput("--out", o->out, o->out, scene.files);
        chooseLight(scene, o->light);
        j["lightFit"] = applyLightFit(scene, o->scene, o->resolution);
        j["warnings"] = warnAboutCapture(scene, o->resolution, o->resolution, mode, &options);
        const auto t0 = std::chrono::steady_clock::now();
        if (scene.light.type == LightType::Point) {
          cube = captureCubeOnDevice(o->device, scene, o->resolution, mode);
          map = cube->faces[0];  // size, capture and origin, which the six faces share
        } else {
          map = captureOnDevice(o->device, scene, o->resolution, o->resolution, mode, kVolumeGuardTexels);
        }
        msCapture = msSince(t0);
        j["device"] = o->device.device;
        j["scene"] = describeScene(scene);
      }
      // With --refine, the rays go to the same scene (built once, before the timed build).
      std::unique_ptr<EmbreeDepthOracle> oracle;
      if (options.refineSteps > 0) {
        oracle = std::make_unique<EmbreeDepthOracle>(scene);
        options.depthOracle = oracle->oracle();
        options.surfaceEnds = oracle->surfaceEnds();
        options.nearerSurfaces = oracle->nearerSurfaces();
        options.casterFaces = oracle->casterFaces();
        options.withoutCasters = oracle->withoutCasters();
      }
      const VolumeBuildResult r = cube ? buildCubeVolume(*cube, options) : buildVolume(map, options);
      const auto t1 = std::chrono::steady_clock::now();
      const WrittenVolume written = writeVolumeMesh(r.mesh, o->out, o->worldCoords);
      const double msWrite = msSince(t1);
      const VolumeBuildStats& s = r.stats;
      if (options.cap == FarCap::Quad && !r.mesh.triangles.empty()) {  // a fourteenth probe: said nowhere at build
        const std::string note = "the quad cap (--cap quad, the thesis's far rectangle) lies over the sheet's far "
                                 "triangles: the volume is closed but has coincident faces, which `check` reports as "
                                 "not outward; it is kept for comparison (README \"Volume mesh\")";
        std::fprintf(stderr, "shadowvol: note: %s: %s\n", o->out.c_str(), note.c_str());
        j["warnings"].push_back(o->out + ": " + note);
      }
      if (r.mesh.triangles.empty()) {  // a second probe's finding: a depth file's empty volume went unsaid
        const std::string note = "the volume is empty: the depth map holds no surface in front of its far plane, "
                                 "so nothing is in shadow (the file holds no triangles)";
        std::fprintf(stderr, "shadowvol: warning: %s: %s\n", o->out.c_str(), note.c_str());
        j["warnings"].push_back(o->out + ": " + note);
      }
      // A second probe's finding: STL keeps no shared corners, and glTF's are welded by position on
      // reading (ours and most readers'), so the pinch copies meet again as non-manifold vertices.
      // Counted as written (a twenty-second probe: --no-flatten's copies were not in splitVertices).
      if (written.coincidentVertices > 0 && (ext == ".stl" || ext == ".gltf" || ext == ".glb")) {
        const std::string note = "the volume has " + std::to_string(written.coincidentVertices) +
                                 " vertices at the position of another (split copies at pinches, so that it is a "
                                 "2-manifold); " + ext +
                                 " readers that weld corners by position, `shadowvol check` among them, join them "
                                 "into non-manifold vertices: write .ply, .obj or .off to keep them apart";
        std::fprintf(stderr, "shadowvol: warning: %s: %s\n", o->out.c_str(), note.c_str());
        j["warnings"].push_back(o->out + ": " + note);
      }
      if (written.collapsedTriangles > 0) {  // float rounding beyond what the origin's choice avoids
        const std::string note = std::to_string(written.collapsedTriangles) +
                                 " triangles have two corners at one position as written (zero area in the file)" +
                                 (o->worldCoords || ext == ".stl" || ext == ".gltf" || ext == ".glb"
                                      ? std::string()  // float only: a finer or nearer scene, or .ply/.obj/.off
                                      : ": --world-coords writes double precision");
        std::fprintf(stderr, "shadowvol: warning: %s: %s\n", o->out.c_str(), note.c_str());
        j["warnings"].push_back(o->out + ": " + note);
      }
      // A spot or directional map's guard band (light.h): captured with one, or as its side file says.
      const int guard = cube ? 0 : map.guard;
      j.update({{"resolution", {map.width - 2 * guard, map.height - 2 * guard}},
                {"guard", guard},
                {"mapSize", {map.width, map.height}},
                {"cubeFaces", cube ? 6 : 1},
                {"capture", toString(map.capture)},
                {"triangulation", o->volume.triangulation},
                {"blur", o->volume.blur},
                {"blurOffset", o->volume.blurOffset},
                {"bias", s.biasUsed},
                {"cap", o->volume.cap},
                {"flattenCap", options.flattenCap},
                {"refine", options.refineSteps},
                {"refineGrid", options.refineSubdivisions},
                {"refineGridEverywhere", options.refineGridEverywhere},
                {"refineHidden", options.refineHidden},
                {"facePrisms", options.facePrisms},
                {"partStarts", r.mesh.partStarts},
                {"origin", {written.origin.x, written.origin.y, written.origin.z}},
                {"worldCoordinates", o->worldCoords},
                {"vertices", r.mesh.vertexCount()},
                {"triangles", r.mesh.triangleCount()},
                {"out", o->out}});
      j.update(describeVolumeStats(s));
      j["ms"].update({{"capture", msCapture}, {"build", s.msTotal}, {"write", msWrite}});
      j["shadowvolVersion"] = SHADOWVOL_VERSION;
      if (o->scene.json) {
        std::cout << jsonText(j) << '\n';
      } else {
        std::string band;
        if (guard > 0)
          band = " (a " + std::to_string(map.width) + "x" + std::to_string(map.height) + " map with a guard band of " +
                 std::to_string(guard) + " texels a side)";
        std::printf("volume of %s, %s%dx%d %s capture%s, %s triangulation%s, %s cap\n",
                    o->depth.empty() ? j["scene"]["source"].get<std::string>().c_str() : o->depth.c_str(),
                    cube ? "point light, 6 cube faces of " : "", map.width - 2 * guard, map.height - 2 * guard,
                    toString(map.capture), band.c_str(), o->volume.triangulation.c_str(), o->volume.blur ? ", blur" : "",
                    o->volume.cap.c_str());
        std::printf(cube ? "  %zu vertices, %zu triangles; %zu of %zu cells dropped (far cube), %zu flipped (%.1f%%)\n"
                         : "  %zu vertices, %zu triangles; %zu of %zu quads dropped (far plane), %zu flipped (%.1f%%)\n",
                    r.mesh.vertexCount(), r.mesh.triangleCount(), s.droppedQuads, s.quads, s.flippedQuads,
                    s.quads ? 100.0 * double(s.flippedQuads) / double(s.quads) : 0.0);
        std::printf("  cap triangles %zu -> %zu after flattening; %zu split vertices; bias %.3g\n", s.capTrianglesBefore,
                    s.capTrianglesAfter, s.splitVertices, s.biasUsed);
        char hiddenText[128];
        if (options.refineHidden)
          std::snprintf(hiddenText, sizeof hiddenText, "%zu quads for a hidden surface (%zu for a rim; search %.1f ms)",
                        s.hiddenQuads, s.rimQuads, s.msHidden);
        else
          std::snprintf(hiddenText, sizeof hiddenText, "no search for hidden surfaces (--no-hidden-search)");
        if (options.refineSubdivisions > 1)
          std::printf("  sub-grid %dx%d on %zu of the %zu refined quads%s: %zu samples, %zu bisected boundary "
                      "sub-edges, %zu sub-cells decided by a centre ray, %zu triangles split; %s\n",
                      options.refineSubdivisions, options.refineSubdivisions, s.subgridQuads, s.refinedCells,
                      options.refineGridEverywhere ? " (everywhere)" : "", s.subgridSamples, s.subgridBoundaryEdges,
                      s.ambiguousCells, s.subgridSplitTriangles,
                      hiddenText);
        if (options.refineSubdivisions > 1 && s.thinQuads > 0)
          std::printf("  sub-grid for thin parts: %zu quads where a part is thinner than the sheet bends\n", s.thinQuads);
        if (options.refineSubdivisions > 1 && s.biasUsed > 0.0)
          std::printf("  sub-grid bias: %zu quads for a crease, %zu sub-cell centre samples, %zu wall tops moved to "
                      "the rim\n",
                      s.creaseQuads, s.subgridBiasSamples, s.rimCrossings);
        if (options.refineSubdivisions > 1)
          std::printf("  refinement (%d steps, %d per boundary sub-edge): %zu boundary edges (%zu to the far plane) "
                      "choose %zu refined quads, %zu rays\n",
                      options.refineSteps, refineSubEdgeSteps(options.refineSteps, options.refineSubdivisions),
                      s.boundaryEdges, s.farBoundaryEdges, s.refinedCells, s.raysCast);
        else if (options.refineSteps > 0)
          std::printf("  refinement (%d steps): %zu boundary edges (%zu to the far %s), %zu refined %s (%zu "
                      "decided by a centre ray, %zu chord points), %zu rays\n",
                      options.refineSteps, s.boundaryEdges, s.farBoundaryEdges, cube ? "cube" : "plane",
                      s.refinedCells, cube ? "cells" : "quads", s.ambiguousCells, s.chordPoints, s.raysCast);
        if (options.facePrisms)
          std::printf("  face prisms: %zu texels' columns handed over by the sheet, %zu faces in them, %zu border "
                      "walls, %zu triangles (%.1f ms)%s\n",
                      s.prismColumnTexels, s.prismFaces, s.prismWalls, s.prismTriangles, s.msPrisms,
                      r.mesh.partStarts.empty()
                          ? ""
                          : ("; a second closed part from triangle " + std::to_string(r.mesh.partStarts[0]) +
                             " on (shadowvol check --part-starts " + std::to_string(r.mesh.partStarts[0]) + ")")
                                .c_str());
        if (options.refineSteps > 0)
          std::printf("  %zu crossings snapped to where their triangle ends%s\n", s.snappedCrossings,
                      !options.refineSnap ? " (--no-snap)" : cube ? " (not for a point light's cube)" : "");
        std::printf("  time: capture %.1f ms, blur %.1f ms, sheet %.1f ms, refine %.1f ms (rays %.1f ms), cap %.1f ms, "
                    "build %.1f ms, write %.1f ms\n",
                    msCapture, s.msBlur, s.msSheet, s.msRefine, s.msRays, s.msCap, s.msTotal, msWrite);
        if (written.origin != glm::dvec3(0.0)) {
          const bool gltf = ext == ".gltf" || ext == ".glb";  // float positions, the origin as the node's translation
          std::printf("  coordinates %s origin (%.17g, %.17g, %.17g)\n",
                      gltf            ? "relative to the glTF node, whose translation is the local"
                      : o->worldCoords ? "in world units (double); local"
                                       : "relative to the local",
                      written.origin.x, written.origin.y, written.origin.z);
        }
        std::printf("wrote %s\n", o->out.c_str());
      }
      return kOk;
    };
  });
}

}  // namespace shadowvol::cli

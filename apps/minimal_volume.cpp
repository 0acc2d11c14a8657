// minimal_volume: the whole library in one page, top to bottom.
//
//   scene  ->  light depth map (Embree ray casting)  ->  shadow-volume mesh  ->  PLY file
//
// Usage: minimal_volume [out.ply]      (default: shadow_volume.ply in the current folder)
// Open the result in MeshLab or Blender: a closed, outward-oriented mesh that bounds exactly the
// region the light cannot see.

#include <cstdio>
#include <exception>

#include "shadowvol/embree/depth_capture.h"  // captureDepthEmbree: CPU depth capture
#include "shadowvol/mesh_io.h"               // writeVolumeMesh: PLY/OBJ/OFF/STL writers
#include "shadowvol/scene.h"                 // Scene, defaultScene, loadScene
#include "shadowvol/volume_builder.h"        // buildVolume: depth map -> VolumeMesh

int main(int argc, char** argv) {
  const char* out = argc > 1 ? argv[1] : "shadow_volume.ply";
  try {
    // 1. A scene: world-space triangles, one light, one camera. The built-in default is a sphere
    //    floating above a ground plane under a spot light. loadScene("file.json") reads your own.
    const shadowvol::Scene scene = shadowvol::defaultScene();

    // 2. The light's depth map: one ray per texel from the light. "Back" capture records the
    //    first surface that faces away from the light (the thesis's default): the sphere's
    //    underside. The ground faces the light, so it records nothing there (no self-shadowing).
    //    The guard band takes the map 2 texels past the light's window on every side, so the
    //    volume's closing ring (on the far plane) lies outside what the light lights.
    const int resolution = 256;
    const shadowvol::DepthMap depth = shadowvol::captureDepthEmbree(
        scene, resolution, resolution, shadowvol::CaptureMode::Back, shadowvol::kVolumeGuardTexels);

    // 3. The shadow volume: every texel becomes a vertex, neighbouring texels form quads (the
    //    "sheet"). Perfect triangulation picks each quad's diagonal so shadow edges do not
    //    staircase; the exact far cap drops the sheet where the light saw nothing and closes
    //    what is left at the far plane.
    shadowvol::VolumeBuildOptions options;
    options.triangulation = shadowvol::Triangulation::Perfect;
    options.cap = shadowvol::FarCap::Exact;
    const shadowvol::VolumeBuildResult volume = shadowvol::buildVolume(depth, options);

    // 4. Export. The mesh is also a plain value (volume.mesh.positions / .triangles), so a caller
    //    can use it without touching a file.
    shadowvol::writeVolumeMesh(volume.mesh, out);
    std::printf("%zu vertices, %zu triangles -> %s\n", volume.mesh.vertexCount(), volume.mesh.triangleCount(), out);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "minimal_volume: %s\n", e.what());
    return 1;
  }
}

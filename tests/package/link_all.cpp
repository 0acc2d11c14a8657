// Links every target of the installed package and uses one function of each: the CGAL checks on a
// volume built from an Embree capture, and the GL names (no context is made: CI has no display
// guarantee here; the GL tests cover rendering).
#include <cstdio>

#include "shadowvol/cgal/mesh_check.h"
#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/gl/renderer.h"
#include "shadowvol/validate/frame_validation.h"
#include "shadowvol/version.h"
#include "shadowvol/volume_builder.h"

int main() {
  const shadowvol::Scene scene = shadowvol::defaultScene();
  const auto depth = shadowvol::captureDepthEmbree(scene, 64, 64, shadowvol::CaptureMode::Back);
  const auto volume = shadowvol::buildVolume(depth, {});
  const shadowvol::MeshCheckReport report = shadowvol::checkMesh(volume.mesh);
  std::printf("shadowvol %s: %s volume, %s\n", SHADOWVOL_VERSION, report.valid() ? "valid" : "INVALID",
              shadowvol::gl::toString(shadowvol::gl::ShadowMethod::Hybrid));
  return report.valid() ? 0 : 1;
}

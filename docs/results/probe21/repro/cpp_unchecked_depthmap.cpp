#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/volume_builder.h"
#include "shadowvol/mesh_io.h"
#include "shadowvol/error.h"
using namespace shadowvol;
static void report(const char* name, const DepthMap& m, VolumeBuildOptions o = {}) {
  try {
    VolumeBuildResult r = buildVolume(m, o);
    size_t nonfinite = 0;
    for (auto& p : r.mesh.positions) for (int c = 0; c < 3; ++c) if (!std::isfinite(p[c])) ++nonfinite;
    std::printf("%-28s OK %zu verts %zu tris, nonfinite %zu\n", name, r.mesh.vertexCount(), r.mesh.triangleCount(), nonfinite);
  } catch (const InputError& e) { std::printf("%-28s InputError: %s\n", name, e.what()); }
  catch (const std::exception& e) { std::printf("%-28s %s\n", name, e.what()); }
  std::fflush(stdout);
}
int main(int argc, char** argv) {
  Scene scene = defaultScene();
  DepthMap base = captureDepthEmbree(scene, 64, 64, CaptureMode::Back);
  const char* which = argc > 1 ? argv[1] : "all";
  auto want = [&](const char* n) { return !std::strcmp(which, "all") || !std::strcmp(which, n); };
  if (want("nanview")) { DepthMap m = base; m.lightView[0][0] = NAN; report("nan lightView", m); }
  if (want("singularproj")) { DepthMap m = base; m.lightProjection = glm::dmat4(0.0); report("zero lightProjection", m); }
  if (want("scaledview")) { DepthMap m = base; m.lightView = m.lightView * 1e-300; report("lightView*1e-300", m); }
  if (want("nanorigin")) { DepthMap m = base; m.origin.x = NAN; report("nan origin", m); }
  if (want("inforigin")) { DepthMap m = base; m.origin.x = 1e308; report("1e308 origin", m); }
  if (want("hugefar")) { DepthMap m = base; m.farPlane = 1e300; report("far 1e300 (matrices unchanged)", m); }
  if (want("nanfar")) { DepthMap m = base; m.farPlane = NAN; report("nan far", m); }
  if (want("pointtype")) { DepthMap m = base; m.lightType = LightType::Point; report("lightType point", m); }
  if (want("dirtype")) { DepthMap m = base; m.lightType = LightType::Directional; report("lightType directional w/ persp", m); }
  if (want("farltnear")) { DepthMap m = base; m.farPlane = m.nearPlane * 0.5; report("far < near", m); }
  if (want("sizemismatch")) { DepthMap m = base; m.depth.resize(10); report("depth.size mismatch", m); }
  if (want("w1")) { DepthMap m = base; m.width = 1; m.height = 1; m.depth = {5.f}; report("1x1", m); }
  if (want("nandepth")) { DepthMap m = base; m.depth[100] = NAN; report("nan depth", m); }
  if (want("builder")) {
    VolumeBuilder b; VolumeBuildResult r1, r2;
    DepthMap big = captureDepthEmbree(scene, 128, 100, CaptureMode::Back);
    b.build(base, {}, r1); b.build(big, {}, r1); b.build(base, {}, r1);
    VolumeBuildResult ref = buildVolume(base);
    std::printf("builder reuse same: %d (verts %zu vs %zu)\n", int(r1.mesh.positions == ref.mesh.positions && r1.mesh.triangles == ref.mesh.triangles), r1.mesh.vertexCount(), ref.mesh.vertexCount());
    VolumeBuildOptions bl; bl.blur = true;
    b.build(base, bl, r2); VolumeBuildResult refb = buildVolume(base, bl);
    std::printf("builder reuse blur same: %d\n", int(r2.mesh.positions == refb.mesh.positions));
    try { VolumeBuildOptions bad; bad.bias = -1; b.build(base, bad, r2); } catch (const InputError& e) { std::printf("bad: %s\n", e.what()); }
    b.build(base, {}, r2);
    std::printf("builder after error same: %d\n", int(r2.mesh.positions == ref.mesh.positions));
  }
  return 0;
}

// Volume options for a refined build whose rays go to an Embree scene (the tests' shared set-up).
#pragma once

#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/embree/embree_depth_oracle.h"
#include "shadowvol/scene.h"
#include "shadowvol/volume_builder.h"

namespace shadowvol::test {

/// K = `steps` bisection rays per boundary edge from `oracle`, with its snap (surfaceEnds); no
/// sub-grid and no search for hidden surfaces (set refineSubdivisions and nearerSurfaces for them).
inline VolumeBuildOptions refinedWithRays(const EmbreeDepthOracle& oracle, int steps) {
  VolumeBuildOptions o;
  o.refineSteps = steps;
  o.depthOracle = oracle.oracle();
  o.surfaceEnds = oracle.surfaceEnds();
  return o;
}

/// The volume of `scene`'s N x N map captured by `mode`, refined with K = 6 on the 4 x 4 sub-grid
/// with its search for hidden surfaces (what `--refine 6 --refine-grid 4` builds).
inline VolumeBuildResult buildOnSubgrid(const Scene& scene, int n, CaptureMode mode) {
  const EmbreeDepthOracle oracle(scene);
  const DepthMap map = captureDepthEmbree(scene, n, n, mode);
  VolumeBuildOptions o = refinedWithRays(oracle, 6);
  o.refineSubdivisions = 4;
  o.nearerSurfaces = oracle.nearerSurfaces();
  return buildVolume(map, o);
}

}  // namespace shadowvol::test

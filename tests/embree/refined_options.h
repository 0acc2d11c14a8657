// Volume options for a refined build whose rays go to an Embree scene (the tests' shared set-up).
#pragma once

#include "shadowvol/embree/embree_depth_oracle.h"
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

}  // namespace shadowvol::test

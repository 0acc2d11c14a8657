#include "shadowvol/frame.h"

#include <algorithm>

namespace shadowvol {

const char* toString(ShadowMethod m) { return nameIn(kShadowMethodNames, m); }

bool parseShadowMethod(const std::string& text, ShadowMethod& m) { return parseIn(kShadowMethodNames, text, m); }

const char* toString(VolumeSource v) { return nameIn(kVolumeSourceNames, v); }

bool parseVolumeSource(const std::string& text, VolumeSource& v) { return parseIn(kVolumeSourceNames, text, v); }

const char* toString(GpuVolumeDraw d) { return nameIn(kGpuVolumeDrawNames, d); }

bool parseGpuVolumeDraw(const std::string& text, GpuVolumeDraw& d) {
  GpuVolumeDraw parsed;
  if (!parseIn(kGpuVolumeDrawNames, text, parsed) || parsed == GpuVolumeDraw::Refined) return false;
  d = parsed;
  return true;
}

const char* toString(VolumeCount c) { return nameIn(kVolumeCountNames, c); }

bool parseVolumeCount(const std::string& text, VolumeCount& c) { return parseIn(kVolumeCountOptionNames, text, c); }

const char* toString(RefineCrossings c) { return nameIn(kRefineCrossingsNames, c); }

bool parseRefineCrossings(const std::string& text, RefineCrossings& c) {
  return parseIn(kRefineCrossingsNames, text, c);
}

const char* toString(ExplicitDepth d) { return nameIn(kExplicitDepthNames, d); }

bool parseExplicitDepth(const std::string& text, ExplicitDepth& d) { return parseIn(kExplicitDepthNames, text, d); }

CaptureUse captureUse(const RenderOptions& o) {
  if (o.method == ShadowMethod::Hybrid) {
    if (o.refineCrossings == RefineCrossings::GpuWalk) return CaptureUse::OneLayer;
    return volumeUse(o.volumeOptions.refineSteps);
  }
  return o.method == ShadowMethod::Dpsm ? CaptureUse::OneLayer : CaptureUse::ShadowMap;
}

ExplicitDepth chooseExplicitDepth(const RenderOptions& o, std::size_t sceneTriangles, bool softwareRasterizer,
                                  int faces) {
  if (o.explicitDepth != ExplicitDepth::Auto) return o.explicitDepth;
  const bool canCast = o.method == ShadowMethod::Hybrid && o.volume == VolumeSource::Explicit &&
                       o.volumeOptions.depthOracle && o.refineCrossings != RefineCrossings::GpuWalk;
  const double texels = double(o.depthWidth) * double(o.depthHeight) * double(std::max(faces, 1));
  const bool raysCheaper = double(sceneTriangles) >= kRayDepthTrianglesPerTexel * texels;
  return canCast && softwareRasterizer && raysCheaper ? ExplicitDepth::Rays : ExplicitDepth::LightPass;
}

bool needsDepthOracle(const RenderOptions& o) {
  if (o.method != ShadowMethod::Hybrid || o.volume != VolumeSource::Explicit) return false;
  return (o.volumeOptions.refineSteps > 0 && o.refineCrossings == RefineCrossings::Rays) ||
         o.explicitDepth == ExplicitDepth::Rays;
}

std::vector<PassTime> passTotals(const std::vector<PassTime>& passes) {
  std::vector<PassTime> out;
  for (const PassTime& p : passes) {
    auto it = std::find_if(out.begin(), out.end(), [&](const PassTime& o) { return o.name == p.name; });
    if (it == out.end()) out.push_back(p);
    else it->ms += p.ms;
  }
  return out;
}

const char* toString(TimingMethod t) { return nameIn(kTimingMethodNames, t); }

}  // namespace shadowvol

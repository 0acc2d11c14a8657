#include "shadowvol/frame.h"

#include <algorithm>

namespace shadowvol {

const char* toString(ShadowMethod m) {
  switch (m) {
    case ShadowMethod::Hybrid:
      return "hybrid";
    case ShadowMethod::ShadowMap:
      return "shadowmap";
    case ShadowMethod::Pcf3:
      return "pcf3";
    case ShadowMethod::Pcf5:
      return "pcf5";
    case ShadowMethod::None:
      return "none";
    case ShadowMethod::Silhouette:
      return "silhouette";
    case ShadowMethod::Dpsm:
      return "dpsm";
  }
  return "?";
}

bool parseShadowMethod(const std::string& text, ShadowMethod& m) {
  if (text == "hybrid")
    m = ShadowMethod::Hybrid;
  else if (text == "shadowmap")
    m = ShadowMethod::ShadowMap;
  else if (text == "pcf3")
    m = ShadowMethod::Pcf3;
  else if (text == "pcf5")
    m = ShadowMethod::Pcf5;
  else if (text == "none")
    m = ShadowMethod::None;
  else if (text == "silhouette")
    m = ShadowMethod::Silhouette;
  else if (text == "dpsm")
    m = ShadowMethod::Dpsm;
  else
    return false;
  return true;
}

const char* toString(VolumeSource v) {
  return v == VolumeSource::Gpu ? "gpu" : "explicit";
}

bool parseVolumeSource(const std::string& text, VolumeSource& v) {
  if (text == "gpu")
    v = VolumeSource::Gpu;
  else if (text == "explicit")
    v = VolumeSource::Explicit;
  else
    return false;
  return true;
}

const char* toString(GpuVolumeDraw d) {
  switch (d) {
    case GpuVolumeDraw::Auto: return "auto";
    case GpuVolumeDraw::Indexed: return "indexed";
    case GpuVolumeDraw::ComputeMesh: return "compute-mesh";
    case GpuVolumeDraw::KeptQuads: return "kept-quads";
    case GpuVolumeDraw::Refined: return "refined";
    default: return "all-quads";
  }
}

const char* toString(VolumeCount c) {
  return c == VolumeCount::Auto ? "auto" : c == VolumeCount::ZPass ? "z-pass" : "z-fail";
}

bool parseVolumeCount(const std::string& text, VolumeCount& c) {
  if (text == "auto") c = VolumeCount::Auto;
  else if (text == "zfail") c = VolumeCount::ZFail;
  else if (text == "zpass") c = VolumeCount::ZPass;
  else return false;
  return true;
}

const char* toString(RefineCrossings c) {
  return c == RefineCrossings::GpuWalk ? "gpu-walk" : (c == RefineCrossings::GpuRays ? "gpu-rays" : "rays");
}

bool parseRefineCrossings(const std::string& text, RefineCrossings& c) {
  if (text == "rays") c = RefineCrossings::Rays;
  else if (text == "gpu-walk") c = RefineCrossings::GpuWalk;
  else if (text == "gpu-rays") c = RefineCrossings::GpuRays;
  else return false;
  return true;
}

const char* toString(ExplicitDepth d) {
  switch (d) {
    case ExplicitDepth::LightPass: return "gpu";
    case ExplicitDepth::Rays: return "rays";
    case ExplicitDepth::Auto: return "auto";
  }
  return "?";
}

bool parseExplicitDepth(const std::string& text, ExplicitDepth& d) {
  if (text == "gpu") d = ExplicitDepth::LightPass;
  else if (text == "rays") d = ExplicitDepth::Rays;
  else if (text == "auto") d = ExplicitDepth::Auto;
  else return false;
  return true;
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

const char* toString(TimingMethod t) {
  return t == TimingMethod::GpuTimer ? "gpu-timer-query" : "wall-clock-glfinish";
}

}  // namespace shadowvol

#include "shadowvol/validate/validation_report.h"

#include "shadowvol/cgal/mesh_check_json.h"
#include "shadowvol/error.h"

namespace shadowvol {
namespace {

nlohmann::json toJson(const ShadowError& e) {
  return {{"pixels", e.pixels},
          {"missedShadow", e.missed},
          {"falseShadow", e.falseShadow},
          {"missedFraction", e.missedFraction()},
          {"falseFraction", e.falseFraction()},
          {"errorFraction", e.errorFraction()}};
}

nlohmann::json toJson(const Agreement& a) {
  nlohmann::json misses = nlohmann::json::array();
  for (const Agreement::Miss& m : a.firstMisses)
    misses.push_back({{"x", m.x}, {"row", m.row}, {"stencil", m.stencil}, {"zfail", m.zfail},
                      {"zfailMin", m.zfailMin}, {"zfailMax", m.zfailMax}});
  return {{"pixels", a.pixels},
          {"agree", a.agree},
          {"ties", a.ties},
          {"imagePlaneTies", a.imagePlaneTies},
          {"disagree", a.pixels - a.agree},
          {"fraction", a.fraction()},
          {"firstDisagreeing", misses}};
}

}  // namespace

nlohmann::json describeValidation(const FrameValidation& v, const ValidationOptions& options, bool silhouetteMethod) {
  nlohmann::json j;
  j["pixels"] = {{"total", std::size_t(v.width) * std::size_t(v.height)},
                 {"visible", v.visible},
                 {"background", v.background},
                 {"facingAway", v.facingAway},
                 {"outsideLight", v.outsideLight},
                 {"exactLit", v.exactLit},
                 {"exactShadowed", v.exactShadowed}};
  if (v.meshCheck) {
    j["meshChecks"] = meshCheckJson(*v.meshCheck, v.meshChecksNotApplicable);
    if (v.gpuMeshCheck) j["gpuVolumeMeshChecks"] = meshCheckJson(*v.gpuMeshCheck);
    j["stencilVsCount"] = toJson(v.stencilVsCount);
    j["stencilVsCount"]["over"] = v.stencilOverLitFrustumOnly ? "visible pixels inside the light's frustum (z-pass)"
                                                              : "visible pixels";
    j["eyeInsideVolume"] = v.eyeInsideVolume;
    j["recountedPixels"] = v.recountedPixels;
    j["zfailVsZpass"] = v.zfailVsZpass ? toJson(*v.zfailVsZpass) : nlohmann::json("not applicable: eye inside");
    j["againstExact"] = {{"stencil", v.stencilError ? toJson(*v.stencilError) : nlohmann::json()},
                         {"count", v.countError ? toJson(*v.countError) : nlohmann::json()},
                         {"method", toJson(v.methodError)}};
  } else {
    const char* na = silhouetteMethod
                         ? "not applicable: the silhouette volume is scored against exact only (it crosses itself "
                           "by construction, so the depth-map volume's mesh checks do not apply)"
                         : "not applicable: no shadow volume";
    j["meshChecks"] = na;
    j["stencilVsCount"] = na;
    j["zfailVsZpass"] = na;
    j["againstExact"] = {{"stencil", na}, {"count", na}, {"method", toJson(v.methodError)}};
  }
  if (v.errorCauses)
    j["errorCauses"] = {{"resolution", v.errorCauses->resolution},
                        {"capture", v.errorCauses->capture},
                        {"border", v.errorCauses->border},
                        {"borderAllowed", kMaxBorderPixels},
                        {"offset", v.errorCauses->offset},
                        {"rule", "resolution: the method's misclassified pixels that the same capture at unlimited "
                                 "resolution (captured depth on the pixel's own light ray + offset < the point's "
                                 "light-view depth) gets right; capture: those it gets wrong too; border: of those "
                                 "it gets right, a shadow volume's missed pixels less than one texel inside the light "
                                 "window's outermost texel centres, where a map without a guard band puts its ring "
                                 "on the far plane (the renderer's maps have one: 0 while it works)"}};
  else
    j["errorCauses"] = "not computed: only for the depth-map methods (hybrid, shadowmap, pcf3, pcf5) of a spot or "
                       "directional light";
  {
    nlohmann::json lost = {{"occluders", v.lostShadows.occluders},
                           {"judged", v.lostShadows.judged},
                           {"minPixels", kMinOccluderPixels},
                           {"missedSelf", v.lostShadows.missedSelf},
                           {"missedOnOthers", v.lostShadows.missedOnOthers},
                           {"rule", "each exactly shadowed pixel belongs to the object its exact shadow ray meets "
                                    "first; an object shadowing at least minPixels pixels may have at most the "
                                    "allowed missed share of them missed. missedSelf: missed pixels on the object "
                                    "that occludes them (self-shadows); missedOnOthers: on another object"}};
    if (const auto& w = v.lostShadows.worst)
      lost["worst"] = {{"object", w->object},
                       {"name", w->name},
                       {"pixels", w->pixels},
                       {"missed", w->missed},
                       {"missedSelf", w->missedSelf},
                       {"firstPixel", {w->first % std::size_t(v.width), w->first / std::size_t(v.width)}}};
    j["shadowsByOccluder"] = lost;
  }
  if (v.leaks)
    j["leaks"] = {{"deep", v.leaks->deep},
                  {"allowed", kMaxLeakPixels},
                  {"rule", "missed pixels with no outline pixel (not exactly shadowed, on the image's border or "
                               "beside a jump in the view) within " + numberText(kLeakTexels) +
                               " of the light's texels along the surface plus the method's depth offset's reach, "
                               "plus " + numberText(kLeakPixels) + " image pixels: a hole in the shadow "
                               "(validate/shadow_leaks.h)"}};
  else
    j["leaks"] = "not judged: a method whose texels are not sized here (dual-paraboloid maps, none)";
  j["requiredAgreement"] = kRequiredAgreement;
  j["verdict"] = {{"consistent", v.consistent},
                  {"accurate", v.accurate},
                  {"maxError", options.maxError},
                  {"maxMissedShare", options.maxMissedShare},
                  {"failures", v.failures}};
  j["passed"] = v.passed;
  return j;
}

}  // namespace shadowvol

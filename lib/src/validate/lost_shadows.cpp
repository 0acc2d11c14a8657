#include "shadowvol/validate/lost_shadows.h"

#include <map>

#include "shadowvol/check.h"

namespace shadowvol {

LostShadows findLostShadows(const std::vector<PixelClass>& exact, const std::vector<std::uint8_t>& methodShadowed,
                            const std::vector<std::uint32_t>& occluders, const std::vector<std::uint32_t>& receivers) {
  SV_CHECK_EQ(exact.size(), methodShadowed.size());
  SV_CHECK_EQ(exact.size(), occluders.size());
  SV_CHECK_EQ(exact.size(), receivers.size());
  std::map<std::uint32_t, OccluderShadow> by;  // ordered by object: deterministic ties
  for (std::size_t k = 0; k < exact.size(); ++k) {
    if (exact[k] != PixelClass::Shadowed || occluders[k] == kNoOccluder) continue;
    auto [it, fresh] = by.try_emplace(occluders[k]);
    OccluderShadow& s = it->second;
    if (fresh) s.object = occluders[k], s.first = k;
    ++s.pixels;
    if (methodShadowed[k] == 0) {
      ++s.missed;
      s.missedSelf += receivers[k] == occluders[k];
    }
  }
  LostShadows out;
  out.occluders = by.size();
  for (const auto& [object, s] : by) {
    out.missedSelf += s.missedSelf;
    out.missedOnOthers += s.missed - s.missedSelf;
    if (s.pixels < kMinOccluderPixels) continue;
    ++out.judged;
    if (!out.worst || s.missed * out.worst->pixels > out.worst->missed * s.pixels) out.worst = s;
  }
  return out;
}

}  // namespace shadowvol

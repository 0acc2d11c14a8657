// The measured part of a validation report as JSON: pixel classes, mesh checks, stencil against
// crossing counts, z-fail against z-pass, every shadow test against exact shadows, and the
// verdict. `shadowvol validate` writes it into report.json (beside the scene, GL device and
// options) and the Python module returns it as a dict, so both carry the same fields.
#pragma once

#include <nlohmann/json.hpp>

#include "shadowvol/validate/frame_validation.h"

namespace shadowvol {

/// Keys: pixels, meshChecks, stencilVsCount, eyeInsideVolume, recountedPixels, zfailVsZpass,
/// againstExact, requiredAgreement, verdict, passed. Where a check does not apply (no volume,
/// or `silhouetteMethod`: the silhouette volume is scored against exact shadows only) the value
/// is a sentence saying why.
nlohmann::json describeValidation(const FrameValidation& v, const ValidationOptions& options, bool silhouetteMethod);

}  // namespace shadowvol

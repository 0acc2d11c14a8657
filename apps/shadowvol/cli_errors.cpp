#include "cli_errors.h"

#include <array>
#include <string_view>

namespace shadowvol::cli {
namespace {

constexpr std::array kFlags{
    LibraryFieldFlag{"RenderOptions", "imageWidth x imageHeight", "--size"},
    LibraryFieldFlag{"RenderOptions", "depthWidth x depthHeight", "--resolution"},
    LibraryFieldFlag{"Renderer::captureDepth", "width x height", "--resolution"},
    LibraryFieldFlag{"RenderOptions", "shadowBiasConstant", "--shadow-bias"},
    LibraryFieldFlag{"RenderOptions", "shadowBiasSlope", "--shadow-slope"},
    LibraryFieldFlag{"RenderOptions", "volumeOptions.blurOffset", "--blur-offset"},
    LibraryFieldFlag{"RenderOptions", "volumeOptions.bias", "--bias"},
    LibraryFieldFlag{"RenderOptions", "volumeOptions.refineSteps", "--refine"},
    LibraryFieldFlag{"RenderOptions", "volumeOptions.cap", "--cap"},
    LibraryFieldFlag{"RenderOptions", "volumeCount", "--count"},
    LibraryFieldFlag{"RenderOptions", "gpuVolumeDraw", "--gpu-draw"},
    LibraryFieldFlag{"RenderOptions", "method", "--method"},
    LibraryFieldFlag{"RenderOptions", "volume", "--volume"},
    LibraryFieldFlag{"RenderOptions", "capture", "--capture"},
    LibraryFieldFlag{"RenderOptions", "paraboloidSubdivision", "--dpsm-subdivide"},
    LibraryFieldFlag{"RenderOptions", "depthWidth", "--resolution"},
    LibraryFieldFlag{"Renderer::captureCube", "n x n", "--resolution"},
    LibraryFieldFlag{"cube map", "N", "--resolution"},
    LibraryFieldFlag{"RenderOptions", "refineCrossings", "--crossings"},
    LibraryFieldFlag{"RenderOptions", "explicitDepth", "--depth-from"},
    LibraryFieldFlag{"ContextOptions", "platform", "--platform"},
    LibraryFieldFlag{"SweepOptions", "methods", "--methods"},
    LibraryFieldFlag{"SweepOptions", "resolutions", "--resolutions"},
    LibraryFieldFlag{"SweepOptions", "scenes", "--scenes"},
    LibraryFieldFlag{"volume options", "bias", "--bias"},
    LibraryFieldFlag{"volume options", "blur offset", "--blur-offset"},
    LibraryFieldFlag{"volume options", "blur", "--blur"},
    LibraryFieldFlag{"volume options", "refine steps", "--refine"},
    LibraryFieldFlag{"volume options", "cap", "--cap"},
    LibraryFieldFlag{"volume options", "refine subdivisions", "--refine-grid"},
    LibraryFieldFlag{"volume options", "refine chords", "--chord-points"},
    LibraryFieldFlag{"volume options", "refine grid everywhere", "--refine-grid-everywhere"},
    LibraryFieldFlag{"volume options", "refine snap", "--no-snap"},
    LibraryFieldFlag{"volume options", "refine hidden", "--no-hidden-search"},
    LibraryFieldFlag{"volume options", "face prisms", "--face-prisms"},
    LibraryFieldFlag{"volume options", "flatten cap", "--no-flatten"},
};

}  // namespace

std::span<const LibraryFieldFlag> libraryFieldFlags() { return kFlags; }

InputError asCommandLineError(const InputError& e) {
  const auto flagOf = [&](std::string_view field) -> const LibraryFieldFlag* {
    for (const LibraryFieldFlag& f : kFlags)
      if (e.source() == f.source && field == f.field) return &f;
    return nullptr;
  };
  const std::string problem = e.problemNamed([&](std::string_view field) {
    const LibraryFieldFlag* f = flagOf(field);
    return std::string(f ? f->flag : field);
  });
  const LibraryFieldFlag* f = flagOf(e.field());
  if (!f && !e.hasFieldMarks()) return e;
  const std::string source = f ? "command line" : e.source(), field = f ? std::string(f->flag) : e.field();
  if (dynamic_cast<const OptionConflict*>(&e)) return OptionConflict(source, field, e.value(), problem);
  return InputError(source, field, e.value(), problem);
}

}  // namespace shadowvol::cli

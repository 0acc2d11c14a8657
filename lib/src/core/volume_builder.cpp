#include "shadowvol/volume_builder.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include <glm/geometric.hpp>
#include <tbb/task_group.h>

#include "shadowvol/check.h"
#include "shadowvol/error.h"
#include "shadowvol/far_cap.h"
#include "volume/build_buffers.h"
#include "volume/cap_boundary.h"
#include "volume/cap_triangles.h"
#include "volume/grid_unprojector.h"
#include "volume/quad_codes.h"
#include "volume/sheet_depths.h"
#include "volume/sheet_emit.h"
#include "volume/sheet_vertices.h"

namespace shadowvol {

const char* toString(FarCap c) { return c == FarCap::Exact ? "exact" : "quad"; }

bool parseFarCap(const std::string& text, FarCap& c) {
  if (text == "exact") c = FarCap::Exact;
  else if (text == "quad") c = FarCap::Quad;
  else return false;
  return true;
}

namespace {

// defaultBias from the map's metadata: light view and projection, size, far plane, capture.
double defaultBiasOf(const glm::dmat4& view, const glm::dmat4& projection, int width, int height, double farPlane,
                     CaptureMode capture) {
  if (capture != CaptureMode::Front) return 0.0;
  // Texel footprint at the far plane (the largest over the map for a spot light; constant for a
  // directional one): the depth change across one texel of a receiver tilted 45 degrees.
  const TexelUnprojector unproject(view, projection, width, height);
  const double w2 = 0.5 * (width - 1), h2 = 0.5 * (height - 1);
  const glm::dvec3 c = unproject.lightViewPoint(w2, h2, farPlane);
  const double footprint = std::max(glm::length(unproject.lightViewPoint(w2 + 1.0, h2, farPlane) - c),
                                    glm::length(unproject.lightViewPoint(w2, h2 + 1.0, farPlane) - c));
  // Float depth precision: 4 ulps of a float at the far plane (2^-23 relative per ulp).
  const double precision = 4.0 * farPlane * std::ldexp(1.0, -23);
  return footprint + precision;
}

}  // namespace

double defaultBias(const DepthMap& map) {
  return defaultBiasOf(map.lightView, map.lightProjection, map.width, map.height, map.farPlane, map.capture);
}

double defaultBias(const Light& light, int width, int height, CaptureMode capture) {
  return defaultBiasOf(lightView(light), lightProjection(light, double(width) / double(height)), width, height,
                       light.farPlane, capture);
}

namespace {

// Cheap checks of the map's metadata and of the options, before anything else.
void validateMapAndOptions(const DepthMap& map, const VolumeBuildOptions& options) {
  SV_CHECK_GT(map.width, 0);
  SV_CHECK_GT(map.height, 0);
  SV_CHECK_EQ(map.depth.size(), std::size_t(map.width) * std::size_t(map.height));
  SV_CHECK_GT(map.farPlane, map.nearPlane);
  SV_CHECK_GE(map.nearPlane, 0.0);
  auto finite = [](const char* name, double v) {
    if (!std::isfinite(v)) {
      std::ostringstream value;
      value << v;
      throw InputError("volume options", name, value.str(), "must be a finite number of world units");
    }
  };
  finite("blur offset", options.blurOffset);
  if (options.bias) finite("bias", *options.bias);
}

}  // namespace

// Grid-sized scratch kept by a VolumeBuilder between builds.
struct VolumeBuilder::Scratch {
  volume::Scratch<double> blurred;        // sheet depths when materialised
  volume::Scratch<std::uint8_t> code;     // one code byte per quad
  volume::Scratch<std::uint32_t> quadTri; // index of each kept quad's first triangle
};

VolumeBuilder::VolumeBuilder() : scratch_(std::make_unique<Scratch>()) {}
VolumeBuilder::~VolumeBuilder() = default;
VolumeBuilder::VolumeBuilder(VolumeBuilder&&) noexcept = default;
VolumeBuilder& VolumeBuilder::operator=(VolumeBuilder&&) noexcept = default;

VolumeBuildResult buildVolume(const DepthMap& map, const VolumeBuildOptions& options) {
  VolumeBuilder builder;
  VolumeBuildResult result;
  builder.build(map, options, result);
  return result;
}

void VolumeBuilder::build(const DepthMap& map, const VolumeBuildOptions& options, VolumeBuildResult& result) {
  result.mesh.positions.clear();
  result.mesh.triangles.clear();
  result.stats = {};
  try {
    buildInto(map, options, result);
  } catch (...) {
    result.mesh.positions.clear();
    result.mesh.triangles.clear();
    result.stats = {};
    throw;
  }
}

void VolumeBuilder::buildInto(const DepthMap& map, const VolumeBuildOptions& options, VolumeBuildResult& result) {
  using namespace volume;
  const auto tStart = Clock::now();
  validateMapAndOptions(map, options);
  VolumeBuildStats& stats = result.stats;
  const double bias = options.bias.value_or(defaultBias(map));
  stats.biasUsed = bias;
  const int w = map.width, h = map.height;
  if (w < 2 || h < 2) {
    validateDepths(map);
    stats.msTotal = msSince(tStart);
    return;  // no quad: an empty volume
  }
  const std::size_t texels = std::size_t(w) * h;
  SV_CHECK_LT(3 * std::uint64_t(texels), std::uint64_t(kNone));  // sheet + pinch copies + cap vertices
  stats.quads = std::size_t(w - 1) * (h - 1);
  const bool exact = options.cap == FarCap::Exact;

  // 1. Sheet depths: materialised only for the blur (computed per row where needed otherwise).
  auto t0 = Clock::now();
  SheetDepths sheet(map, SheetDepthRule(map, bias, options.blurOffset));
  if (options.blur) {
    sheet.materialise(true, scratch_->blurred);
    stats.msBlur = msSince(t0);
  }

  // 2. Quad codes: diagonals and kept triangles.
  t0 = Clock::now();
  const GridUnprojector unproject(map);
  const QuadCodes codes = computeQuadCodes(sheet, unproject, {exact, options.triangulation == Triangulation::Perfect},
                                           scratch_->code);
  const QuadGrid grid{w - 1, h - 1, scratch_->code.data()};
  stats.flippedQuads = codes.flipped;
  stats.droppedQuads = codes.dropped;

  // 3. Vertices, and 4. the cap's boundary: pinch and cut copies, cap edges.
  const TexelUse use(grid, codes);
  const SheetVertices vertices = countSheetVertices(use);
  const auto tRuns = Clock::now();
  const CapBoundary boundary = findCapBoundary(use, vertices, sheet);
  stats.splitVertices = boundary.copies;
  const double msEdges = msSince(tRuns);

  // The flattened cap needs only the edges: triangulated while the sheet is emitted.
  const bool flatCap = !exact || options.flattenCap;
  std::vector<std::array<std::uint32_t, 3>> cap;
  double msCapTask = 0.0;
  tbb::task_group capTask;
  if (flatCap)
    capTask.run([&] {
      const auto tc = Clock::now();
      cap = triangulateCapLoops(boundary.edges);
      msCapTask = msSince(tc);
    });

  // 5. The sheet: positions and triangles, then the pinch copies. Room for the cap too (a
  // flattened cap has about as many triangles as boundary edges), so that appending it rarely
  // reallocates.
  VolumeMesh& mesh = result.mesh;
  const std::uint64_t sheetTriangles = codes.sheetTriangles();
  sizeBuffer(mesh.positions, vertices.count() + boundary.copies);
  sizeBuffer(mesh.triangles, sheetTriangles, sheetTriangles + sheetTriangles / 4 + 4 * std::size_t(w + h) + 64);
  sizeBuffer(scratch_->quadTri, stats.quads);
  try {
    emitSheet(sheet, unproject, use, codes, vertices, mesh, scratch_->quadTri);
  } catch (...) {
    capTask.wait();
    throw;
  }
  emitPinchCopies(grid, boundary, scratch_->quadTri, mesh);
  stats.msSheet = msSince(t0) - msEdges;

  // 6. The far cap.
  t0 = Clock::now();
  stats.capTrianglesBefore = sheetTriangles;
  if (flatCap) {
    capTask.wait();
    appendFlatCap(cap, mesh);
    stats.capTrianglesAfter = cap.size();
  } else {
    stats.capTrianglesAfter = appendMirroredCap(grid, scratch_->quadTri, boundary.edges, unproject, map.farPlane, mesh);
  }
  stats.msCap = msSince(t0) + msEdges + msCapTask;  // the cap's own work, partly run during the sheet
  stats.msTotal = msSince(tStart);
}

}  // namespace shadowvol

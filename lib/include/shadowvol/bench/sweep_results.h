// The rows of a time-against-error sweep (`shadowvol bench`) and their CSV file.
//
// results.csv: one header line, then one row per (scene, method, resolution) cell, columns in the
// order of kSweepColumns. Empty fields mean "not applicable" (a phase the method does not have, an
// error figure with no pixels). Numbers are written with enough digits to read back exactly.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace shadowvol {

/// Median, min and max of one timed quantity over the measured frames, milliseconds.
struct TimeStat {
  double median = 0.0, min = 0.0, max = 0.0;
};

struct SweepRow {
  // The cell.
  std::string scene;          ///< scene file stem, e.g. "sweep-032000", or "default"
  std::size_t triangles = 0;  ///< scene triangles
  std::string method;         ///< method key, e.g. "shadowmap", "pcf3", "hybrid-perfect-blur/gpu", "silhouette"
  std::string family;         ///< shadowmap | pcf3 | pcf5 | hybrid | silhouette
  std::string capture;        ///< back | front | midpoint ("" for silhouette)
  int resolution = 0;         ///< depth map N (N x N); 0 for silhouette (no depth map)
  int width = 0, height = 0;  ///< image pixels
  // Time.
  std::string timing;         ///< gpu-timer | wall-clock-glfinish
  int frames = 0;             ///< measured frames (after the warm-up)
  TimeStat frame;             ///< whole frame
  std::vector<std::pair<std::string, TimeStat>> phases;  ///< light, resolve, blur, readback, build,
                                                          ///< upload, camera, volume, lighting, shade, silhouette
  std::size_t volumeTriangles = 0;  ///< hybrid and silhouette: triangles drawn for the volume
  std::size_t volumeQuads = 0;      ///< hybrid/gpu: quads of the depth map (0 otherwise)
  std::size_t volumeQuadsDrawn = 0; ///< hybrid/gpu: quads the geometry shader expanded
  std::string volumeCount;          ///< stencil methods: "z-pass" or "z-fail" (gl::VolumeCount used);
                                    ///< empty otherwise and in files of version < 2
  // Error against the exact shadows, over visible pixels facing the light inside its frustum.
  std::size_t pixels = 0;           ///< pixels compared
  double error = 0.0, leak = 0.0, acne = 0.0;           ///< fractions of `pixels`
  std::size_t bandPixels = 0;       ///< of those, within kBoundaryBand pixels of the exact boundary
  double bandError = 0.0, bandLeak = 0.0, bandAcne = 0.0;  ///< fractions of bandPixels
  std::optional<double> distMean, distP99, distMax;     ///< distance of misclassified pixels from the
                                                         ///< exact boundary, image pixels; unset when none
};

/// Half-width of the band around the exact shadow boundary, image pixels.
inline constexpr double kBoundaryBand = 3.0;

/// The phase names of a row, in CSV column order.
const std::vector<std::string>& sweepPhases();

/// CSV header (column names, comma-separated, no newline).
std::string sweepCsvHeader();
/// One CSV line (no newline).
std::string toCsv(const SweepRow& row);
/// Parses one CSV line; throws InputError naming `source`, the line number and the column on bad input.
/// The version of the file this code writes: 4 added list_ms, 3 crossings_ms, 2 volume_count, 1
/// volume_quads and volume_quads_drawn. `version` < kSweepCsvVersion reads a file of an earlier version (the
/// columns it lacks stay empty or 0); readSweepCsv picks it from the header.
inline constexpr int kSweepCsvVersion = 4;
SweepRow parseSweepRow(const std::string& line, const std::string& source, std::size_t lineNumber,
                       int version = kSweepCsvVersion);

/// Reads results.csv. A last line without its newline (an interrupted write) is ignored.
std::vector<SweepRow> readSweepCsv(const std::filesystem::path& path);

/// Key of a cell: scene | method | resolution | widthxheight (what resume compares).
std::string cellKey(const SweepRow& row);

}  // namespace shadowvol

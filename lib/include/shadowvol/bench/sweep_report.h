// The report of a time-against-error sweep (`shadowvol bench`): DIR/report.md and its SVG plots,
// written from the rows of DIR/results.csv. Plain text output, no plotting library.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "shadowvol/bench/sweep_results.h"

namespace shadowvol {

/// What the report states at its top, as given (free text, one line each; empty = "unknown").
struct SweepReportInfo {
  std::string machine;     ///< e.g. "2 cores, Intel Xeon ..., 8 GiB"
  std::string glRenderer;  ///< GL_RENDERER string, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string timing;      ///< how frames were timed, e.g. "gpu-timer" or "wall-clock-glfinish"
  std::string command;     ///< the command line that reproduces the sweep
};

/// Writes DIR/report.md, DIR/plots/<scene>.svg (error against frame time, one per scene and image
/// size) and DIR/plots/polygon-sweep.svg (frame time against triangle count for the scenes named
/// sweep-*, when there are any) from `rows` (all of results.csv, any order; a repeated cell counts
/// once, the last one wins). Each file is written atomically (writeAtomically). Rows with non-finite
/// figures show as "n/a" in tables and are left out of plots. Returns the paths written, report.md
/// first. Throws InputError when a file cannot be written.
std::vector<std::filesystem::path> writeSweepReport(const std::vector<SweepRow>& rows, const SweepReportInfo& info,
                                                    const std::filesystem::path& dir);

/// The Pareto front of (time, error) points: the indices of the points no other point dominates,
/// sorted by time (then by error, then by index). Point a dominates b when a is no slower and no
/// worse and strictly better in one of the two; exact duplicates therefore both stay on the front.
/// Points with a non-finite coordinate are never on the front. Empty input gives an empty front.
std::vector<std::size_t> paretoFront(const std::vector<std::pair<double, double>>& timeError);

}  // namespace shadowvol

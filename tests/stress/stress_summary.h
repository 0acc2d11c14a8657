// The suite's results: a table by category (configs, passed, one column per failure kind), the
// failing configurations with their reasons; printed, and written as summary.json and summary.md.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "config_runner.h"
#include "stress_config.h"
#include "stress_judge.h"

namespace shadowvol::stress {

struct ConfigResult {
  StressConfig config;
  ConfigOutcome outcome;
  Judgement judgement;
};

struct SuiteRun {
  std::string mode;                 ///< "quick" or "full", plus " --only CATEGORY"
  std::filesystem::path shadowvol;  ///< the binary under test
  RunSettings settings;
  double wallSeconds = 0;
  std::vector<ConfigResult> results;  ///< in run order
  bool passed() const;                ///< every configuration meets the goal
};

/// The table and the failing configurations, as text.
void printSummary(const SuiteRun& run, std::ostream& out);
/// OUT/summary.json: totals, per-category counts, and every configuration with its runs,
/// failures and notes.
void writeSummaryJson(const SuiteRun& run, const std::filesystem::path& file);
/// OUT/summary.md: the same table and failure list in Markdown, then the informational notes.
void writeSummaryMarkdown(const SuiteRun& run, const std::filesystem::path& file);

}  // namespace shadowvol::stress

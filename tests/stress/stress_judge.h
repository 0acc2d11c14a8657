// Judges one configuration's runs against the robustness goal. The criteria, per category, are
// stated at the top of stress_suite.cpp; this file implements them.
#pragma once

#include <string>
#include <vector>

#include "config_runner.h"
#include "stress_config.h"

namespace shadowvol::stress {

/// A failed criterion; the table has one column per kind.
enum class FailureKind { Crash, NonFinite, NotClosedOutward, Agreement, ZfailZpass, OffsetTwin, RefusedWrong, Other };
inline constexpr FailureKind kFailureKinds[] = {
    FailureKind::Crash,      FailureKind::NonFinite,  FailureKind::NotClosedOutward, FailureKind::Agreement,
    FailureKind::ZfailZpass, FailureKind::OffsetTwin, FailureKind::RefusedWrong,     FailureKind::Other};
/// The column heading ("crashes", "non-finite", ...) and the key in summary.json ("crash", ...).
const char* failureColumn(FailureKind k);
const char* failureKey(FailureKind k);

struct Finding {
  FailureKind kind;
  std::string run;     ///< "explicit", "gpu", "front", "build", or "" for the configuration as a whole
  std::string reason;  ///< one line
};

struct Judgement {
  std::vector<Finding> failures;   ///< empty = the configuration meets the goal
  std::vector<std::string> notes;  ///< informational only: accuracy verdicts, informational twin drift
  bool passed() const { return failures.empty(); }
  bool has(FailureKind k) const;
};

/// The twin comparison's tolerances (an offset config against its at-origin twin).
struct TwinTolerance {
  double exactShare = 0.02;     ///< exact-shadow pixel counts may differ by 2 % of the twin's ...
  double exactSlackPixels = 1;  ///< ... or by 1 pixel, whichever is more
  double errorFactor = 1.5;     ///< the method's error fraction may be 1.5 x the twin's ...
  double errorSlack = 1e-3;     ///< ... plus 0.1 % of the pixels facing the light (about 8 of the default view's)
};

/// Judges `c` from its runs; `twin` is the twin's outcome (null when it has none or it was not run).
Judgement judgeConfig(const StressConfig& c, const ConfigOutcome& outcome, const ConfigOutcome* twin,
                      const RunSettings& settings, const TwinTolerance& tolerance = {});

}  // namespace shadowvol::stress

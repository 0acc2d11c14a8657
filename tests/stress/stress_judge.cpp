#include "stress_judge.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shadowvol::stress {
namespace {

using nlohmann::json;

constexpr double kRequiredAgreement = 0.9999;  // the goal: stencil vs count on >= 99.99 % of visible pixels

std::string percent(double f, int digits = 3) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f %%", digits, 100 * f);
  return buf;
}

/// JSON pointers of the null values in `j`: nlohmann writes NaN and infinities as null. The only
/// null validate writes on purpose, meshChecks.notApplicable, is skipped.
void nullFields(const json& j, const std::string& at, std::vector<std::string>& out) {
  if (j.is_null()) out.push_back(at.empty() ? "/" : at);
  if (j.is_object())
    for (auto it = j.begin(); it != j.end(); ++it)
      if (it.key() != "notApplicable") nullFields(it.value(), at + "/" + it.key(), out);
  if (j.is_array())
    for (std::size_t k = 0; k < j.size(); ++k) nullFields(j[k], at + "/" + std::to_string(k), out);
}

std::string joinFirst(const std::vector<std::string>& items, std::size_t n) {
  std::string s;
  for (std::size_t k = 0; k < items.size() && k < n; ++k) s += (k ? ", " : "") + items[k];
  if (items.size() > n) s += ", ... (" + std::to_string(items.size()) + ")";
  return s;
}

/// The number at `pointer`, NaN where there is none (every comparison with NaN fails).
double numberAt(const json& j, const char* pointer) {
  const json::json_pointer p(pointer);
  return j.contains(p) && j.at(p).is_number() ? j.at(p).get<double>() : std::nan("");
}

bool crashed(const ProcessResult& p) {
  return p.timedOut || p.signal || p.notRun || p.exitCode == 4;
}

class Judge {
 public:
  Judge(const StressConfig& c, const RunSettings& s, Judgement& j) : c_(c), s_(s), j_(j) {}

  void fail(FailureKind k, const RunOutcome& r, std::string reason) {
    j_.failures.push_back({k, runName(r.kind), reason});
  }
  void note(const RunOutcome& r, const std::string& text) {
    j_.notes.push_back(std::string(runName(r.kind)) + ": " + text);
  }

  /// Crash, or an exit status this command should not give a legal scene. True when judged done.
  bool badEnd(const RunOutcome& r, bool isBuild) {
    const ProcessResult& p = r.process;
    if (crashed(p)) {
      fail(FailureKind::Crash, r, describeEnd(p, s_.timeoutSeconds) + ": " + lastLine(p.stderrText));
      return true;
    }
    if (p.exitCode == 1 || p.exitCode == 2) {
      fail(FailureKind::RefusedWrong, r,
           "a legal scene refused (" + describeEnd(p, s_.timeoutSeconds) + "): " + lastLine(p.stderrText));
      return true;
    }
    if (p.exitCode != 0 && !(p.exitCode == 3 && !isBuild)) {
      fail(FailureKind::Other, r, "unexpected " + describeEnd(p, s_.timeoutSeconds) + ": " + lastLine(p.stderrText));
      return true;
    }
    return false;
  }

  void validateRun(const RunOutcome& r) {
    if (badEnd(r, false)) return;
    if (!r.report) {
      fail(FailureKind::Other, r,
           describeEnd(r.process, s_.timeoutSeconds) + " but " +
               (r.reportProblem.empty() ? "no report.json" : r.reportProblem));
      return;
    }
    const json& rep = *r.report;
    if (rep.value("passed", false) != (r.process.exitCode == 0))
      fail(FailureKind::Other, r, "exit status and report.json's \"passed\" disagree");
    std::vector<std::string> nulls;
    nullFields(rep, "", nulls);
    if (!nulls.empty())
      fail(FailureKind::NonFinite, r, "null (non-finite) values in report.json at " + joinFirst(nulls, 4));
    const json& m = rep.value("meshChecks", json());
    if (!m.is_object()) {
      fail(FailureKind::Other, r, "report.json has no mesh checks");
      return;
    }
    if (m.value("nonFiniteVertices", 0) > 0)
      fail(FailureKind::NonFinite, r, std::to_string(m.value("nonFiniteVertices", 0)) + " non-finite volume vertices");
    // An empty volume (nothing casts a shadow at this resolution) is closed, and outward does not
    // apply: its signed volume is 0. validate's own verdict treats it so too.
    const bool closed = m.value("closedManifold", false);
    const bool outward = m.value("outward", false) || m.value("triangles", 1) == 0;
    if (!closed || !outward)
      fail(FailureKind::NotClosedOutward, r,
           std::string(closed ? "" : "not closed") + (closed || outward ? "" : ", ") + (outward ? "" : "not outward") +
               ": " + m.value("summary", std::string()));
    if (m.value("triangles", 1) == 0) note(r, "empty volume: nothing casts a shadow at this resolution");
    else if (closed && outward && !m.value("valid", true))  // degenerate faces and the like: not in the goal
      note(r, "mesh checks beyond closed/outward fail: " + m.value("summary", std::string()));
    agreement(r, rep);
    zfailZpass(r, rep);
    const json& verdict = rep.value("verdict", json());
    if (verdict.is_object() && !verdict.value("accurate", true))
      note(r, "accuracy verdict failed (not a robustness failure): " +
                  joinFirst(verdict.value("failures", std::vector<std::string>()), 2));
  }

  void agreement(const RunOutcome& r, const json& rep) {
    const json& a = rep.value("stencilVsCount", json());
    if (!a.is_object()) {
      fail(FailureKind::Other, r, "report.json has no stencilVsCount");
      return;
    }
    const double f = a.value("fraction", 0.0);
    if (!(f >= kRequiredAgreement))
      fail(FailureKind::Agreement, r,
           "stencil vs count " + percent(f) + " (" + std::to_string(a.value("disagree", 0)) + " of " +
               std::to_string(a.value("pixels", 0)) + " visible pixels disagree)");
  }

  void zfailZpass(const RunOutcome& r, const json& rep) {
    const bool inside = rep.value("eyeInsideVolume", false);
    const json& z = rep.value("zfailVsZpass", json());
    if (c_.eyeInside && *c_.eyeInside != inside) {
      if (inside)  // the comparison the goal asks for was skipped
        fail(FailureKind::ZfailZpass, r,
             "validate classed the eye as inside the volume, but it lies clearly outside: "
             "z-fail vs z-pass was not compared");
      else
        note(r, "validate classed the eye as outside the volume, but it lies clearly inside");
    }
    if (inside) return;
    if (!z.is_object()) {
      fail(FailureKind::Other, r, "eye outside the volume but no zfailVsZpass in report.json");
      return;
    }
    if (z.value("disagree", 0) != 0)
      fail(FailureKind::ZfailZpass, r,
           "z-fail != z-pass on " + std::to_string(z.value("disagree", 0)) + " of " +
               std::to_string(z.value("pixels", 0)) + " pixels, eye outside the volume");
  }

  void buildRun(const RunOutcome& r) {
    if (badEnd(r, true)) return;
    if (!r.ply) {
      fail(FailureKind::Other, r, "exit 0 but no volume.ply written");
      return;
    }
    const PlyCheck& p = *r.ply;
    if (!p.error.empty()) {
      fail(FailureKind::Other, r, "volume.ply: " + p.error);
      return;
    }
    if (p.nonFinite)
      fail(FailureKind::NonFinite, r, std::to_string(p.nonFinite) + " non-finite vertices in volume.ply");
    if (!p.closed() || !p.outward()) {
      char buf[256];
      std::snprintf(buf, sizeof buf, "volume.ply: %zu open, %zu overused, %zu same-direction edges; volume %.6g",
                    p.openEdges, p.overusedEdges, p.sameDirection, p.signedVolume);
      fail(FailureKind::NotClosedOutward, r, buf);
    }
    std::vector<std::string> nulls;
    if (r.stdoutJson) nullFields(*r.stdoutJson, "", nulls);
    if (!nulls.empty())
      fail(FailureKind::NonFinite, r, "null (non-finite) values in build --json at " + joinFirst(nulls, 4));
  }

  void refusedRun(const RunOutcome& r) {
    const ProcessResult& p = r.process;
    const std::string file = c_.name + ".json";
    const std::string end = describeEnd(p, s_.timeoutSeconds);
    if (crashed(p)) fail(FailureKind::Crash, r, end + ": " + lastLine(p.stderrText));
    if (p.exitCode != 1) {
      fail(FailureKind::RefusedWrong, r,
           (p.exitCode == 0 || p.exitCode == 3 ? "accepted (" + end + ")" : end) +
               ", not exit 1: " + lastLine(p.stderrText));
      return;
    }
    const bool named = std::any_of(c_.fields.begin(), c_.fields.end(),
                                   [&](const std::string& f) { return p.stderrText.find(f) != std::string::npos; });
    if (!named || p.stderrText.find(file) == std::string::npos)
      fail(FailureKind::RefusedWrong, r,
           std::string("exit 1, but stderr does not name ") + (named ? "the file" : "the field") + " (" +
               joinFirst(c_.fields, 3) + "): " + lastLine(p.stderrText));
    if (r.leftOutput) fail(FailureKind::RefusedWrong, r, "refused but left its output behind");
  }

 private:
  const StressConfig& c_;
  const RunSettings& s_;
  Judgement& j_;
};

/// Exact-shadow pixels and the method's error of `r` against the twin's run of the same kind.
void compareWithTwin(const StressConfig& c, const RunOutcome& r, const RunOutcome& t, const TwinTolerance& tol,
                     Judgement& j) {
  if (!r.report || !t.report) return;  // a missing report is a failure of its own
  const double n = numberAt(*r.report, "/pixels/exactShadowed"), nt = numberAt(*t.report, "/pixels/exactShadowed");
  const double e = numberAt(*r.report, "/againstExact/method/errorFraction");
  const double et = numberAt(*t.report, "/againstExact/method/errorFraction");
  std::vector<std::string> problems;
  char buf[256];
  if (!(std::abs(n - nt) <= std::max(tol.exactShare * nt, tol.exactSlackPixels))) {
    std::snprintf(buf, sizeof buf, "exact shadow %.0f px vs twin's %.0f", n, nt);
    problems.push_back(buf);
  }
  if (!(e <= tol.errorFactor * et + tol.errorSlack)) {
    std::snprintf(buf, sizeof buf, "error %s vs twin's %s", percent(e).c_str(), percent(et).c_str());
    problems.push_back(buf);
  }
  if (problems.empty()) return;
  const std::string what = joinFirst(problems, 2) + " (twin " + *c.twin + ")";
  if (c.twinRole == TwinRole::Required)
    j.failures.push_back({FailureKind::OffsetTwin, runName(r.kind), what});
  else
    j.notes.push_back(std::string(runName(r.kind)) + ": twin drift (informational): " + what);
}

}  // namespace

const char* failureColumn(FailureKind k) {
  switch (k) {
    case FailureKind::Crash:
      return "crashes";
    case FailureKind::NonFinite:
      return "non-finite";
    case FailureKind::NotClosedOutward:
      return "not closed/outward";
    case FailureKind::Agreement:
      return "agree < 99.99%";
    case FailureKind::ZfailZpass:
      return "z-fail != z-pass";
    case FailureKind::OffsetTwin:
      return "offset twin";
    case FailureKind::RefusedWrong:
      return "refused wrong";
    case FailureKind::Other:
      return "other";
  }
  return "?";
}

const char* failureKey(FailureKind k) {
  switch (k) {
    case FailureKind::Crash:
      return "crash";
    case FailureKind::NonFinite:
      return "nonFinite";
    case FailureKind::NotClosedOutward:
      return "notClosedOutward";
    case FailureKind::Agreement:
      return "agreement";
    case FailureKind::ZfailZpass:
      return "zfailZpass";
    case FailureKind::OffsetTwin:
      return "offsetTwin";
    case FailureKind::RefusedWrong:
      return "refusedWrong";
    case FailureKind::Other:
      return "other";
  }
  return "?";
}

bool Judgement::has(FailureKind k) const {
  return std::any_of(failures.begin(), failures.end(), [k](const Finding& f) { return f.kind == k; });
}

Judgement judgeConfig(const StressConfig& c, const ConfigOutcome& outcome, const ConfigOutcome* twin,
                      const RunSettings& settings, const TwinTolerance& tolerance) {
  Judgement j;
  Judge judge(c, settings, j);
  for (const RunOutcome& r : outcome.runs) {
    if (c.refused)
      judge.refusedRun(r);
    else if (r.kind == RunKind::Build)
      judge.buildRun(r);
    else
      judge.validateRun(r);
  }
  if (c.twin && !twin && c.twinRole == TwinRole::Required)
    j.failures.push_back({FailureKind::OffsetTwin, "", "its twin " + *c.twin + " was not run"});
  if (c.twin && twin)
    for (const RunOutcome& r : outcome.runs)
      if (r.kind != RunKind::Build)
        if (const RunOutcome* t = twin->find(r.kind)) compareWithTwin(c, r, *t, tolerance, j);
  return j;
}

}  // namespace shadowvol::stress

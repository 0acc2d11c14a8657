#include "stress_summary.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>

namespace shadowvol::stress {
namespace {

using nlohmann::json;

struct Counts {
  int configs = 0, passed = 0;
  std::map<FailureKind, int> failed;  // configurations with at least one failure of the kind
  void add(const Judgement& j) {
    ++configs;
    passed += j.passed();
    for (FailureKind k : kFailureKinds) failed[k] += j.has(k);
  }
};

/// Counts per category in kCategories order (only those that ran), then "total".
std::vector<std::pair<std::string, Counts>> countByCategory(const SuiteRun& run) {
  std::vector<std::pair<std::string, Counts>> rows;
  Counts total;
  for (const std::string& cat : kCategories) {
    Counts c;
    for (const ConfigResult& r : run.results)
      if (r.config.category == cat) c.add(r.judgement);
    if (c.configs) rows.emplace_back(cat, c);
  }
  for (const ConfigResult& r : run.results) total.add(r.judgement);
  rows.emplace_back("total", total);
  return rows;
}

std::vector<std::vector<std::string>> tableCells(const SuiteRun& run) {
  std::vector<std::vector<std::string>> cells;
  std::vector<std::string> head = {"category", "configs", "passed"};
  for (FailureKind k : kFailureKinds) head.push_back(failureColumn(k));
  cells.push_back(head);
  for (const auto& [cat, c] : countByCategory(run)) {
    std::vector<std::string> row = {cat, std::to_string(c.configs), std::to_string(c.passed)};
    for (FailureKind k : kFailureKinds) row.push_back(std::to_string(c.failed.at(k)));
    cells.push_back(row);
  }
  return cells;
}

std::string findingText(const Finding& f) {
  return std::string("[") + failureKey(f.kind) + (f.run.empty() ? "" : ", " + f.run) + "] " + f.reason;
}

std::string header(const SuiteRun& run) {
  char buf[512];
  int failing = 0;
  for (const ConfigResult& r : run.results) failing += !r.judgement.passed();
  std::snprintf(buf, sizeof buf, "shadowvol stress suite (%s): %zu configurations, %d failing, %.1f s wall; %s",
                run.mode.c_str(), run.results.size(), failing, run.wallSeconds, run.shadowvol.string().c_str());
  return buf;
}

}  // namespace

bool SuiteRun::passed() const {
  return std::all_of(results.begin(), results.end(), [](const ConfigResult& r) { return r.judgement.passed(); });
}

void printSummary(const SuiteRun& run, std::ostream& out) {
  const auto cells = tableCells(run);
  std::vector<std::size_t> width(cells[0].size(), 0);
  for (const auto& row : cells)
    for (std::size_t k = 0; k < row.size(); ++k) width[k] = std::max(width[k], row[k].size());
  out << header(run) << "\n\n";
  for (const auto& row : cells) {
    for (std::size_t k = 0; k < row.size(); ++k) {
      const std::string pad(width[k] - row[k].size(), ' ');
      out << (k == 0 ? row[k] + pad : pad + row[k]) << (k + 1 < row.size() ? "  " : "\n");
    }
  }
  out << "\n";
  for (const ConfigResult& r : run.results) {
    if (r.judgement.passed()) continue;
    out << "FAIL " << r.config.name << " (" << r.config.what << ")\n";
    for (const Finding& f : r.judgement.failures) out << "     " << findingText(f) << "\n";
  }
  std::size_t notes = 0;
  for (const ConfigResult& r : run.results) notes += r.judgement.notes.size();
  out << (run.passed() ? "\nPASSED" : "\nFAILED") << ": every configuration " << (run.passed() ? "meets" : "must meet")
      << " the goal; " << notes << " informational notes (accuracy, twin drift) are in summary.json\n";
}

void writeSummaryJson(const SuiteRun& run, const std::filesystem::path& file) {
  json j;
  j["mode"] = run.mode;
  j["shadowvol"] = run.shadowvol.string();
  j["resolution"] = run.settings.resolution;
  j["size"] = run.settings.size;
  j["wallSeconds"] = run.wallSeconds;
  j["passed"] = run.passed();
  for (const auto& [cat, c] : countByCategory(run)) {
    json row = {{"category", cat}, {"configs", c.configs}, {"passed", c.passed}};
    for (FailureKind k : kFailureKinds) row[failureKey(k)] = c.failed.at(k);
    j["categories"].push_back(row);
  }
  j["configs"] = json::array();
  for (const ConfigResult& r : run.results) {
    json cj = {{"name", r.config.name},          {"category", r.config.category}, {"what", r.config.what},
               {"passed", r.judgement.passed()}, {"seconds", r.outcome.seconds},  {"notes", r.judgement.notes}};
    if (r.config.twin) cj["twin"] = *r.config.twin;
    cj["failures"] = json::array();
    for (const Finding& f : r.judgement.failures)
      cj["failures"].push_back({{"kind", failureKey(f.kind)}, {"run", f.run}, {"reason", f.reason}});
    for (const RunOutcome& o : r.outcome.runs)
      cj["runs"].push_back({{"run", runName(o.kind)},
                            {"end", describeEnd(o.process, run.settings.timeoutSeconds)},
                            {"seconds", o.process.seconds},
                            {"argv", o.argv}});
    j["configs"].push_back(cj);
  }
  std::ofstream(file) << j.dump(2) << '\n';
}

void writeSummaryMarkdown(const SuiteRun& run, const std::filesystem::path& file) {
  std::ofstream out(file);
  out << "# " << header(run) << "\n\n";
  const auto cells = tableCells(run);
  for (std::size_t r = 0; r < cells.size(); ++r) {
    out << "|";
    for (const auto& cell : cells[r]) out << " " << cell << " |";
    out << "\n";
    if (r == 0) {
      out << "|";
      for (std::size_t k = 0; k < cells[r].size(); ++k) out << (k == 0 ? "---|" : "---:|");
      out << "\n";
    }
  }
  out << "\n## Failing configurations\n\n";
  bool any = false;
  for (const ConfigResult& r : run.results) {
    if (r.judgement.passed()) continue;
    any = true;
    out << "- `" << r.config.name << "` (" << r.config.what << ")\n";
    for (const Finding& f : r.judgement.failures) out << "  - " << findingText(f) << "\n";
  }
  if (!any) out << "None.\n";
  out << "\n## Informational notes (not failures)\n\n";
  for (const ConfigResult& r : run.results)
    for (const std::string& n : r.judgement.notes) out << "- `" << r.config.name << "` " << n << "\n";
}

}  // namespace shadowvol::stress

// The sweep report: the Pareto front on hand-made points, and report.md + SVG plots from hand-made rows.
#include "shadowvol/bench/sweep_report.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace shadowvol {
namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

/// A simple well-formedness check: every element opened is closed in order (no comments, no CDATA).
bool balancedTags(const std::string& xml) {
  std::vector<std::string> open;
  for (std::size_t at = xml.find('<'); at != std::string::npos; at = xml.find('<', at + 1)) {
    const std::size_t end = xml.find('>', at);
    if (end == std::string::npos) return false;
    const std::string tag = xml.substr(at + 1, end - at - 1);
    if (tag.empty()) return false;
    if (tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1)) return false;
      open.pop_back();
    } else if (tag.back() != '/') {
      open.push_back(tag.substr(0, tag.find_first_of(" \t\n")));
    }
  }
  return open.empty();
}

TEST(ParetoFront, KnownFrontWithTiesAndDuplicates) {
  const std::vector<std::pair<double, double>> p = {
      {4.0, 0.10},  // 0: front
      {1.0, 0.50},  // 1: front (fastest)
      {2.0, 0.60},  // 2: dominated by 1
      {2.0, 0.30},  // 3: front
      {3.0, 0.30},  // 4: dominated by 3 (same error, slower)
      {2.0, 0.30},  // 5: duplicate of 3: kept
      {8.0, 0.10},  // 6: dominated by 0 (same error, slower)
      {9.0, 0.00},  // 7: front (zero error)
      {1.0, 0.70},  // 8: dominated by 1 (same time, worse)
  };
  EXPECT_EQ(paretoFront(p), (std::vector<std::size_t>{1, 3, 5, 0, 7}));
}

TEST(ParetoFront, DegenerateInputs) {
  EXPECT_TRUE(paretoFront({}).empty());
  EXPECT_EQ(paretoFront({{5.0, 0.2}}), (std::vector<std::size_t>{0}));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(paretoFront({{nan, 0.0}, {2.0, nan}, {3.0, 0.4}}), (std::vector<std::size_t>{2}));
  // All equal: all kept, in index order.
  EXPECT_EQ(paretoFront({{1.0, 0.1}, {1.0, 0.1}, {1.0, 0.1}}), (std::vector<std::size_t>{0, 1, 2}));
}

SweepRow row(const std::string& scene, std::size_t triangles, const std::string& method, const std::string& family,
             int resolution, double ms, double error) {
  SweepRow r;
  r.scene = scene;
  r.triangles = triangles;
  r.method = method;
  r.family = family;
  r.capture = family == "silhouette" ? "" : "back";
  r.resolution = resolution;
  r.width = 320;
  r.height = 240;
  r.timing = "wall-clock-glfinish";
  r.frames = 5;
  r.frame = {ms, ms * 0.9, ms * 1.2};
  r.phases = {{"light", {ms * 0.25, 0, 0}}, {"camera", {ms * 0.5, 0, 0}}};
  r.pixels = 50000;
  r.error = error;
  r.leak = error / 2;
  r.acne = error / 2;
  r.bandPixels = 4000;
  r.bandError = error * 10;
  if (error > 0) r.distMean = 1.5, r.distP99 = 4.25, r.distMax = 7.0;
  return r;
}

class SweepReportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) /
           ("sweep_report_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(SweepReportTest, WritesReportAndPlots) {
  std::vector<SweepRow> rows;
  for (const auto& [scene, tris] :
       {std::pair<std::string, std::size_t>{"sweep-000500", 500}, {"sweep-032000", 32000}}) {
    const double k = tris == 500 ? 1.0 : 3.0;
    rows.push_back(row(scene, tris, "shadowmap", "shadowmap", 64, 1.25 * k, 0.0625));
    rows.push_back(row(scene, tris, "shadowmap", "shadowmap", 256, 2.5 * k, 0.03125));
    rows.push_back(row(scene, tris, "shadowmap", "shadowmap", 1024, 10.0 * k, 0.015625));
    rows.push_back(row(scene, tris, "pcf3", "pcf3", 64, 1.5 * k, 0.05));
    rows.push_back(row(scene, tris, "pcf3", "pcf3", 256, 3.0 * k, 0.025));
    rows.push_back(row(scene, tris, "hybrid-fixed/gpu", "hybrid", 64, 2.0 * k, 0.0125));
    rows.push_back(row(scene, tris, "hybrid-fixed/gpu", "hybrid", 256, 4.0 * k, 0.0));
  }
  SweepReportInfo info{"test machine, 2 cores", "llvmpipe (test)", "wall-clock-glfinish",
                       "shadowvol bench --out results-test"};
  const auto written = writeSweepReport(rows, info, dir_);

  ASSERT_FALSE(written.empty());
  EXPECT_EQ(written.front(), dir_ / "report.md");
  for (const auto& p : {dir_ / "report.md", dir_ / "plots" / "sweep-000500.svg", dir_ / "plots" / "sweep-032000.svg",
                        dir_ / "plots" / "polygon-sweep.svg"}) {
    EXPECT_TRUE(fs::is_regular_file(p)) << p;
    EXPECT_TRUE(std::count(written.begin(), written.end(), p)) << p;
  }
  EXPECT_EQ(written.size(), 4u);

  for (const char* name : {"sweep-000500.svg", "sweep-032000.svg", "polygon-sweep.svg"}) {
    const std::string svg = readText(dir_ / "plots" / name);
    SCOPED_TRACE(name);
    EXPECT_EQ(svg.rfind("<svg", 0), 0u);
    EXPECT_TRUE(balancedTags(svg));
    EXPECT_EQ(count(svg, "<polyline class=\"curve\""), 3u);  // one per method
    EXPECT_EQ(count(svg, "nan"), 0u);
    EXPECT_EQ(count(svg, "inf"), 0u);
    for (const char* m : {"shadowmap", "pcf3", "hybrid-fixed/gpu"}) EXPECT_NE(svg.find(m), std::string::npos) << m;
  }
  const std::string scenePlot = readText(dir_ / "plots" / "sweep-000500.svg");
  EXPECT_EQ(count(scenePlot, "<polyline class=\"front\""), 1u);
  EXPECT_EQ(count(scenePlot, "<path class=\"whisker\""), 7u);  // min..max frame time of every point
  EXPECT_EQ(count(readText(dir_ / "plots" / "polygon-sweep.svg"), "class=\"whisker\""), 0u);
  EXPECT_NE(scenePlot.find("zero error"), std::string::npos);    // the hybrid's 0 at 256 is clamped and said so
  EXPECT_NE(scenePlot.find(">1024</text>"), std::string::npos);  // points labelled by resolution

  const std::string md = readText(dir_ / "report.md");
  for (const char* s : {"shadowvol bench --out results-test", "test machine, 2 cores", "llvmpipe (test)",
                        "wall-clock-glfinish", "sweep-000500", "sweep-032000", "shadowmap", "pcf3", "hybrid-fixed/gpu",
                        "![sweep-000500: error against frame time](plots/sweep-000500.svg)",
                        "(plots/polygon-sweep.svg)", "## Polygon sweep"})
    EXPECT_NE(md.find(s), std::string::npos) << s;
  // Cells: median ms / error %, and band % / p99 px.
  EXPECT_NE(md.find("| 1.25 / 6.25 |"), std::string::npos);  // shadowmap 64 on sweep-000500
  EXPECT_NE(md.find("| 3.75 / 6.25 |"), std::string::npos);  // shadowmap 64 on sweep-032000
  EXPECT_NE(md.find("| 4 / 0 |"), std::string::npos);        // hybrid 256, zero error
  EXPECT_NE(md.find("| 62.5 / 4.25 |"), std::string::npos);  // shadowmap 64: band 10x, p99 4.25
  EXPECT_NE(md.find("| 0 / - |"), std::string::npos);        // no misclassified pixel: no distance
  // Headline: target = shadow map's best (1.5625 % at 1024, 10 ms); the hybrid reaches it at 64 in 2 ms.
  EXPECT_NE(md.find("Target: 1.56 % total error"), std::string::npos);
  EXPECT_NE(md.find("| hybrid-fixed/gpu | 64 | 2 | 256 | 0 | 256 | 4 | 0 | 0 | - |"), std::string::npos) << md;
  EXPECT_NE(md.find("| pcf3 | not reached |"), std::string::npos);
  // Pareto front of sweep-000500 (the rest is dominated by these).
  EXPECT_NE(md.find("shadowmap 64 (1.25 ms, 6.25 %) → pcf3 64 (1.5 ms, 5 %) → hybrid-fixed/gpu 64 (2 ms, 1.25 %) → "
                    "hybrid-fixed/gpu 256 (4 ms, 0 %)."),
            std::string::npos);
  // Polygon sweep table at 256: frame ms per scene.
  EXPECT_NE(md.find("| shadowmap | 2.5 | 7.5 |"), std::string::npos);
  EXPECT_EQ(count(md, "nan"), 0u);
}

TEST_F(SweepReportTest, OnePointMethodsSeveralSizesAndNonFiniteRows) {
  std::vector<SweepRow> rows;
  rows.push_back(row("plate", 2, "shadowmap", "shadowmap", 128, 1.0, 0.02));
  rows.push_back(row("plate", 2, "shadowmap", "shadowmap", 512, 2.0, 0.01));
  rows.push_back(row("plate", 2, "silhouette", "silhouette", 0, 1.5, 0.0));
  SweepRow big = row("plate", 2, "shadowmap", "shadowmap", 128, 4.0, 0.03);
  big.width = 640;
  big.height = 480;
  rows.push_back(big);
  rows.push_back(row("plate", 2, "pcf5", "pcf5", 128, std::numeric_limits<double>::quiet_NaN(), 0.02));
  // A repeated cell: the last one wins.
  rows.push_back(row("plate", 2, "shadowmap", "shadowmap", 512, 2.25, 0.01));

  const auto written = writeSweepReport(rows, {}, dir_);
  EXPECT_EQ(written.size(), 3u);  // report + one plot per image size, no polygon sweep
  const std::string small = readText(dir_ / "plots" / "plate-320x240.svg");
  const std::string large = readText(dir_ / "plots" / "plate-640x480.svg");
  EXPECT_TRUE(balancedTags(small));
  EXPECT_TRUE(balancedTags(large));
  EXPECT_EQ(count(small, "<polyline class=\"curve\""), 1u);  // shadowmap; silhouette is a lone marker
  EXPECT_NE(small.find("silhouette"), std::string::npos);
  EXPECT_EQ(count(large, "<polyline class=\"curve\""), 0u);
  EXPECT_EQ(count(small, "nan"), 0u);
  EXPECT_FALSE(fs::exists(dir_ / "plots" / "polygon-sweep.svg"));

  const std::string md = readText(dir_ / "report.md");
  EXPECT_NE(md.find("### plate (320x240)"), std::string::npos);
  EXPECT_NE(md.find("### plate (640x480)"), std::string::npos);
  EXPECT_NE(md.find("Command: `unknown`"), std::string::npos);
  EXPECT_NE(md.find("| n/a / 2 |"), std::string::npos);                    // pcf5's NaN frame time
  EXPECT_NE(md.find("| silhouette | no map | 1.5 |"), std::string::npos);  // reaches the target without a map
  EXPECT_NE(md.find("2.25 / 1"), std::string::npos);
  EXPECT_EQ(md.find("2 / 1 |"), std::string::npos);  // the first copy of the repeated cell is gone
  EXPECT_EQ(count(md, "nan"), 0u);
}

// Two scenes whose names make one file name (a second probe's finding: the second plot overwrote
// the first, and both sections showed it): the second gets a number.
TEST_F(SweepReportTest, ScenesWhoseNamesMakeOneFileNameGetTwoPlots) {
  std::vector<SweepRow> rows;
  rows.push_back(row("a<b", 2, "shadowmap", "shadowmap", 128, 1.0, 0.02));
  rows.push_back(row("a>b", 2, "shadowmap", "shadowmap", 128, 3.0, 0.04));
  const auto written = writeSweepReport(rows, {}, dir_);
  EXPECT_EQ(written.size(), 3u);
  EXPECT_TRUE(fs::exists(dir_ / "plots" / "a_b.svg"));
  EXPECT_TRUE(fs::exists(dir_ / "plots" / "a_b-2.svg"));
  const std::string md = readText(dir_ / "report.md");
  EXPECT_NE(md.find("(plots/a_b.svg)"), std::string::npos);
  EXPECT_NE(md.find("(plots/a_b-2.svg)"), std::string::npos);
}

TEST_F(SweepReportTest, NoRowsGiveAReportWithoutPlots) {
  const auto written = writeSweepReport({}, {}, dir_);
  EXPECT_EQ(written, (std::vector<fs::path>{dir_ / "report.md"}));
  const std::string md = readText(dir_ / "report.md");
  EXPECT_NE(md.find("Cells: 0"), std::string::npos);
  EXPECT_EQ(md.find("## Polygon sweep"), std::string::npos);
}

}  // namespace
}  // namespace shadowvol

// The sweep's machinery (issue 6): CSV columns and round trip, resume after an interruption, and
// the error metric on hand-made masks with known answers. No timing is asserted.
#include <algorithm>
#include <fstream>
#include <random>
#include <tuple>

#include <gtest/gtest.h>

#include "shadowvol/bench/shadow_error.h"
#include "shadowvol/bench/sweep.h"
#include "shadowvol/error.h"
#include "test_util.h"

namespace shadowvol {
namespace {

SweepRow sampleRow() {
  SweepRow r;
  r.scene = "sweep-000500";
  r.triangles = 486;
  r.method = "hybrid-perfect-blur/gpu";
  r.family = "hybrid";
  r.capture = "back";
  r.resolution = 256;
  r.width = 640;
  r.height = 480;
  r.timing = "wall-clock-glfinish";
  r.frames = 5;
  r.frame = {12.5, 11.25, 14.125};
  r.phases = {{"light", {1.5, 1.5, 1.5}}, {"volume", {7.25, 7.25, 7.25}}};
  r.volumeTriangles = 123456;
  r.volumeQuads = 65025;
  r.volumeQuadsDrawn = 3252;
  r.volumeCount = "z-pass";
  r.pixels = 1000;
  r.error = 0.0123;
  r.leak = 0.01;
  r.acne = 0.0023;
  r.bandPixels = 100;
  r.bandError = 0.123;
  r.bandLeak = 0.1;
  r.bandAcne = 0.023;
  r.distMean = 0.75;
  r.distP99 = 2.5;
  return r;
}

TEST(SweepCsv, HeaderAndRowHaveTheSameColumnsAndRoundTrip) {
  const SweepRow r = sampleRow();
  const std::string header = sweepCsvHeader(), line = toCsv(r);
  EXPECT_EQ(std::count(header.begin(), header.end(), ','), std::count(line.begin(), line.end(), ','));
  EXPECT_EQ(header.substr(0, 25), "scene,triangles,method,fa");
  for (const char* col : {"frame_ms", "light_ms", "volume_ms", "error", "leak", "acne", "band_error", "dist_p99"})
    EXPECT_NE(header.find(col), std::string::npos) << col;
  const SweepRow b = parseSweepRow(line, "test", 2);
  EXPECT_EQ(b.scene, r.scene);
  EXPECT_EQ(b.method, r.method);
  EXPECT_EQ(b.resolution, 256);
  EXPECT_DOUBLE_EQ(b.frame.median, 12.5);
  EXPECT_DOUBLE_EQ(b.frame.max, 14.125);
  ASSERT_EQ(b.phases.size(), 2u);
  EXPECT_EQ(b.phases[1].first, "volume");
  EXPECT_DOUBLE_EQ(b.error, 0.0123);
  EXPECT_DOUBLE_EQ(*b.distP99, 2.5);
  EXPECT_FALSE(b.distMax.has_value());  // empty field = not applicable
  EXPECT_EQ(b.volumeQuads, 65025u);
  EXPECT_EQ(b.volumeQuadsDrawn, 3252u);
  EXPECT_EQ(b.volumeCount, r.volumeCount);
  EXPECT_EQ(cellKey(b), cellKey(r));
}

// Results of earlier versions still read: without the volume_quads columns (docs/results/main:
// 0 quads) and without volume_count (empty).
TEST(SweepCsv, ResultsOfEarlierVersionsStillRead) {
  const auto dir = test::tempDir();
  const auto csv = dir / "results.csv";
  // Version 3: no list_ms column; versions 0-2 no crossings_ms either; 2 without the last column
  // of 3, 1 and 0 without more.
  auto splitCsvLine = [](const std::string& line) {  // the sample has no quoted field
    std::vector<std::string> f(1);
    for (char c : line)
      if (c == ',') f.emplace_back();
      else f.back() += c;
    return f;
  };
  const std::vector<std::string> header = splitCsvLine(sweepCsvHeader());
  const auto columnOf = [&](const char* name) {
    return std::size_t(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::size_t crossings = columnOf("crossings_ms"), list = columnOf("list_ms");
  ASSERT_LT(crossings, header.size());
  ASSERT_EQ(list, crossings + 1);
  auto olderVersion = [&](const std::string& line, bool withCrossings, int dropped) {
    std::vector<std::string> f = splitCsvLine(line);
    f.erase(f.begin() + std::ptrdiff_t(list));
    if (!withCrossings) f.erase(f.begin() + std::ptrdiff_t(crossings));
    f.resize(f.size() - std::size_t(dropped));
    std::string out;
    for (const auto& x : f) out += (out.empty() ? "" : ",") + x;
    return out;
  };
  const auto hasPhase = [](const SweepRow& r, const char* name) {
    return std::any_of(r.phases.begin(), r.phases.end(), [&](const auto& p) { return p.first == name; });
  };
  SweepRow sample = sampleRow();
  sample.volumeCount = "z-pass";
  sample.phases.push_back({"crossings", TimeStat{2.5, 2.5, 2.5}});
  sample.phases.push_back({"list", TimeStat{1.5, 1.5, 1.5}});
  test::writeText(csv, sweepCsvHeader() + "\n" + toCsv(sample) + "\n");
  const auto now = readSweepCsv(csv);
  ASSERT_EQ(now.size(), 1u);
  EXPECT_EQ(now[0].volumeCount, "z-pass");
  EXPECT_TRUE(hasPhase(now[0], "crossings"));
  EXPECT_TRUE(hasPhase(now[0], "list"));
  test::writeText(csv, olderVersion(sweepCsvHeader(), true, 0) + "\n" + olderVersion(toCsv(sample), true, 0) + "\n");
  const auto three = readSweepCsv(csv);
  ASSERT_EQ(three.size(), 1u);
  EXPECT_TRUE(hasPhase(three[0], "crossings"));
  EXPECT_FALSE(hasPhase(three[0], "list"));
  for (int dropped : {0, 1, 3}) {
    SCOPED_TRACE(dropped);
    test::writeText(csv, olderVersion(sweepCsvHeader(), false, dropped) + "\n" +
                             olderVersion(toCsv(sample), false, dropped) + "\n");
    const auto rows = readSweepCsv(csv);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].volumeTriangles, 123456u);
    EXPECT_EQ(rows[0].volumeQuads, dropped <= 1 ? 65025u : 0u);
    EXPECT_EQ(rows[0].volumeCount, dropped == 0 ? "z-pass" : "");
    EXPECT_FALSE(hasPhase(rows[0], "crossings"));
    EXPECT_FALSE(hasPhase(rows[0], "list"));
  }
  EXPECT_EQ(readSweepCsv(test::sourceDir() / "docs/results/main/results.csv").empty(), false);
}

TEST(SweepCsv, InterruptedLastLineIsIgnoredAndBadFilesAreNamed) {
  const auto dir = test::tempDir();
  const auto csv = dir / "results.csv";
  const std::string row = toCsv(sampleRow());
  test::writeText(csv, sweepCsvHeader() + "\n" + row + "\n" + row.substr(0, row.size() / 2));
  EXPECT_EQ(readSweepCsv(csv).size(), 1u);
  test::writeText(csv, "a,b,c\n");
  EXPECT_THROW(readSweepCsv(csv), InputError);
  test::writeText(csv, sweepCsvHeader() + "\nx,notanumber" + row.substr(row.find(',', row.find(',') + 1)) + "\n");
  try {
    readSweepCsv(csv);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("triangles"), std::string::npos) << e.what();
  }
}

// Regression (a hostile-input probe): a row whose times were "nan" was read into the report.
TEST(SweepCsv, NonFiniteOrNegativeNumbersAreRefusedWithLineAndColumn) {
  const auto dir = test::tempDir();
  const auto csv = dir / "results.csv";
  SweepRow r = sampleRow();
  const std::string good = toCsv(r);
  const std::string median = "12.5";  // sampleRow's frame median, the first real column
  ASSERT_NE(good.find("," + median + ","), std::string::npos);
  for (const char* bad : {"nan", "inf", "-1"}) {
    std::string row = good;
    row.replace(row.find("," + median + ",") + 1, median.size(), bad);
    test::writeText(csv, sweepCsvHeader() + "\n" + row + "\n");
    try {
      readSweepCsv(csv);
      FAIL() << bad;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("line 2"), std::string::npos) << what;
      EXPECT_NE(what.find("frame_ms"), std::string::npos) << what;
      EXPECT_NE(what.find(bad), std::string::npos) << what;
    }
  }
}

// A second probe's findings: whole numbers wrapped in their fields (a resolution of 4294967360
// read as 64, -3 pixels as 2^64 - 3), a NUL byte cut the message short, a folder or an empty file
// gave no clear refusal.
TEST(SweepCsv, WholeNumbersOutOfRangeControlBytesFoldersAndEmptyFilesAreRefused) {
  const auto dir = test::tempDir();
  const auto csv = dir / "results.csv";
  const std::string good = toCsv(sampleRow());
  ASSERT_NE(good.find(",256,640,480,"), std::string::npos);
  auto refusal = [&](const std::string& row) -> std::string {
    test::writeText(csv, sweepCsvHeader() + "\n" + row + "\n");
    try {
      readSweepCsv(csv);
    } catch (const InputError& e) {
      return e.what();
    }
    return "accepted";
  };
  for (const auto& [from, to, column] :
       {std::tuple{",256,640,480,", ",4294967360,640,480,", "resolution"}, {",256,640,480,", ",256,-640,480,", "width"},
        {",1000,", ",-3,", "pixels"}, {",123456,", ",-1,", "volume_triangles"}}) {
    std::string row = good;
    row.replace(row.find(from), std::string(from).size(), to);
    const std::string what = refusal(row);
    EXPECT_NE(what.find("line 2"), std::string::npos) << what;
    EXPECT_NE(what.find(column), std::string::npos) << what;
    EXPECT_NE(what.find("expected a whole number in"), std::string::npos) << what;
  }
  std::string nul = good;
  nul.replace(nul.find(",12.5,") + 1, 4, std::string("1\0" "5", 3));
  const std::string what = refusal(nul);
  EXPECT_NE(what.find("\\x00"), std::string::npos) << what;
  EXPECT_NE(what.find("expected a number"), std::string::npos) << what;
  test::writeText(csv, "");
  EXPECT_THROW(readSweepCsv(csv), InputError);
  test::writeText(csv, sweepCsvHeader());  // the header alone, without its line end: read, no rows
  EXPECT_TRUE(readSweepCsv(csv).empty());
  std::filesystem::remove(csv);
  std::filesystem::create_directory(csv);
  try {
    readSweepCsv(csv);
    FAIL() << "a folder was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
  }
}

TEST(ShadowErrorMetric, HandMadeMasksWithKnownAnswers) {
  // 20 x 10 pixels, all facing the light; exact shadow in columns 0..9, the test's in 0..11:
  // 20 acne pixels in columns 10 and 11, at 0.5 and 1.5 pixels from the boundary.
  const int w = 20, h = 10;
  std::vector<PixelClass> exact(w * h);
  std::vector<std::uint8_t> test(w * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      exact[y * w + x] = x < 10 ? PixelClass::Shadowed : PixelClass::Lit;
      test[y * w + x] = x < 12;
    }
  ShadowErrorMetrics m = measureShadowError(w, h, exact, test, 3.0);
  EXPECT_EQ(m.pixels, 200u);
  EXPECT_EQ(m.acne, 20u);
  EXPECT_EQ(m.leak, 0u);
  EXPECT_EQ(m.bandPixels, 60u);  // columns 7..12 lie within 3 pixels of the boundary
  EXPECT_EQ(m.bandAcne, 20u);
  EXPECT_DOUBLE_EQ(*m.distMean, 1.0);
  EXPECT_DOUBLE_EQ(*m.distMax, 1.5);
  EXPECT_DOUBLE_EQ(*m.distP99, 1.5);
  // Pixels that do not face the light are not compared; a leak far from the boundary counts too.
  exact[0] = PixelClass::FacingAway;
  exact[1] = PixelClass::Background;
  test = std::vector<std::uint8_t>(w * h, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < 10; ++x) test[y * w + x] = 1;
  test[5 * w + 2] = 0;  // one leak; nearest lit pixel 8 columns away: 8 - 0.5 = 7.5 from the boundary
  m = measureShadowError(w, h, exact, test, 3.0);
  EXPECT_EQ(m.pixels, 198u);
  EXPECT_EQ(m.leak, 1u);
  EXPECT_EQ(m.acne, 0u);
  EXPECT_DOUBLE_EQ(*m.distMax, 7.5);
  // No shadow at all: no boundary, no distances.
  std::fill(exact.begin(), exact.end(), PixelClass::Lit);
  m = measureShadowError(w, h, exact, test, 3.0);
  EXPECT_EQ(m.bandPixels, 0u);
  EXPECT_FALSE(m.distMean.has_value());
}

TEST(ShadowErrorMetric, DistanceTransformMatchesBruteForce) {
  std::mt19937 rng(7);
  const int w = 23, h = 17;
  std::vector<std::uint8_t> site(w * h);
  for (auto& s : site) s = rng() % 11 == 0;
  const auto d = squaredDistanceTransform(w, h, site);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double best = INFINITY;
      for (int v = 0; v < h; ++v)
        for (int u = 0; u < w; ++u)
          if (site[v * w + u]) best = std::min(best, double((u - x) * (u - x) + (v - y) * (v - y)));
      ASSERT_DOUBLE_EQ(d[y * w + x], best) << x << "," << y;
    }
}

// Both light fits in one run: the view-fitted cells name their scene "<scene>@view"; a method
// without a depth map is measured once.
// A one-frame sweep of `methods` at 64² over `scenes` into `dir`, image w x h, both light fits.
SweepOptions quickSweep(std::vector<std::filesystem::path> scenes, std::vector<std::string> methods, int w, int h,
                        const std::filesystem::path& dir) {
  SweepOptions o;
  o.scenes = std::move(scenes);
  o.methods = std::move(methods);
  o.resolutions = {64};
  o.width = w;
  o.height = h;
  o.repeat = 1;
  o.warmup = 0;
  o.out = dir;
  o.fits = {LightFit::Scene, LightFit::View};
  return o;
}

// Regressions (a hostile-input probe): two scene files of one name were merged (and a resumed
// sweep took one's rows for the other's), a name with a comma failed after the scenes before it
// were measured, a repeated resolution was measured twice. Now refused, or merged, before any cell.
TEST(Sweep, SceneNamesAreCheckedBeforeAnythingIsMeasured) {
  const auto dir = test::tempDir();
  const auto other = dir / "elsewhere";
  std::filesystem::create_directories(other);
  std::filesystem::copy_file(test::sourceDir() / "data/scenes/plate.json", other / "default.json");
  std::filesystem::copy_file(test::sourceDir() / "data/scenes/plate.json", other / "a,b.json");
  std::filesystem::copy_file(test::sourceDir() / "data/scenes/plate.json", other / "a\"b.json");
  gl::Renderer renderer;
  const std::atomic<bool> stop{false};
  std::vector<std::string> notes;
  auto refusal = [&](std::vector<std::filesystem::path> scenes) -> std::string {
    try {
      runSweep(renderer, quickSweep(std::move(scenes), {"shadowmap"}, 32, 24, dir / "out"), stop, nullptr, notes);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  const auto plate = test::sourceDir() / "data/scenes/plate.json";
  EXPECT_NE(refusal({std::filesystem::path(), other / "default.json"}).find("the built-in scene"), std::string::npos);
  EXPECT_NE(refusal({plate, plate}).find("given twice"), std::string::npos);
  EXPECT_NE(refusal({plate, other / "a,b.json"}).find("a comma"), std::string::npos);
  EXPECT_NE(refusal({plate, other / "a\"b.json"}).find("a double quote"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));  // nothing measured, nothing written
  SweepOptions o = quickSweep({plate}, {"shadowmap"}, 32, 24, dir / "once");
  o.fits = {LightFit::Scene};
  o.resolutions = {32, 32};
  EXPECT_EQ(runSweep(renderer, o, stop, nullptr, notes).size(), 1u);
  // A method without a depth map under --fit view alone measures nothing: said (a second probe
  // found an empty sweep without a word).
  notes.clear();
  SweepOptions view = quickSweep({plate}, {"silhouette"}, 32, 24, dir / "view");
  view.fits = {LightFit::View};
  EXPECT_TRUE(runSweep(renderer, view, stop, nullptr, notes).empty());
  ASSERT_FALSE(notes.empty());
  EXPECT_NE(notes[0].find("silhouette: no view-fitted cells"), std::string::npos) << notes[0];
}

TEST(SweepCsv, ASecondRowForACellIsRefused) {
  const auto dir = test::tempDir();
  const std::string row = toCsv(sampleRow());
  test::writeText(dir / "results.csv", sweepCsvHeader() + "\n" + row + "\n" + row + "\n");
  try {
    readSweepCsv(dir / "results.csv");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cell of line 2"), std::string::npos) << e.what();
  }
}

TEST(Sweep, BothLightFitsSideBySide) {
  const auto dir = test::tempDir();
  gl::Renderer renderer;
  const SweepOptions o = quickSweep({std::filesystem::path(SV_SOURCE_DIR) / "data/scenes/tree-wide-ground.json"},
                                    {"shadowmap", "silhouette"}, 64, 48, dir);
  std::atomic<bool> stop{false};
  std::vector<std::string> notes;
  const auto rows = runSweep(renderer, o, stop, nullptr, notes);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].scene, "tree-wide-ground");
  EXPECT_EQ(rows[1].scene, "tree-wide-ground");
  EXPECT_EQ(rows[1].method, "silhouette");
  EXPECT_EQ(rows[2].scene, std::string("tree-wide-ground") + kViewFitSuffix);
  EXPECT_EQ(rows[2].method, "shadowmap");
  EXPECT_EQ(rows[0].pixels, rows[2].pixels);  // the same receivers are compared
}

// A point-light scene beside a spot-light one: each gets the methods for its kind of light (the
// cube methods at the face resolution), silhouette volumes both, and the view fit none of the
// point light's cells. Every method misclassifies under 5 % of the pixels: a wrong face order or
// a missing face would get a sixth of the room wrong.
TEST(Sweep, PointLightScenesGetTheCubeMethods) {
  const auto dir = test::tempDir();
  gl::Renderer renderer;
  const SweepOptions o =
      quickSweep({std::filesystem::path(), std::filesystem::path(SV_SOURCE_DIR) / "data/scenes/point/room.json"},
                 {"shadowmap", "cube-shadowmap", "cube-pcf3", "dpsm", "hybrid-cube/explicit", "hybrid-cube/gpu", "silhouette"},
                 80, 60, dir);
  std::atomic<bool> stop{false};
  std::vector<std::string> notes;
  const auto rows = runSweep(renderer, o, stop, nullptr, notes);
  std::vector<std::string> cells;
  for (const auto& r : rows) cells.push_back(r.scene + " " + r.method);
  const std::vector<std::string> expected = {"default shadowmap",         "default silhouette",
                                             "default@view shadowmap",    "room cube-shadowmap",
                                             "room cube-pcf3",            "room dpsm",
                                             "room hybrid-cube/explicit", "room hybrid-cube/gpu",
                                             "room silhouette"};
  EXPECT_EQ(cells, expected);
  for (const auto& r : rows) {
    EXPECT_GT(r.pixels, 0u) << r.method;
    EXPECT_LT(r.error, 0.05) << r.scene << " " << r.method;
  }
  for (const char* note : {"default: 5 of the methods are for point lights", "room: 1 of the methods are for spot",
                           "room: no view-fitted cells"})
    EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [&](const std::string& n) { return n.rfind(note, 0) == 0; }))
        << note << " in " << ::testing::PrintToString(notes);
}

// A cell that its method refuses (the refined GPU volume past 2048^2 texels) is skipped with a
// note naming it; the sweep measures the others. Before, the refusal ended the whole sweep.
TEST(Sweep, RefusedCellsAreSkippedWithANote) {
  const auto dir = test::tempDir();
  gl::Renderer renderer;
  SweepOptions o = quickSweep({std::filesystem::path()}, {"hybrid-refined/gpu"}, 64, 48, dir);  // the default scene
  o.resolutions = {2056, 32};
  o.fits = {LightFit::Scene};
  std::atomic<bool> stop{false};
  std::vector<std::string> notes;
  SweepProgress last;
  const auto rows = runSweep(renderer, o, stop, [&](const SweepProgress& p) { last = p; }, notes);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].resolution, 32);
  EXPECT_EQ(last.done, 2u);
  EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& n) {
    return n.rfind("default | hybrid-refined/gpu | 2056 skipped: ", 0) == 0 && n.find("2048") != std::string::npos;
  })) << ::testing::PrintToString(notes);
}

// The refined explicit volume with its depth map ray-cast: the sweep attaches the scene's oracle
// (the cell is measured, not refused), the frame has a light pass (the rays) and no read-back, and
// the error is the light-pass key's within a few pixels (the two maps differ only where the GPU's
// rasteriser and Embree's rays split a texel centre on an edge).
TEST(Sweep, RayCastDepthMethodHasNoReadBack) {
  const auto dir = test::tempDir();
  gl::Renderer renderer;
  SweepOptions o = quickSweep({std::filesystem::path()},
                              {"hybrid-refined-lightpass/explicit", "hybrid-refined-raycast/explicit"}, 64, 48, dir);
  o.fits = {LightFit::Scene};
  std::atomic<bool> stop{false};
  std::vector<std::string> notes;
  const auto rows = runSweep(renderer, o, stop, [](const SweepProgress&) {}, notes);
  ASSERT_EQ(rows.size(), 2u) << ::testing::PrintToString(notes);
  const auto phase = [](const SweepRow& r, const std::string& name) {
    return std::any_of(r.phases.begin(), r.phases.end(), [&](const auto& p) { return p.first == name; });
  };
  const SweepRow& gpu = rows[0].method == "hybrid-refined-lightpass/explicit" ? rows[0] : rows[1];
  const SweepRow& rays = rows[0].method == "hybrid-refined-lightpass/explicit" ? rows[1] : rows[0];
  EXPECT_EQ(rays.method, "hybrid-refined-raycast/explicit");
  EXPECT_TRUE(phase(gpu, "readback"));
  EXPECT_TRUE(phase(rays, "light"));
  EXPECT_FALSE(phase(rays, "readback"));
  EXPECT_TRUE(phase(rays, "build"));
  EXPECT_EQ(rays.pixels, gpu.pixels);
  EXPECT_NEAR(rays.error * double(rays.pixels), gpu.error * double(gpu.pixels), 8.0);
}

TEST(Sweep, ResumesWithoutRedoingFinishedCells) {
  const auto dir = test::tempDir();
  gl::Renderer renderer;
  SweepOptions o;
  o.scenes = {std::filesystem::path()};  // the built-in default scene
  o.methods = {"shadowmap", "hybrid-fixed/gpu", "silhouette"};
  o.resolutions = {16, 32};
  o.width = 64;
  o.height = 48;
  o.repeat = 1;
  o.warmup = 0;
  o.out = dir;
  std::atomic<bool> stop{false};
  std::vector<std::string> notes;
  SweepProgress last;
  auto rows = runSweep(renderer, o, stop, [&](const SweepProgress& p) { last = p; }, notes);
  ASSERT_EQ(rows.size(), 5u);  // 2 resolutions x 2 methods + silhouette once
  EXPECT_EQ(last.done, 5u);
  EXPECT_EQ(last.skipped, 0u);
  for (const auto& r : rows) {
    EXPECT_EQ(r.frames, 1);
    EXPECT_GT(r.pixels, 0u);
    EXPECT_GE(r.error, 0.0);
    EXPECT_LE(r.error, 1.0);
  }
  // Simulate an interruption in the middle of the last row, then run the same sweep again.
  const auto csv = dir / "results.csv";
  std::ifstream in(csv);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  text.resize(text.rfind('\n', text.size() - 2) + 1 + 10);  // keep 10 characters of the last row
  test::writeText(csv, text);
  rows = runSweep(renderer, o, stop, [&](const SweepProgress& p) { last = p; }, notes);
  EXPECT_EQ(rows.size(), 5u);
  EXPECT_EQ(last.skipped, 4u);  // only the interrupted cell was measured again
  EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& n) {
    return n.rfind("resumed: 4 of 5 cells were already in ", 0) == 0;
  })) << ::testing::PrintToString(notes);
  EXPECT_EQ(readSweepCsv(csv).size(), 5u);
  // Regression: a run killed while creating results.csv left it empty, and every later run failed
  // ("not a shadowvol sweep file"); an empty file now starts afresh.
  const auto dir3 = dir / "empty";
  std::filesystem::create_directories(dir3);
  test::writeText(dir3 / "results.csv", "");
  SweepOptions one = o;
  one.out = dir3;
  one.methods = {"shadowmap"};
  one.resolutions = {16};
  EXPECT_EQ(runSweep(renderer, one, stop, nullptr, notes).size(), 1u);
  EXPECT_EQ(readSweepCsv(dir3 / "results.csv").size(), 1u);
  // Regression: the header alone without its line end was dropped as an incomplete line, and the
  // rows appended after it made a file that no longer read back.
  test::writeText(dir3 / "results.csv", sweepCsvHeader());
  EXPECT_EQ(runSweep(renderer, one, stop, nullptr, notes).size(), 1u);
  EXPECT_EQ(readSweepCsv(dir3 / "results.csv").size(), 1u);
  // A stop request before the first cell measures nothing.
  stop = true;
  const auto dir2 = dir / "stopped";
  o.out = dir2;
  EXPECT_TRUE(runSweep(renderer, o, stop, nullptr, notes).empty());
  // Unknown methods are named.
  stop = false;
  o.methods = {"laser"};
  EXPECT_THROW(runSweep(renderer, o, stop, nullptr, notes), InputError);
}

}  // namespace
}  // namespace shadowvol

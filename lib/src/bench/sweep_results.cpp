#include "shadowvol/bench/sweep_results.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "shadowvol/depth_map.h"
#include "shadowvol/error.h"

namespace shadowvol {
namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == ',') {
      out.push_back(cur);
      cur.clear();
    } else if (c != '\r') {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

// The phases a file of `version` has a column for: the crossings pass (the refined GPU volume)
// from version 3 on, the list pass (the GPU cube volume's) from version 4.
bool phaseIn(const std::string& phase, int version) {
  if (phase == "crossings") return version >= 3;
  if (phase == "list") return version >= 4;
  return true;
}

// The columns of each version of the file, all still read: 0 before the GPU volume reported its
// quads (docs/results/main), 1 before the stencil count (z-pass or z-fail) was recorded, 2 before
// the crossings pass, 3 before the list pass, 4 now.
std::vector<std::string> columns(int version = kSweepCsvVersion) {
  std::vector<std::string> c = {"scene", "triangles", "method", "family", "capture", "resolution", "width", "height",
                                "timing", "frames", "frame_ms", "frame_ms_min", "frame_ms_max"};
  for (const auto& p : sweepPhases())
    if (phaseIn(p, version)) c.push_back(p + "_ms");
  for (const char* s : {"volume_triangles", "pixels", "error", "leak", "acne", "band_pixels", "band_error",
                        "band_leak", "band_acne", "dist_mean", "dist_p99", "dist_max"})
    c.push_back(s);
  if (version >= 1)
    for (const char* s : {"volume_quads", "volume_quads_drawn"}) c.push_back(s);
  if (version >= 2) c.push_back("volume_count");
  return c;
}

std::string headerOf(const std::vector<std::string>& cols) {
  std::string h;
  for (const auto& c : cols) h += (h.empty() ? "" : ",") + c;
  return h;
}

}  // namespace

const std::vector<std::string>& sweepPhases() {
  static const std::vector<std::string> p = {"light",  "resolve", "blur",   "crossings", "list",
                                             "readback", "build", "upload", "camera",    "volume",
                                             "lighting", "shade", "silhouette"};
  return p;
}

std::string sweepCsvHeader() { return headerOf(columns()); }

std::string toCsv(const SweepRow& r) {
  std::vector<std::string> f = {r.scene,
                                std::to_string(r.triangles),
                                r.method,
                                r.family,
                                r.capture,
                                std::to_string(r.resolution),
                                std::to_string(r.width),
                                std::to_string(r.height),
                                r.timing,
                                std::to_string(r.frames),
                                num(r.frame.median),
                                num(r.frame.min),
                                num(r.frame.max)};
  for (const auto& name : sweepPhases()) {
    std::string v;
    for (const auto& [n, t] : r.phases)
      if (n == name) v = num(t.median);
    f.push_back(v);
  }
  f.push_back(std::to_string(r.volumeTriangles));
  f.push_back(std::to_string(r.pixels));
  f.push_back(num(r.error));
  f.push_back(num(r.leak));
  f.push_back(num(r.acne));
  f.push_back(std::to_string(r.bandPixels));
  f.push_back(num(r.bandError));
  f.push_back(num(r.bandLeak));
  f.push_back(num(r.bandAcne));
  f.push_back(r.distMean ? num(*r.distMean) : "");
  f.push_back(r.distP99 ? num(*r.distP99) : "");
  f.push_back(r.distMax ? num(*r.distMax) : "");
  f.push_back(std::to_string(r.volumeQuads));
  f.push_back(std::to_string(r.volumeQuadsDrawn));
  f.push_back(r.volumeCount);
  std::string line;
  for (std::size_t k = 0; k < f.size(); ++k) {
    for (char c : f[k])
      if (c == ',' || c == '\n') throw InputError("results.csv", columns()[k], f[k], "a field may not hold ',' or a newline");
    line += (k ? "," : "") + f[k];
  }
  return line;
}

// A field as a message shows it: control bytes (a NUL cut the message short) as \xNN.
std::string shown(const std::string& field) {
  std::string out;
  for (const char c : field) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", unsigned(static_cast<unsigned char>(c)));
      out += buf;
    } else {
      out += c;
    }
  }
  return out;
}

SweepRow parseSweepRow(const std::string& line, const std::string& source, std::size_t lineNumber, int version) {
  const auto f = split(line);
  const auto cols = columns(version);
  const std::string where = source + " line " + std::to_string(lineNumber);
  if (f.size() != cols.size())
    throw InputError(where, "", std::to_string(f.size()) + " fields", "expected " + std::to_string(cols.size()));
  std::size_t k = 0;
  auto text = [&]() { return f[k++]; };
  auto real = [&]() -> double {
    const std::string& s = f[k];
    double v = 0;
    const auto res = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || res.ec != std::errc() || res.ptr != s.data() + s.size())
      throw InputError(where, cols[k], shown(s), "expected a number");
    // Every real column is a time, a fraction or a distance: a NaN, an infinity or a negative
    // value is a damaged row, not a measurement.
    if (!std::isfinite(v) || v < 0.0) throw InputError(where, cols[k], shown(s), "expected a finite number >= 0");
    ++k;
    return v;
  };
  // A count, or a size within [lo, hi]: a value that would wrap in its field (a resolution of
  // 4294967360 read as 64, -3 pixels as 2^64 - 3) is a damaged row (a second probe's finding).
  auto whole = [&](long long lo = 0, long long hi = 1'000'000'000'000'000LL) -> long long {
    const std::string& s = f[k];
    long long v = 0;
    const auto res = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || res.ec != std::errc() || res.ptr != s.data() + s.size())
      throw InputError(where, cols[k], shown(s), "expected a whole number");
    if (v < lo || v > hi)
      throw InputError(where, cols[k], shown(s),
                       "expected a whole number in " + std::to_string(lo) + ".." + std::to_string(hi));
    ++k;
    return v;
  };
  auto maybe = [&]() -> std::optional<double> {
    if (f[k].empty()) {
      ++k;
      return std::nullopt;
    }
    return real();
  };
  SweepRow r;
  r.scene = text();
  r.triangles = std::size_t(whole());
  r.method = text();
  r.family = text();
  r.capture = text();
  r.resolution = int(whole(0, kMaxWindowSide));  // 0: silhouette volumes, which have no map
  r.width = int(whole(1, 1 << 20));
  r.height = int(whole(1, 1 << 20));
  r.timing = text();
  r.frames = int(whole(1, 1'000'000));
  r.frame.median = real();
  r.frame.min = real();
  r.frame.max = real();
  for (const auto& name : sweepPhases()) {
    if (!phaseIn(name, version)) continue;
    const auto v = maybe();
    if (v) r.phases.push_back({name, TimeStat{*v, *v, *v}});
  }
  r.volumeTriangles = std::size_t(whole());
  r.pixels = std::size_t(whole());
  r.error = real();
  r.leak = real();
  r.acne = real();
  r.bandPixels = std::size_t(whole());
  r.bandError = real();
  r.bandLeak = real();
  r.bandAcne = real();
  r.distMean = maybe();
  r.distP99 = maybe();
  r.distMax = maybe();
  if (version >= 1) {
    r.volumeQuads = std::size_t(whole());
    r.volumeQuadsDrawn = std::size_t(whole());
  }
  if (version >= 2) r.volumeCount = text();
  return r;
}

std::vector<SweepRow> readSweepCsv(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw InputError(path.string(), "", "", "not a regular file (a folder?): the results file must be a CSV file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "", "", "cannot open the results file");
  std::ostringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  std::vector<SweepRow> rows;
  std::map<std::string, std::size_t> lines;  // cell key -> its line
  std::size_t pos = 0, lineNumber = 0;
  int version = kSweepCsvVersion;
  while (pos < text.size()) {
    const std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) break;  // an interrupted last line
    const std::string line = text.substr(pos, end - pos);
    pos = end + 1;
    ++lineNumber;
    if (lineNumber == 1) {
      version = -1;
      for (int v = 0; v <= kSweepCsvVersion; ++v)
        if (line == headerOf(columns(v))) version = v;
      if (version < 0)
        throw InputError(path.string(), "header", line.substr(0, 60), "not a shadowvol sweep file of this version");
      continue;
    }
    if (line.empty()) continue;
    rows.push_back(parseSweepRow(line, path.string(), lineNumber, version));
    // One row per cell: a second (a hand edit, or two scenes of one name before they were
    // refused) would be reported in the first's place.
    if (const auto [at, fresh] = lines.emplace(cellKey(rows.back()), lineNumber); !fresh)
      throw InputError(path.string() + " line " + std::to_string(lineNumber), "cell", cellKey(rows.back()),
                       "a second row for the cell of line " + std::to_string(at->second) + ": delete one");
  }
  // No complete line: the header alone without its line end (what a resume completes), else not
  // a sweep file at all (an empty file reported nothing without a word).
  if (lineNumber == 0) {
    bool header = false;
    for (int v = 0; v <= kSweepCsvVersion; ++v) header = header || text == headerOf(columns(v));
    if (!header)
      throw InputError(path.string(), "header", shown(text.substr(0, 60)),
                       text.empty() ? "the file is empty: not a shadowvol sweep file"
                                    : "not a shadowvol sweep file of this version");
  }
  return rows;
}

std::string cellKey(const SweepRow& r) {
  return r.scene + "|" + r.method + "|" + std::to_string(r.resolution) + "|" + std::to_string(r.width) + "x" +
         std::to_string(r.height);
}

}  // namespace shadowvol

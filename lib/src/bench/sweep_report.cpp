#include "shadowvol/bench/sweep_report.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "shadowvol/error.h"
#include "shadowvol/mesh_io.h"

namespace shadowvol {
namespace {

// ---------------------------------------------------------------------------------------------
// Text formatting. Every number goes through these, so non-finite values print as "n/a", never "nan".

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

/// Three significant digits, no exponent for ordinary magnitudes ("0.0123", "12.3", "1234").
std::string sig(double v) {
  if (!std::isfinite(v)) return "n/a";
  if (std::abs(v) >= 1000) return fmt("%.0f", v);
  return fmt("%.3g", v);
}

std::string pct(double fraction) {
  return std::isfinite(fraction) ? sig(100.0 * fraction) : "n/a";
}
std::string px(const std::optional<double>& v) {
  return v ? sig(*v) : "-";
}
std::string resLabel(int r) {
  return r > 0 ? std::to_string(r) : "no map";
}

std::string mdEscape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '|') o += '\\';
    o += c;
  }
  return o;
}

std::string xmlEscape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&':
        o += "&amp;";
        break;
      case '<':
        o += "&lt;";
        break;
      case '>':
        o += "&gt;";
        break;
      case '"':
        o += "&quot;";
        break;
      default:
        o += c;
    }
  }
  return o;
}

/// A file name from a scene name: keeps [A-Za-z0-9._-], replaces the rest by '_'.
std::string fileStem(const std::string& s) {
  std::string o;
  for (char c : s) {
    const bool ok =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
    o += ok ? c : '_';
  }
  return o.empty() || o[0] == '.' ? "_" + o : o;
}

std::string sizeLabel(int w, int h) {
  return std::to_string(w) + "x" + std::to_string(h);
}

// ---------------------------------------------------------------------------------------------
// Rows grouped by scene and image size.

struct Group {
  std::string scene;
  int width = 0, height = 0;
  std::size_t triangles = 0;
  std::vector<const SweepRow*> rows;
  std::string plotFile;  ///< file name under plots/
};

bool plottable(const SweepRow& r) {
  return std::isfinite(r.frame.median) && r.frame.median > 0 && std::isfinite(r.error);
}

const SweepRow* findRow(const Group& g, const std::string& method, int res) {
  for (const SweepRow* r : g.rows)
    if (r->method == method && r->resolution == res) return r;
  return nullptr;
}

std::vector<int> resolutionsOf(const std::vector<const SweepRow*>& rows) {
  std::set<int> s;
  for (const SweepRow* r : rows) s.insert(r->resolution);
  return {s.begin(), s.end()};
}

std::vector<std::string> methodsOf(const std::vector<const SweepRow*>& rows, const std::vector<std::string>& order) {
  std::vector<std::string> out;
  for (const auto& m : order)
    if (std::any_of(rows.begin(), rows.end(), [&](const SweepRow* r) { return r->method == m; })) out.push_back(m);
  return out;
}

/// The row among `rows` with the lowest error (ties: lower time); nullptr when none has a finite error.
const SweepRow* lowestError(const std::vector<const SweepRow*>& rows) {
  const SweepRow* best = nullptr;
  for (const SweepRow* r : rows) {
    if (!std::isfinite(r->error)) continue;
    if (!best || r->error < best->error || (r->error == best->error && r->frame.median < best->frame.median)) best = r;
  }
  return best;
}

/// Resolution for the per-phase and polygon-sweep tables: 256 when present, else the smallest map.
int referenceResolution(const std::vector<int>& resolutions) {
  if (std::count(resolutions.begin(), resolutions.end(), 256)) return 256;
  for (int r : resolutions)
    if (r > 0) return r;
  return resolutions.empty() ? 0 : resolutions.front();
}

// ---------------------------------------------------------------------------------------------
// SVG plots with log axes.

constexpr std::array<const char*, 8> kColours = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                                 "#E69F00", "#56B4E9", "#000000", "#8C564B"};
constexpr std::array<const char*, 3> kDashes = {"", "7,3", "2,2"};

struct Series {
  std::string name;
  int style = 0;                              ///< colour = style % 8, dash and marker = style / 8
  std::vector<std::array<double, 2>> pts;     ///< data coordinates, all positive and finite
  std::vector<std::string> labels;            ///< one per point, may be empty strings
  std::vector<std::array<double, 2>> xRange;  ///< per point: whisker from x min to x max (empty: none)
};

struct PlotSpec {
  std::string title, xLabel, yLabel;
  std::vector<Series> series;
  std::vector<std::array<double, 2>> front;  ///< Pareto front, sorted by x; empty = none
  std::optional<double> zeroLine;            ///< y where zero values are drawn (marked by a dotted line)
};

struct LogAxis {
  double lo = 0, hi = 1;  ///< log10 of the range ends

  static LogAxis fit(const std::vector<double>& values) {
    double a = HUGE_VAL, b = -HUGE_VAL;
    for (double v : values) {
      a = std::min(a, std::log10(v));
      b = std::max(b, std::log10(v));
    }
    if (values.empty()) a = 0, b = 1;
    if (b - a < 1e-9) a -= 0.5, b += 0.5;
    const double pad = 0.05 * (b - a);
    return {a - pad, b + pad};
  }
  /// Maps v to [p0, p1] (pixels).
  double map(double v, double p0, double p1) const { return p0 + (std::log10(v) - lo) / (hi - lo) * (p1 - p0); }
};

struct Tick {
  double v;
  bool major, labelled;
};

std::string tickText(double v) {
  const int k = int(std::floor(std::log10(v) + 1e-9));
  if (k < -3 || k > 5) return fmt("%g", std::round(v / std::pow(10.0, k) * 100) / 100) + "e" + std::to_string(k);
  return fmt("%g", v);
}

std::vector<Tick> ticks(const LogAxis& ax) {
  const double span = ax.hi - ax.lo;
  const int k0 = int(std::floor(ax.lo)), k1 = int(std::ceil(ax.hi));
  int decades = 0;
  for (int k = k0; k <= k1; ++k) decades += (k >= ax.lo && k <= ax.hi);
  const int step = decades > 10 ? 2 : 1;  // label every other decade on very long axes
  std::vector<Tick> t;
  for (int k = k0; k <= k1; ++k)
    for (int m = 1; m <= 9; ++m) {
      if (m > 1 && span > 6) continue;
      const double v = m * std::pow(10.0, k);
      const double l = std::log10(v);
      if (l < ax.lo || l > ax.hi) continue;
      const bool labelled = m == 1 ? (k % step == 0) : (decades < 2 && (m == 2 || m == 5 || span < 0.5));
      t.push_back({v, m == 1, labelled});
    }
  if (std::count_if(t.begin(), t.end(), [](const Tick& x) { return x.labelled; }) < 2) {
    // A very short range: label its ends.
    t.push_back({std::pow(10.0, ax.lo), false, true});
    t.push_back({std::pow(10.0, ax.hi), false, true});
  }
  return t;
}

std::string num1(double v) {
  return fmt("%.1f", v);
}

void marker(std::ostringstream& o, int shape, double x, double y, const char* colour, double size) {
  if (shape == 0) {
    o << "<circle cx=\"" << num1(x) << "\" cy=\"" << num1(y) << "\" r=\"" << num1(size) << "\" fill=\"" << colour
      << "\"/>\n";
  } else if (shape == 1) {
    o << "<rect x=\"" << num1(x - size) << "\" y=\"" << num1(y - size) << "\" width=\"" << num1(2 * size)
      << "\" height=\"" << num1(2 * size) << "\" fill=\"" << colour << "\"/>\n";
  } else {
    const double s = size * 1.25;
    o << "<polygon points=\"" << num1(x) << "," << num1(y - s) << " " << num1(x + s) << "," << num1(y + 0.8 * s) << " "
      << num1(x - s) << "," << num1(y + 0.8 * s) << "\" fill=\"" << colour << "\"/>\n";
  }
}

// The plot's frame: its size, the plot area's corners and the log axes fitted to what it shows.
struct PlotFrame {
  static constexpr double W = 980, H = 640, X0 = 80, X1 = 700, Y0 = 50, Y1 = 560;
  LogAxis ax, ay;
  explicit PlotFrame(const PlotSpec& spec) {
    std::vector<double> xs, ys;
    for (const auto& s : spec.series) {
      for (const auto& p : s.pts) xs.push_back(p[0]), ys.push_back(p[1]);
      for (const auto& r : s.xRange)
        for (double x : r)
          if (x > 0 && std::isfinite(x)) xs.push_back(x);
    }
    for (const auto& p : spec.front) xs.push_back(p[0]), ys.push_back(p[1]);
    ax = LogAxis::fit(xs);
    ay = LogAxis::fit(ys);
  }
  double X(double v) const { return ax.map(v, X0, X1); }
  double Y(double v) const { return ay.map(v, Y1, Y0); }
};

// Grid, ticks, tick labels, the plot area's box and the axis labels.
void svgAxes(std::ostringstream& o, const PlotFrame& f, const PlotSpec& spec) {
  constexpr double X0 = PlotFrame::X0, X1 = PlotFrame::X1, Y0 = PlotFrame::Y0, Y1 = PlotFrame::Y1;
  o << "<g stroke=\"#e4e4e4\" stroke-width=\"1\">\n";
  for (const Tick& t : ticks(f.ax))
    if (t.major || t.labelled)
      o << "<line x1=\"" << num1(f.X(t.v)) << "\" y1=\"" << Y0 << "\" x2=\"" << num1(f.X(t.v)) << "\" y2=\"" << Y1
        << "\"/>\n";
  for (const Tick& t : ticks(f.ay))
    if (t.major || t.labelled)
      o << "<line x1=\"" << X0 << "\" y1=\"" << num1(f.Y(t.v)) << "\" x2=\"" << X1 << "\" y2=\"" << num1(f.Y(t.v))
        << "\"/>\n";
  o << "</g>\n<g stroke=\"black\" stroke-width=\"1\">\n";
  for (const Tick& t : ticks(f.ax)) {
    const double len = t.major || t.labelled ? 6 : 3;
    o << "<line x1=\"" << num1(f.X(t.v)) << "\" y1=\"" << Y1 << "\" x2=\"" << num1(f.X(t.v)) << "\" y2=\""
      << num1(Y1 + len) << "\"/>\n";
  }
  for (const Tick& t : ticks(f.ay)) {
    const double len = t.major || t.labelled ? 6 : 3;
    o << "<line x1=\"" << num1(X0 - len) << "\" y1=\"" << num1(f.Y(t.v)) << "\" x2=\"" << X0 << "\" y2=\""
      << num1(f.Y(t.v)) << "\"/>\n";
  }
  o << "</g>\n";
  for (const Tick& t : ticks(f.ax))
    if (t.labelled)
      o << "<text x=\"" << num1(f.X(t.v)) << "\" y=\"" << num1(Y1 + 20) << "\" text-anchor=\"middle\">" << tickText(t.v)
        << "</text>\n";
  for (const Tick& t : ticks(f.ay))
    if (t.labelled)
      o << "<text x=\"" << num1(X0 - 9) << "\" y=\"" << num1(f.Y(t.v) + 4) << "\" text-anchor=\"end\">" << tickText(t.v)
        << "</text>\n";
  o << "<rect x=\"" << X0 << "\" y=\"" << Y0 << "\" width=\"" << X1 - X0 << "\" height=\"" << Y1 - Y0
    << "\" fill=\"none\" stroke=\"black\"/>\n";
  o << "<text x=\"" << num1((X0 + X1) / 2) << "\" y=\"" << num1(Y1 + 45) << "\" text-anchor=\"middle\">"
    << xmlEscape(spec.xLabel) << "</text>\n";
  o << "<text transform=\"translate(22," << num1((Y0 + Y1) / 2) << ") rotate(-90)\" text-anchor=\"middle\">"
    << xmlEscape(spec.yLabel) << "</text>\n";
  if (spec.zeroLine) {
    const double y = f.Y(*spec.zeroLine);
    o << "<line x1=\"" << X0 << "\" y1=\"" << num1(y) << "\" x2=\"" << X1 << "\" y2=\"" << num1(y)
      << "\" stroke=\"#888888\" stroke-dasharray=\"1,3\"/>\n";
    o << "<text x=\"" << num1(X0 + 4) << "\" y=\"" << num1(y + 12) << "\" font-size=\"10\" "
      << "fill=\"#666666\">zero error drawn here</text>\n";
  }
}

// The Pareto front: a thick grey step line (the best error for a time budget) and rings.
void svgFront(std::ostringstream& o, const PlotFrame& f, const std::vector<std::array<double, 2>>& front) {
  if (front.empty()) return;
  o << "<polyline class=\"front\" fill=\"none\" stroke=\"#c4c4c4\" stroke-width=\"8\" stroke-linejoin=\"round\" "
       "stroke-linecap=\"round\" points=\"";
  for (std::size_t i = 0; i < front.size(); ++i) {
    if (i > 0) o << num1(f.X(front[i][0])) << "," << num1(f.Y(front[i - 1][1])) << " ";
    o << num1(f.X(front[i][0])) << "," << num1(f.Y(front[i][1])) << " ";
  }
  o << "\"/>\n";
  for (const auto& p : front)
    o << "<circle cx=\"" << num1(f.X(p[0])) << "\" cy=\"" << num1(f.Y(p[1]))
      << "\" r=\"8\" fill=\"none\" stroke=\"#888888\" stroke-width=\"1.5\"/>\n";
}

// One series: its curve, min..max whiskers, markers and point labels.
void svgSeries(std::ostringstream& o, const PlotFrame& f, const Series& s) {
  const char* colour = kColours[std::size_t(s.style) % kColours.size()];
  const std::size_t kind = std::size_t(s.style) / kColours.size() % kDashes.size();
  if (s.pts.size() >= 2) {
    o << "<polyline class=\"curve\" fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"1.8\"";
    if (*kDashes[kind]) o << " stroke-dasharray=\"" << kDashes[kind] << "\"";
    o << " points=\"";
    for (const auto& p : s.pts) o << num1(f.X(p[0])) << "," << num1(f.Y(p[1])) << " ";
    o << "\"><title>" << xmlEscape(s.name) << "</title></polyline>\n";
  }
  for (std::size_t i = 0; i < s.pts.size(); ++i) {
    if (i < s.xRange.size() && s.xRange[i][1] > s.xRange[i][0]) {  // min..max whisker with end ticks
      const double y = f.Y(s.pts[i][1]), a = f.X(s.xRange[i][0]), b = f.X(s.xRange[i][1]);
      o << "<path class=\"whisker\" fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"1\" d=\"M" << num1(a)
        << "," << num1(y) << "H" << num1(b) << "M" << num1(a) << "," << num1(y - 3) << "V" << num1(y + 3) << "M"
        << num1(b) << "," << num1(y - 3) << "V" << num1(y + 3) << "\"/>\n";
    }
    marker(o, int(kind), f.X(s.pts[i][0]), f.Y(s.pts[i][1]), colour, s.pts.size() == 1 ? 4.5 : 3.0);
    if (i < s.labels.size() && !s.labels[i].empty())
      o << "<text x=\"" << num1(f.X(s.pts[i][0]) + 5) << "\" y=\"" << num1(f.Y(s.pts[i][1]) - 5)
        << "\" font-size=\"9\" fill=\"" << colour << "\">" << xmlEscape(s.labels[i]) << "</text>\n";
  }
}

// The legend, right of the plot: one entry per series, then the front's.
void svgLegend(std::ostringstream& o, const PlotSpec& spec) {
  const std::size_t entries = spec.series.size() + (spec.front.empty() ? 0 : 1);
  const double lh = std::min(18.0, (PlotFrame::Y1 - PlotFrame::Y0) / double(std::max<std::size_t>(entries, 1)));
  const double fs = std::min(12.0, lh - 2);
  const double lx = PlotFrame::X1 + 20;
  double ly = PlotFrame::Y0 + lh / 2;
  for (const auto& s : spec.series) {
    const char* colour = kColours[std::size_t(s.style) % kColours.size()];
    const std::size_t kind = std::size_t(s.style) / kColours.size() % kDashes.size();
    o << "<line x1=\"" << num1(lx) << "\" y1=\"" << num1(ly) << "\" x2=\"" << num1(lx + 28) << "\" y2=\"" << num1(ly)
      << "\" stroke=\"" << colour << "\" stroke-width=\"1.8\"";
    if (*kDashes[kind]) o << " stroke-dasharray=\"" << kDashes[kind] << "\"";
    o << "/>\n";
    marker(o, int(kind), lx + 14, ly, colour, 3.0);
    o << "<text x=\"" << num1(lx + 34) << "\" y=\"" << num1(ly + fs / 3) << "\" font-size=\"" << num1(fs) << "\">"
      << xmlEscape(s.name) << "</text>\n";
    ly += lh;
  }
  if (!spec.front.empty()) {
    o << "<line x1=\"" << num1(lx) << "\" y1=\"" << num1(ly) << "\" x2=\"" << num1(lx + 28) << "\" y2=\"" << num1(ly)
      << "\" stroke=\"#c4c4c4\" stroke-width=\"8\" stroke-linecap=\"round\"/>\n";
    o << "<text x=\"" << num1(lx + 34) << "\" y=\"" << num1(ly + fs / 3) << "\" font-size=\"" << num1(fs)
      << "\">Pareto front (ringed points)</text>\n";
  }
}

std::string svgPlot(const PlotSpec& spec) {
  const PlotFrame f(spec);
  constexpr double W = PlotFrame::W, H = PlotFrame::H;
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << W << "\" height=\"" << H
    << "\" viewBox=\"0 0 " << W << " " << H << "\" font-family=\"Helvetica, Arial, sans-serif\" font-size=\"12\">\n";
  o << "<rect x=\"0\" y=\"0\" width=\"" << W << "\" height=\"" << H << "\" fill=\"white\"/>\n";
  o << "<text x=\"" << num1((PlotFrame::X0 + PlotFrame::X1) / 2)
    << "\" y=\"28\" text-anchor=\"middle\" font-size=\"15\" font-weight=\"bold\">" << xmlEscape(spec.title)
    << "</text>\n";
  svgAxes(o, f, spec);
  svgFront(o, f, spec.front);
  for (const auto& s : spec.series) svgSeries(o, f, s);
  svgLegend(o, spec);
  o << "</svg>\n";
  return o.str();
}

// ---------------------------------------------------------------------------------------------
// Files.

void writeText(const std::filesystem::path& path, const std::string& text) {
  writeAtomically(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw InputError(path.string(), "", "", "cannot create the file");
    out << text;
    out.close();
    if (!out) throw InputError(path.string(), "", "", "cannot write the file");
  });
}

// ---------------------------------------------------------------------------------------------
// The report.

struct Report {
  std::vector<SweepRow> rows;        ///< deduplicated, in order of first appearance
  std::vector<std::string> methods;  ///< in order of first appearance: the style index is the position
  std::vector<Group> groups;         ///< scene x image size, in order of first appearance

  int style(const std::string& method) const {
    return int(std::find(methods.begin(), methods.end(), method) - methods.begin());
  }
};

Report organise(const std::vector<SweepRow>& input) {
  Report rep;
  std::map<std::string, std::size_t> index;  // cell key -> position in rep.rows
  for (const SweepRow& r : input) {
    auto [it, inserted] = index.emplace(cellKey(r), rep.rows.size());
    if (inserted)
      rep.rows.push_back(r);
    else
      rep.rows[it->second] = r;  // a repeated cell: the last one wins
  }
  std::map<std::string, int> sizesPerScene;
  for (const SweepRow& r : rep.rows) {
    if (std::find(rep.methods.begin(), rep.methods.end(), r.method) == rep.methods.end())
      rep.methods.push_back(r.method);
    auto g = std::find_if(rep.groups.begin(), rep.groups.end(), [&](const Group& x) {
      return x.scene == r.scene && x.width == r.width && x.height == r.height;
    });
    if (g == rep.groups.end()) {
      rep.groups.push_back({r.scene, r.width, r.height, 0, {}, ""});
      ++sizesPerScene[r.scene];
      g = rep.groups.end() - 1;
    }
    g->triangles = std::max(g->triangles, r.triangles);
  }
  // Plot names: the scene's name made safe for a file, and a number where two scenes' names become
  // one (a<b and a>b, default@view and default_view: a second probe saw one plot overwrite the
  // other), in the order of the groups, so that the names do not depend on the file system.
  std::set<std::string> taken;
  for (Group& g : rep.groups) {
    for (const SweepRow& r : rep.rows)
      if (r.scene == g.scene && r.width == g.width && r.height == g.height) g.rows.push_back(&r);
    const std::string stem =
        fileStem(g.scene) + (sizesPerScene[g.scene] > 1 ? "-" + sizeLabel(g.width, g.height) : "");
    g.plotFile = stem + ".svg";
    for (int k = 2; taken.count(g.plotFile) > 0; ++k) g.plotFile = stem + "-" + std::to_string(k) + ".svg";
    taken.insert(g.plotFile);
  }
  return rep;
}

std::string groupTitle(const Group& g) {
  return g.scene + " (" + sizeLabel(g.width, g.height) + ")";
}

/// The plottable rows of `g` on the Pareto front of (frame ms, error), fastest first.
std::vector<const SweepRow*> frontOf(const Group& g) {
  std::vector<const SweepRow*> pts;
  for (const SweepRow* r : g.rows)
    if (plottable(*r)) pts.push_back(r);
  std::vector<std::pair<double, double>> te;
  for (const SweepRow* r : pts) te.emplace_back(r->frame.median, r->error);
  std::vector<const SweepRow*> out;
  for (std::size_t i : paretoFront(te)) out.push_back(pts[i]);
  return out;
}

std::string cellName(const SweepRow& r) {
  return r.resolution > 0 ? r.method + " " + std::to_string(r.resolution) : r.method;
}

std::string scenePlot(const Report& rep, const Group& g) {
  double minNonZero = HUGE_VAL;
  bool anyZero = false;
  for (const SweepRow* r : g.rows)
    if (plottable(*r)) {
      if (r->error > 0) minNonZero = std::min(minNonZero, r->error);
      if (r->error <= 0) anyZero = true;
    }
  double floor = 1e-6;
  if (minNonZero < floor) floor = std::pow(10.0, std::floor(std::log10(minNonZero)) - 1);
  auto yOf = [&](double e) { return std::max(e, floor); };

  PlotSpec spec;
  spec.title = g.scene + " (" + sizeLabel(g.width, g.height) + ", " + std::to_string(g.triangles) +
               " triangles): error against frame time";
  spec.xLabel = "frame time, median ms (log; whiskers: min to max over the measured frames)";
  spec.yLabel = "misclassified fraction of compared pixels (log; zero drawn at " + fmt("%g", floor) + ")";
  if (anyZero) spec.zeroLine = floor;
  for (const std::string& m : methodsOf(g.rows, rep.methods)) {
    Series s;
    s.name = m;
    s.style = rep.style(m);
    for (int res : resolutionsOf(g.rows)) {
      const SweepRow* r = findRow(g, m, res);
      if (!r || !plottable(*r)) continue;
      s.pts.push_back({r->frame.median, yOf(r->error)});
      s.labels.push_back(res > 0 ? std::to_string(res) : "");
      s.xRange.push_back({r->frame.min, r->frame.max});
    }
    if (!s.pts.empty()) spec.series.push_back(std::move(s));
  }
  for (const SweepRow* r : frontOf(g)) spec.front.push_back({r->frame.median, yOf(r->error)});
  return svgPlot(spec);
}

void header(std::ostringstream& md, const std::vector<std::string>& cols) {
  md << "|";
  for (const auto& c : cols) md << " " << c << " |";
  md << "\n|";
  for (std::size_t i = 0; i < cols.size(); ++i) md << (i == 0 ? ":---|" : "---:|");
  md << "\n";
}

void tableRow(std::ostringstream& md, const std::vector<std::string>& cells) {
  md << "|";
  for (const auto& c : cells) md << " " << c << " |";
  md << "\n";
}

void headline(std::ostringstream& md, const Report& rep, const Group& g) {
  md << "### " << mdEscape(groupTitle(g)) << "\n\n";
  std::vector<const SweepRow*> sm;
  for (const SweepRow* r : g.rows)
    if (r->family == "shadowmap") sm.push_back(r);
  std::string targetWhat = "plain shadow map";
  if (sm.empty()) {
    for (const SweepRow* r : g.rows)
      if (r->resolution > 0) sm.push_back(r);
    targetWhat = "depth-map method (no plain shadow map in this sweep)";
  }
  const SweepRow* target = lowestError(sm);
  if (!target) {
    md << "No depth-map method with an error figure: no target.\n\n";
    return;
  }
  const double targetMs = target->frame.median;
  md << "Target: " << pct(target->error) << " % total error, the best " << targetWhat << " ("
     << mdEscape(cellName(*target)) << ", " << sig(targetMs) << " ms).\n\n";
  header(md, {"method", "reaches target at", "ms", "best within " + sig(targetMs) + " ms", "error %", "lowest error at",
              "ms", "error %", "band error %", "p99 px"});
  for (const std::string& m : methodsOf(g.rows, rep.methods)) {
    std::vector<const SweepRow*> mine, reaching, inBudget;
    for (const SweepRow* r : g.rows) {
      if (r->method != m) continue;
      mine.push_back(r);
      if (!std::isfinite(r->frame.median) || !std::isfinite(r->error)) continue;
      if (r->error <= target->error) reaching.push_back(r);
      if (r->frame.median <= targetMs) inBudget.push_back(r);
    }
    const SweepRow* fastest = nullptr;
    for (const SweepRow* r : reaching)
      if (!fastest || r->frame.median < fastest->frame.median) fastest = r;
    const SweepRow* budget = lowestError(inBudget);
    const SweepRow* best = lowestError(mine);
    tableRow(md, {mdEscape(m), fastest ? resLabel(fastest->resolution) : "not reached",
                  fastest ? sig(fastest->frame.median) : "-", budget ? resLabel(budget->resolution) : "slower",
                  budget ? pct(budget->error) : "-", best ? resLabel(best->resolution) : "-",
                  best ? sig(best->frame.median) : "-", best ? pct(best->error) : "-",
                  best ? pct(best->bandError) : "-", best ? px(best->distP99) : "-"});
  }
  md << "\n";
}

void sceneSection(std::ostringstream& md, const Report& rep, const Group& g) {
  md << "### " << mdEscape(groupTitle(g)) << "\n\n";
  std::size_t pixels = 0, band = 0;
  for (const SweepRow* r : g.rows) pixels = std::max(pixels, r->pixels), band = std::max(band, r->bandPixels);
  md << g.triangles << " triangles; " << pixels << " pixels compared, " << band << " of them in the boundary band.\n\n";

  const auto front = frontOf(g);
  if (!front.empty()) {
    md << "Pareto front, fastest first (each cell is the most accurate for its frame time): ";
    for (std::size_t i = 0; i < front.size(); ++i)
      md << (i ? " → " : "") << mdEscape(cellName(*front[i])) << " (" << sig(front[i]->frame.median) << " ms, "
         << pct(front[i]->error) << " %)";
    md << ".\n\n";
  }

  const auto resolutions = resolutionsOf(g.rows);
  const auto methods = methodsOf(g.rows, rep.methods);
  std::vector<std::string> cols = {"method"};
  for (int r : resolutions) cols.push_back(r > 0 ? std::to_string(r) : "no map");

  md << "Frame time (median ms) / total error (%), by depth-map resolution:\n\n";
  header(md, cols);
  for (const auto& m : methods) {
    std::vector<std::string> cells = {mdEscape(m)};
    for (int res : resolutions) {
      const SweepRow* r = findRow(g, m, res);
      cells.push_back(r ? sig(r->frame.median) + " / " + pct(r->error) : "");
    }
    tableRow(md, cells);
  }
  md << "\nBoundary-band error (%) / 99th percentile distance of misclassified pixels from the exact boundary "
        "(px):\n\n";
  header(md, cols);
  for (const auto& m : methods) {
    std::vector<std::string> cells = {mdEscape(m)};
    for (int res : resolutions) {
      const SweepRow* r = findRow(g, m, res);
      cells.push_back(r ? pct(r->bandError) + " / " + px(r->distP99) : "");
    }
    tableRow(md, cells);
  }

  // Per-phase medians at the reference resolution (and methods without a depth map).
  const int ref = referenceResolution(resolutions);
  std::vector<const SweepRow*> atRef;
  for (const auto& m : methods) {
    const SweepRow* r = findRow(g, m, ref);
    if (!r) r = findRow(g, m, 0);
    if (r) atRef.push_back(r);
  }
  std::vector<std::string> phases;
  for (const auto& p : sweepPhases())
    if (std::any_of(atRef.begin(), atRef.end(), [&](const SweepRow* r) {
          return std::any_of(r->phases.begin(), r->phases.end(), [&](const auto& q) { return q.first == p; });
        }))
      phases.push_back(p);
  if (!atRef.empty() && !phases.empty()) {
    md << "\nPhases at depth-map resolution " << resLabel(ref) << " (median ms; methods without a depth map at their "
       << "only setting):\n\n";
    std::vector<std::string> pc = {"method"};
    for (const auto& p : phases) pc.push_back(p);
    pc.push_back("frame");
    header(md, pc);
    for (const SweepRow* r : atRef) {
      std::vector<std::string> cells = {mdEscape(r->method)};
      for (const auto& p : phases) {
        std::string c;
        for (const auto& [n, t] : r->phases)
          if (n == p) c = sig(t.median);
        cells.push_back(c);
      }
      cells.push_back(sig(r->frame.median));
      tableRow(md, cells);
    }
  }
  md << "\n![" << mdEscape(g.scene) << ": error against frame time](plots/" << g.plotFile << ")\n\n";
}

bool isSweepScene(const std::string& s) {
  return s.rfind("sweep-", 0) == 0;
}

/// The polygon sweep at one image size: table into `md`, returns the SVG.
std::string polygonSweep(std::ostringstream& md, const Report& rep, const std::vector<const Group*>& groups,
                         const std::string& plotFile) {
  std::vector<const SweepRow*> all;
  for (const Group* g : groups) all.insert(all.end(), g->rows.begin(), g->rows.end());
  const int ref = referenceResolution(resolutionsOf(all));
  std::vector<const Group*> sorted = groups;
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const Group* a, const Group* b) { return a->triangles < b->triangles; });
  const std::string size = sizeLabel(sorted.front()->width, sorted.front()->height);

  md << "### Image " << size << ", depth map " << resLabel(ref) << "\n\n";
  md << "Frame time (median ms) against scene triangles; methods without a depth map at their only setting.\n\n";
  std::vector<std::string> cols = {"method"};
  for (const Group* g : sorted) cols.push_back(mdEscape(g->scene) + " (" + std::to_string(g->triangles) + ")");
  header(md, cols);

  PlotSpec spec;
  spec.title = "Polygon sweep: frame time against triangles (image " + size + ", depth map " + resLabel(ref) + ")";
  spec.xLabel = "scene triangles (log)";
  spec.yLabel = "frame time, median ms (log)";
  for (const auto& m : methodsOf(all, rep.methods)) {
    std::vector<std::string> cells = {mdEscape(m)};
    Series s;
    s.name = m;
    s.style = rep.style(m);
    bool any = false;
    for (const Group* g : sorted) {
      const SweepRow* r = findRow(*g, m, ref);
      if (!r) r = findRow(*g, m, 0);
      cells.push_back(r ? sig(r->frame.median) : "");
      if (!r) continue;
      any = true;
      if (std::isfinite(r->frame.median) && r->frame.median > 0 && g->triangles > 0) {
        s.pts.push_back({double(g->triangles), r->frame.median});
        s.labels.push_back("");
      }
    }
    if (any) tableRow(md, cells);
    if (!s.pts.empty()) spec.series.push_back(std::move(s));
  }
  md << "\n![polygon sweep: frame time against triangles](plots/" << plotFile << ")\n\n";
  return svgPlot(spec);
}

}  // namespace

std::vector<std::size_t> paretoFront(const std::vector<std::pair<double, double>>& timeError) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < timeError.size(); ++i)
    if (std::isfinite(timeError[i].first) && std::isfinite(timeError[i].second)) order.push_back(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return timeError[a] < timeError[b]; });
  std::vector<std::size_t> front;
  double bestBefore = HUGE_VAL;  // lowest error among strictly faster points
  for (std::size_t i = 0; i < order.size();) {
    // Points of equal time: only those with the group's lowest error can stay, and only when they beat
    // every strictly faster point.
    std::size_t j = i;
    const double t = timeError[order[i]].first, e = timeError[order[i]].second;
    while (j < order.size() && timeError[order[j]].first == t) ++j;
    if (e < bestBefore)
      for (std::size_t k = i; k < j && timeError[order[k]].second == e; ++k) front.push_back(order[k]);
    bestBefore = std::min(bestBefore, e);
    i = j;
  }
  return front;
}

std::vector<std::filesystem::path> writeSweepReport(const std::vector<SweepRow>& rows, const SweepReportInfo& info,
                                                    const std::filesystem::path& dir) {
  const Report rep = organise(rows);
  const std::filesystem::path plots = dir / "plots";
  std::error_code ec;
  std::filesystem::create_directories(plots, ec);
  if (ec) throw InputError(plots.string(), "", "", "cannot create the directory: " + ec.message());

  auto orUnknown = [](const std::string& s) { return s.empty() ? std::string("unknown") : s; };
  std::ostringstream md;
  md << "# Shadow sweep: time against error\n\n";
  md << "- Command: `" << orUnknown(info.command) << "`\n";
  md << "- Machine: " << orUnknown(info.machine) << "\n";
  md << "- GL renderer: " << orUnknown(info.glRenderer) << "\n";
  md << "- Timing: " << orUnknown(info.timing);
  {
    int fmin = 0, fmax = 0;
    for (const SweepRow& r : rep.rows) {
      fmin = fmin == 0 ? r.frames : std::min(fmin, r.frames);
      fmax = std::max(fmax, r.frames);
    }
    if (fmax > 0)
      md << "; frame times are medians of "
         << (fmin == fmax ? std::to_string(fmax) : std::to_string(fmin) + " to " + std::to_string(fmax))
         << " measured frames after a warm-up (min and max in results.csv)";
  }
  md << "\n";
  md << "- Cells: " << rep.rows.size() << " (" << rep.groups.size() << " scene and image size pairs, "
     << rep.methods.size() << " methods)\n\n";
  md << "Error is the fraction of compared pixels (visible, facing the light, inside its frustum) whose shadow "
        "differs from the exact one; band error is the same over the pixels within "
     << sig(kBoundaryBand)
     << " px of the exact shadow boundary; p99 px is the 99th percentile distance of misclassified pixels from "
        "that boundary, in image pixels (\"-\" when no pixel is misclassified). Resolution \"no map\" is a method "
        "without a depth map.\n\n";

  md << "## Headline\n\n";
  md << "Per scene, the target is the lowest total error the plain shadow map (any capture) reaches at any swept "
        "resolution; for each method the table gives the fastest resolution whose error is at most the target, "
        "the lowest error it reaches within the target's frame time, and its lowest error overall with the band "
        "error and p99 distance there.\n\n";
  for (const Group& g : rep.groups) headline(md, rep, g);

  md << "## Scenes\n\n";
  std::vector<std::filesystem::path> written;
  std::vector<std::pair<std::filesystem::path, std::string>> files;
  for (const Group& g : rep.groups) {
    sceneSection(md, rep, g);
    files.emplace_back(plots / g.plotFile, scenePlot(rep, g));
  }

  // Polygon sweep: one plot per image size, the most common size gets polygon-sweep.svg.
  std::vector<std::pair<int, int>> sizes;
  std::map<std::pair<int, int>, std::vector<const Group*>> bySize;
  for (const Group& g : rep.groups)
    if (isSweepScene(g.scene)) {
      const auto key = std::make_pair(g.width, g.height);
      if (!bySize.count(key)) sizes.push_back(key);
      bySize[key].push_back(&g);
    }
  if (!sizes.empty()) {
    std::stable_sort(sizes.begin(), sizes.end(),
                     [&](const auto& a, const auto& b) { return bySize[a].size() > bySize[b].size(); });
    md << "## Polygon sweep\n\n";
    for (std::size_t i = 0; i < sizes.size(); ++i) {
      const std::string file =
          i == 0 ? "polygon-sweep.svg" : "polygon-sweep-" + sizeLabel(sizes[i].first, sizes[i].second) + ".svg";
      files.emplace_back(plots / file, polygonSweep(md, rep, bySize[sizes[i]], file));
    }
  }

  for (const auto& [path, text] : files) writeText(path, text);
  writeText(dir / "report.md", md.str());
  written.push_back(dir / "report.md");
  for (const auto& f : files) written.push_back(f.first);
  return written;
}

}  // namespace shadowvol

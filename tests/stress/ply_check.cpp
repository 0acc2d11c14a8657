#include "ply_check.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace shadowvol::stress {
namespace {

std::size_t typeSize(const std::string& t) {
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}

/// A little-endian scalar of PLY type `t` at `p` (the host is little-endian: Linux on x86/arm).
double readScalar(const char* p, const std::string& t) {
  if (t == "float" || t == "float32") {
    float v;
    std::memcpy(&v, p, 4);
    return v;
  }
  if (t == "double" || t == "float64") {
    double v;
    std::memcpy(&v, p, 8);
    return v;
  }
  if (t == "uchar" || t == "uint8") return std::uint8_t(*p);
  if (t == "int" || t == "int32") {
    std::int32_t v;
    std::memcpy(&v, p, 4);
    return v;
  }
  if (t == "uint" || t == "uint32") {
    std::uint32_t v;
    std::memcpy(&v, p, 4);
    return v;
  }
  return std::nan("");
}

struct Header {
  std::size_t vertices = 0, faces = 0;
  std::vector<std::pair<std::string, std::string>> vertexProps;  // type, name
  std::string countType, indexType;
};

std::string readHeader(std::istream& in, Header& h) {
  std::string line, current;
  std::getline(in, line);
  if (line != "ply") return "not a PLY file";
  while (std::getline(in, line) && line != "end_header") {
    std::istringstream ls(line);
    std::string word;
    ls >> word;
    if (word == "format") {
      ls >> word;
      if (word != "binary_little_endian") return "format " + word + " is not read here";
    } else if (word == "element") {
      std::size_t n = 0;
      ls >> current >> n;
      if (current == "vertex")
        h.vertices = n;
      else if (current == "face")
        h.faces = n;
      else if (n > 0)
        return "unexpected element " + current;
    } else if (word == "property" && current == "vertex") {
      std::string type, name;
      ls >> type >> name;
      h.vertexProps.emplace_back(type, name);
    } else if (word == "property" && current == "face") {
      std::string list;
      ls >> list >> h.countType >> h.indexType;
    }
  }
  if (line != "end_header") return "no end_header";
  return "";
}

}  // namespace

PlyCheck checkPly(const std::filesystem::path& path) {
  PlyCheck c;
  std::ifstream in(path, std::ios::binary);
  if (!in) return PlyCheck{"cannot open " + path.string()};
  Header h;
  if (std::string e = readHeader(in, h); !e.empty()) return PlyCheck{e};
  std::size_t stride = 0;
  std::array<std::ptrdiff_t, 3> at{-1, -1, -1};
  std::array<std::string, 3> types;
  for (const auto& [type, name] : h.vertexProps) {
    const int axis = name == "x" ? 0 : name == "y" ? 1 : name == "z" ? 2 : -1;
    if (axis >= 0) {
      at[axis] = std::ptrdiff_t(stride);
      types[axis] = type;
    }
    stride += typeSize(type);
  }
  if (at[0] < 0 || at[1] < 0 || at[2] < 0) return PlyCheck{"no x, y, z vertex properties"};
  std::vector<char> raw(stride * h.vertices);
  in.read(raw.data(), std::streamsize(raw.size()));
  if (!in) return PlyCheck{"truncated vertex data"};
  std::vector<std::array<double, 3>> v(h.vertices);
  for (std::size_t k = 0; k < h.vertices; ++k)
    for (int a = 0; a < 3; ++a) v[k][a] = readScalar(raw.data() + k * stride + at[a], types[a]);
  c.vertices = h.vertices;
  c.faces = h.faces;
  for (const auto& p : v) c.nonFinite += !(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));

  // Each undirected edge: how many faces use it, and the sum of its directions (+1 low->high).
  std::unordered_map<std::uint64_t, std::pair<int, int>> edges;
  const std::size_t countSize = typeSize(h.countType), indexSize = typeSize(h.indexType);
  if (countSize == 0 || indexSize == 0) return PlyCheck{"unreadable face list type"};
  std::vector<std::uint32_t> poly;
  for (std::size_t f = 0; f < h.faces; ++f) {
    char buf[8];
    if (!in.read(buf, std::streamsize(countSize))) return PlyCheck{"truncated face data"};
    const auto n = std::size_t(readScalar(buf, h.countType));
    poly.resize(n);
    for (auto& i : poly) {
      if (!in.read(buf, std::streamsize(indexSize))) return PlyCheck{"truncated face data"};
      i = std::uint32_t(readScalar(buf, h.indexType));
      if (i >= h.vertices) return PlyCheck{"face index out of range"};
    }
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t a = poly[k], b = poly[(k + 1) % n];
      auto& e = edges[(std::uint64_t(std::min(a, b)) << 32) | std::max(a, b)];
      ++e.first;
      e.second += a < b ? 1 : -1;
    }
    const auto& o = v.empty() ? std::array<double, 3>{} : v[0];  // about the first vertex: less cancellation
    for (std::size_t k = 1; k + 1 < n; ++k) {
      const auto &p = v[poly[0]], &q = v[poly[k]], &r = v[poly[k + 1]];
      const double a[3] = {p[0] - o[0], p[1] - o[1], p[2] - o[2]};
      const double b[3] = {q[0] - o[0], q[1] - o[1], q[2] - o[2]};
      const double d[3] = {r[0] - o[0], r[1] - o[1], r[2] - o[2]};
      c.signedVolume += (a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) +
                         a[2] * (b[0] * d[1] - b[1] * d[0])) /
                        6.0;
    }
  }
  for (const auto& [key, e] : edges) {
    if (e.first == 1)
      ++c.openEdges;
    else if (e.first > 2)
      ++c.overusedEdges;
    else if (e.second != 0)
      ++c.sameDirection;
  }
  return c;
}

}  // namespace shadowvol::stress

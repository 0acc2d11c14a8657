#include "mesh_writers/gltf_writer.h"

#include <algorithm>
#include <cstring>

#include <glm/common.hpp>
#include <nlohmann/json.hpp>

#include "shadowvol/report_json.h"
#include "shadowvol/version.h"

namespace shadowvol::mesh_writers {
namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;     // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;      // "BIN\0"
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr int kFloat = 5126, kUnsignedInt = 5125, kTriangles = 4;

std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string s;
  s.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t k = 0; k < bytes.size(); k += 3) {
    const std::uint32_t a = std::uint8_t(bytes[k]);
    const std::uint32_t b = k + 1 < bytes.size() ? std::uint8_t(bytes[k + 1]) : 0;
    const std::uint32_t c = k + 2 < bytes.size() ? std::uint8_t(bytes[k + 2]) : 0;
    const std::uint32_t v = (a << 16) | (b << 8) | c;
    s += table[(v >> 18) & 63];
    s += table[(v >> 12) & 63];
    s += k + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
    s += k + 2 < bytes.size() ? table[v & 63] : '=';
  }
  return s;
}

/// The buffer: positions (12 bytes each), then indices (12 bytes per triangle); both 4-aligned.
std::string bufferBytes(const GltfMesh& m) {
  std::string bytes(m.positions.size() * 12 + m.triangles.size() * 12, '\0');
  if (!m.positions.empty()) std::memcpy(bytes.data(), m.positions.data(), m.positions.size() * 12);
  if (!m.triangles.empty()) std::memcpy(bytes.data() + m.positions.size() * 12, m.triangles.data(), m.triangles.size() * 12);
  return bytes;
}

nlohmann::json document(const GltfMesh& m, std::size_t bufferLength) {
  nlohmann::json node = {{"name", m.name}};
  if (m.origin != glm::dvec3(0.0)) node["translation"] = {m.origin.x, m.origin.y, m.origin.z};
  nlohmann::json doc = {{"asset", {{"version", "2.0"}, {"generator", std::string("shadowvol ") + SHADOWVOL_VERSION}}},
                        {"scene", 0},
                        {"scenes", {{{"nodes", {0}}}}}};
  if (m.triangles.empty() || m.positions.empty()) {
    doc["nodes"] = {node};
    return doc;
  }
  glm::vec3 lo = m.positions[0], hi = m.positions[0];
  for (const auto& p : m.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  node["mesh"] = 0;
  doc["nodes"] = {node};
  const std::size_t positionBytes = m.positions.size() * 12;
  doc["buffers"] = {{{"byteLength", bufferLength}}};
  doc["bufferViews"] = {
      {{"buffer", 0}, {"byteOffset", 0}, {"byteLength", positionBytes}, {"target", kArrayBuffer}},
      {{"buffer", 0}, {"byteOffset", positionBytes}, {"byteLength", m.triangles.size() * 12},
       {"target", kElementArrayBuffer}}};
  doc["accessors"] = {{{"bufferView", 0},
                       {"componentType", kFloat},
                       {"count", m.positions.size()},
                       {"type", "VEC3"},
                       {"min", {lo.x, lo.y, lo.z}},
                       {"max", {hi.x, hi.y, hi.z}}},
                      {{"bufferView", 1}, {"componentType", kUnsignedInt}, {"count", m.triangles.size() * 3},
                       {"type", "SCALAR"}}};
  doc["meshes"] = {{{"name", m.name},
                    {"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"mode", kTriangles}}}}}};
  return doc;
}

void writeU32(std::ostream& out, std::uint32_t v) { out.write(reinterpret_cast<const char*>(&v), 4); }

}  // namespace

void writeGltf(std::ostream& out, const GltfMesh& m, bool binary) {
  const std::string bytes = bufferBytes(m);
  nlohmann::json doc = document(m, bytes.size());
  const bool hasBuffer = doc.contains("buffers");
  if (!binary) {
    if (hasBuffer) doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(bytes);
    out << jsonText(doc, 1) << '\n';
    return;
  }
  // GLB: header (magic, version 2, total length), JSON chunk padded with spaces, BIN chunk padded
  // with zeros, each chunk's length a multiple of 4 (glTF 2.0, "Binary glTF Layout").
  std::string json = jsonText(doc, -1);
  json.append((4 - json.size() % 4) % 4, ' ');
  std::string bin = bytes;
  bin.append((4 - bin.size() % 4) % 4, '\0');
  const std::size_t total = 12 + 8 + json.size() + (hasBuffer ? 8 + bin.size() : 0);
  writeU32(out, kGlbMagic);
  writeU32(out, 2);
  writeU32(out, std::uint32_t(total));
  writeU32(out, std::uint32_t(json.size()));
  writeU32(out, kChunkJson);
  out << json;
  if (hasBuffer) {
    writeU32(out, std::uint32_t(bin.size()));
    writeU32(out, kChunkBin);
    out << bin;
  }
}

}  // namespace shadowvol::mesh_writers

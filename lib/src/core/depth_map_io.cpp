#include "shadowvol/report_json.h"
#include "shadowvol/depth_map_io.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <numbers>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <nlohmann/json.hpp>

#include "shadowvol/error.h"
#include "shadowvol/output_lock.h"
#include "shadowvol/scene.h"
#include "shadowvol/temporary_files.h"
#include "shadowvol/version.h"
#include "shadowvol/mesh_io.h"
#include "mesh_readers/text_lines.h"  // lowerCase
#include "json_text.h"

namespace shadowvol {
namespace {

using nlohmann::json;

json matrixToJson(const glm::dmat4& m) {
  json a = json::array();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) a.push_back(m[c][r]);
  return a;
}

glm::dmat4 matrixFromJson(const json& a, const std::string& file, const std::string& field) {
  if (!a.is_array() || a.size() != 16) throw InputError(file, field, a.dump(), "expected 16 numbers (column-major)");
  glm::dmat4 m;
  for (int k = 0; k < 16; ++k) {
    if (!a[k].is_number() || !std::isfinite(a[k].get<double>()))
      throw InputError(file, field, a.dump(), "expected 16 finite numbers");
    m[k / 4][k % 4] = a[k].get<double>();
  }
  return m;
}

// FNV-1a (64-bit) of the depths as stored: the side file records it, so a side file beside a PFM
// it was not written with (a write interrupted between the two renames) is refused.
std::string depthChecksum(const std::vector<float>& depth) {
  std::uint64_t h = 14695981039346656037ull;
  const auto* bytes = reinterpret_cast<const unsigned char*>(depth.data());
  for (std::size_t k = 0; k < depth.size() * sizeof(float); ++k) h = (h ^ bytes[k]) * 1099511628211ull;
  char buf[24];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace

void checkDepthValues(const DepthMap& map, const std::string& source) {
  if (map.depth.size() != std::size_t(std::max(map.width, 0)) * std::size_t(std::max(map.height, 0)))
    throw InputError(source, "depth", std::to_string(map.depth.size()) + " values",
                     "expected width x height = " + std::to_string(map.width) + " x " + std::to_string(map.height));
  for (std::size_t k = 0; k < map.depth.size(); ++k) {
    const float d = map.depth[k];
    if (std::isnan(d) || d < 0)
      throw InputError(source, "texel " + std::to_string(k % map.width) + "," + std::to_string(k / map.width),
                       numberText(d), "depth must be >= 0 or +inf (no hit)");
  }
}

// The narrowest spot light a side file may hold: a scene's (README "Scene files": fields of view in
// [0.01, 179) degrees).
constexpr double kMinLightFovDegrees = 0.01;

// The side file's light matches what lightView() and lightProjection() produce: a rigid view
// (orthonormal rotation, bottom row 0 0 0 1), a projection of the light's kind whose near and far
// map to NDC z = -1 and +1, and finite world corners. Anything else would give a volume with
// non-finite or meaningless coordinates.
std::string matrixText(const glm::dmat4& m) {
  std::string t = "[";
  for (int c = 0; c < 4; ++c) {
    t += c ? ", [" : "[";
    for (int r = 0; r < 4; ++r) t += (r ? ", " : "") + numberText(m[c][r]);
    t += "]";
  }
  return t + "]";
}

void checkDepthMapLight(const DepthMap& map, const std::string& sfile, const DepthMapFieldNames& names,
                        bool mixedAxes) {
  if (map.width < 2 || map.height < 2)
    throw InputError(sfile, names.size, std::to_string(map.width) + "x" + std::to_string(map.height),
                     "a depth map needs at least 2 x 2 texels");
  if (map.lightType != LightType::Spot && map.lightType != LightType::Directional)
    throw InputError(sfile, names.lightType, toString(map.lightType),
                     "a depth map is one spot or directional light's view (a point light's six faces are a "
                     "cube map)");
  for (int k = 0; k < 3; ++k)
    if (!(std::abs(map.origin[k]) <= kMaxSceneMagnitude))
      throw InputError(sfile, names.origin, numberText(map.origin[k]),
                       "expected 3 finite numbers within +-1e12, as a scene's");
  const double tol = 1e-6;
  if (!(std::isfinite(map.nearPlane) && map.nearPlane >= 0.0))
    throw InputError(sfile, names.nearPlane, numberText(map.nearPlane), "near must be finite and >= 0");
  if (!(map.farPlane > map.nearPlane && map.farPlane < 1e30))
    throw InputError(sfile, names.farPlane, numberText(map.farPlane), "far must be greater than near and below 1e30");
  if (map.lightType == LightType::Spot && !(map.nearPlane > 0.0))
    throw InputError(sfile, names.nearPlane, numberText(map.nearPlane), "a spot light needs near > 0");
  const glm::dmat4& v = map.lightView;
  const glm::dmat3 r(v);
  const glm::dmat3 rrt = r * glm::transpose(r);
  bool rigid = std::abs(v[0][3]) + std::abs(v[1][3]) + std::abs(v[2][3]) + std::abs(v[3][3] - 1.0) < tol &&
               glm::determinant(r) > 0.0 && glm::length(v[3]) < 1e30;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) rigid = rigid && std::abs(rrt[a][b] - (a == b ? 1.0 : 0.0)) < tol;
  if (!rigid)
    throw InputError(sfile, names.lightView, matrixText(v),
                     "expected a rigid world -> light view transform (rotation and translation)");
  const glm::dmat4& p = map.lightProjection;
  const bool perspective = map.lightType == LightType::Spot;
  // The unprojection (TexelUnprojector, volume_common.glsl) reads P00, P11, P20, P21, P30, P31 and
  // the z and w rows' last two columns; the other entries are 0 in both kinds, and a non-zero one
  // (a w that varies with x, say) would put texels at infinity.
  const double scale = std::max({1.0, std::abs(p[0][0]), std::abs(p[1][1])});
  bool zeroElsewhere = true;
  for (const auto& [c, r] : {std::pair{0, 1}, {0, 2}, {0, 3}, {1, 0}, {1, 2}, {1, 3}})
    if (!(mixedAxes && r + c == 1)) zeroElsewhere = zeroElsewhere && std::abs(p[c][r]) < tol * scale;
  const bool kindOk = zeroElsewhere && (perspective ? std::abs(p[2][3] + 1.0) < tol && std::abs(p[3][3]) < tol
                                                    : std::abs(p[2][3]) < tol && std::abs(p[3][3] - 1.0) < tol);
  auto ndcZ = [&](double d) {
    const glm::dvec4 c = p * glm::dvec4(0.0, 0.0, -d, 1.0);
    return c.z / c.w;
  };
  const bool depthOk =
      std::abs(ndcZ(std::max(map.nearPlane, 1e-300)) + 1.0) < 1e-4 && std::abs(ndcZ(map.farPlane) - 1.0) < 1e-4;
  if (!kindOk || !depthOk || !(std::abs(glm::determinant(p)) > 0.0))
    throw InputError(sfile, names.lightProjection, matrixText(p),
                     std::string("expected the ") + (perspective ? "perspective" : "orthographic") +
                         " projection of a " + toString(perspective ? LightType::Spot : LightType::Directional) +
                         " light that maps near and far to NDC z -1 and +1");
  // A spot light narrower than a scene's light may be (fov 0.01 degrees: P00, P11 = cot(fov / 2)).
  const double maxCot = 1.0 / std::tan(0.5 * kMinLightFovDegrees * std::numbers::pi / 180.0);
  if (perspective && (std::abs(p[0][0]) > maxCot || std::abs(p[1][1]) > maxCot))
    throw InputError(sfile, names.lightProjection, matrixText(p),
                     "a spot light narrower than " + numberText(kMinLightFovDegrees) +
                         " degrees, the narrowest a scene's may be");
  const TexelUnprojector unproject(map);
  std::array<glm::dvec3, 8> corners;
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 w = unproject.worldPoint(k & 1 ? map.width - 1 : 0, k & 2 ? map.height - 1 : 0,
                                              k & 4 ? map.farPlane : std::max(map.nearPlane, 1e-9));
    if (!(std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z) && glm::length(w) < 1e30))
      throw InputError(sfile, names.lightProjection, matrixText(p),
                       "the light's window corners are not finite in world space");
    corners[std::size_t(k)] = w;
  }
  // The volume's vertices are stored relative to /origin, in single precision on export and on the
  // GPU: a window a few float steps wide at its distance from the origin would collapse (a second
  // probe's light 1e11 from an origin of 0 gave 484 zero-area triangles).
  double reach = 0.0;
  for (const auto& c : corners) reach = std::max(reach, glm::length(c));
  const double window = std::min(glm::length(corners[5] - corners[4]), glm::length(corners[6] - corners[4]));
  if (window < kMinWindowFloatSteps * reach * std::numeric_limits<float>::epsilon())
    throw InputError(sfile, names.lightView, matrixText(v),
                     "the light's window at the far plane is " + numberText(window) + " units wide but lies " +
                         numberText(reach) + " units from the origin: less than " +
                         numberText(kMinWindowFloatSteps) +
                         " single-precision steps across, the volume would collapse (write the map with its " +
                         std::string(names.origin) + " near the light's window)");
}


std::filesystem::path depthSidecarPath(const std::filesystem::path& pfm) {
  return std::filesystem::path(pfm.string() + ".json");
}

namespace {

// What a side file names itself and its depths (writeDepthMap writes them, readSideFile holds a
// file to them).
constexpr const char* kSideFileFormat = "shadowvol depth map 1";
constexpr const char* kSideFileQuantity = "light-view depth (-z in light view space), world units; +inf = no hit";

}  // namespace

void writeDepthMap(const DepthMap& map, const std::filesystem::path& pfm) {
  static_assert(std::endian::native == std::endian::little, "PFM writer assumes a little-endian host");
  checkDepthMapGuard(map.guard, map.width, map.height, pfm.string(), "guard");  // as the reader would
  json side = {
      {"format", kSideFileFormat},
      {"writer", "shadowvol " SHADOWVOL_VERSION},
      {"width", map.width},
      {"height", map.height},
      {"quantity", kSideFileQuantity},
      {"light", toString(map.lightType)},
      {"capture", toString(map.capture)},
      {"near", map.nearPlane},
      {"far", map.farPlane},
      {"lightView", matrixToJson(map.lightView)},
      {"lightProjection", matrixToJson(map.lightProjection)},
      {"origin", {map.origin.x, map.origin.y, map.origin.z}},
      {"guard", map.guard},
      {"depthChecksum", "fnv1a64:" + depthChecksum(map.depth)},
  };
  const auto sidecar = depthSidecarPath(pfm);
  const OutputLock lock(folderOf(pfm));  // another run's map and side file of this name wait or are refused
  const OutputSetGuard set;  // a signal between the two renames takes the side file along
  writeAtomically(pfm, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw InputError(pfm.string(), "", "", "cannot create the file");
    out << "Pf\n" << map.width << ' ' << map.height << "\n-1.0\n";  // negative scale = little-endian
    out.write(reinterpret_cast<const char*>(map.depth.data()), std::streamsize(map.depth.size() * sizeof(float)));
    out.flush();
    if (!out) throw InputError(pfm.string(), "", "", "writing the file failed (disk full?)");
    // The side file is written before the PFM is renamed into place, so both exist or neither.
    writeAtomically(sidecar, [&](const std::filesystem::path& tmp2) {
      std::ofstream js(tmp2);
      js << jsonText(side) << '\n';
      js.flush();
      if (!js) throw InputError(sidecar.string(), "", "", "writing the file failed");
    });
  });
}

// Refuses what is not a regular file (a folder, /dev/zero, a pipe) before anything is read.
static void requireRegularFile(const std::filesystem::path& p, const char* what) {
  std::error_code ec;
  if (std::filesystem::exists(p, ec) && !std::filesystem::is_regular_file(p, ec))
    throw InputError(p.string(), "", "", std::string(what) + " is not a regular file (a folder, device or pipe)");
}

namespace {

// The side file's "depthChecksum" (optional: files from before it was written lack it):
// "fnv1a64:" and 16 hex digits of map's depths, or InputError naming what is wrong.
void checkSideFileChecksum(const json& given, const std::string& sfile, const std::string& file, const DepthMap& map) {
  const std::string want = given.is_string() ? given.get<std::string>() : "";
  if (want.rfind("fnv1a64:", 0) != 0)
    throw InputError(sfile, "/depthChecksum", given.dump().substr(0, 40),
                     "expected \"fnv1a64:\" and 16 hex digits (the only checksum this shadowvol writes)");
  if (want != "fnv1a64:" + depthChecksum(map.depth))
    throw InputError(sfile, "/depthChecksum", want,
                     "does not match the depths in " + file + ": the side file belongs to another depth map");
}

// The keys a side file may hold (writeDepthMap's); any other is refused, as a scene file's are.
const char* const kSideFileKeys[] = {"format", "writer", "width", "height", "quantity", "light", "capture", "near",
                                     "far", "lightView", "lightProjection", "origin", "guard", "depthChecksum"};

// The side file's width or height: a whole number equal to the PFM's (`given`).
void checkSideFileSize(const json& side, const char* key, int given, const std::string& sfile) {
  const std::string field = std::string("/") + key;
  if (!side.contains(key)) throw InputError(sfile, field, "", "required field is missing");
  const json& v = side[key];
  if (!v.is_number_integer()) throw InputError(sfile, field, v.dump().substr(0, 40), "expected a whole number");
  if (v != given)
    throw InputError(sfile, field, v.dump(), std::string("does not match the PFM's ") + key + ", " + std::to_string(given));
}

// The side file's optional descriptive fields: "writer" a string, "quantity" the one this
// shadowvol writes (depths of another quantity, say NDC z, would be read as light-view depths).
void checkSideFileLabels(const json& side, const std::string& sfile) {
  if (side.contains("writer") && !side["writer"].is_string())
    throw InputError(sfile, "/writer", side["writer"].dump().substr(0, 40), "expected a string");
  if (side.contains("quantity") && side["quantity"] != kSideFileQuantity)
    throw InputError(sfile, "/quantity", side["quantity"].dump().substr(0, 80),
                     std::string("an unknown quantity: this shadowvol reads \"") + kSideFileQuantity + "\"");
}

// Fills map's light, capture, planes, matrices and origin from the side file of the PFM `file`,
// whose W x H depths map already holds: the JSON rules of every input (json_text.h), the format
// named when given, no unknown key, the size and the checksum of those depths.
void readSideFile(const std::filesystem::path& sidecar, const std::string& file, DepthMap& map) {
  const std::string sfile = sidecar.string();
  std::error_code ec;
  requireRegularFile(sidecar, "the side file");
  if (std::filesystem::exists(sidecar, ec) && std::filesystem::file_size(sidecar, ec) > (1u << 20))
    throw InputError(sfile, "", "", "larger than a depth map's side file may be (1 MiB)");
  std::ifstream js(sidecar, std::ios::binary);
  if (!js) throw InputError(sfile, "", "", "cannot open the depth map's side file");
  const json side = parseJsonText(std::string(std::istreambuf_iterator<char>(js), std::istreambuf_iterator<char>()), sfile);
  if (!side.is_object()) throw InputError(sfile, "", side.dump().substr(0, 40), "expected a JSON object");
  for (const auto& [key, value] : side.items())
    if (std::find(std::begin(kSideFileKeys), std::end(kSideFileKeys), key) == std::end(kSideFileKeys))
      throw InputError(sfile, "/" + key, value.dump().substr(0, 40), "not a field of a depth map's side file");
  if (side.contains("format") && side["format"] != kSideFileFormat)  // optional: older files lack it
    throw InputError(sfile, "/format", side["format"].dump(),
                     std::string("an unknown format: this shadowvol reads \"") + kSideFileFormat + "\"");
  auto need = [&](const char* key) -> const json& {
    if (!side.contains(key)) throw InputError(sfile, std::string("/") + key, "", "required field is missing");
    return side[key];
  };
  checkSideFileLabels(side, sfile);
  checkSideFileSize(side, "width", map.width, sfile);
  checkSideFileSize(side, "height", map.height, sfile);
  const std::string light = need("light").is_string() ? need("light").get<std::string>() : "";
  if (!parseLightType(light, map.lightType) || map.lightType == LightType::Point)  // a map is one light view
    throw InputError(sfile, "/light", need("light").dump(), "expected \"spot\" or \"directional\"");
  const std::string cap = need("capture").is_string() ? need("capture").get<std::string>() : "";
  if (!parseCaptureMode(cap, map.capture))
    throw InputError(sfile, "/capture", need("capture").dump(), "expected " + choicesText(namesIn(kCaptureModeNames)));
  for (const char* plane : {"near", "far"})
    if (!need(plane).is_number()) throw InputError(sfile, std::string("/") + plane, side[plane].dump(), "expected a number");
  map.nearPlane = side["near"].get<double>();
  map.farPlane = side["far"].get<double>();
  if (!(map.farPlane > map.nearPlane))
    throw InputError(sfile, "/far", side["far"].dump(), "far must be greater than near");
  map.lightView = matrixFromJson(need("lightView"), sfile, "/lightView");
  map.lightProjection = matrixFromJson(need("lightProjection"), sfile, "/lightProjection");
  checkDepthMapLight(map, sfile);
  if (side.contains("depthChecksum")) checkSideFileChecksum(side["depthChecksum"], sfile, file, map);
  if (side.contains("origin")) {  // optional: files from before it was written have origin 0
    const json& o = side["origin"];
    if (!o.is_array() || o.size() != 3 || !o[0].is_number() || !o[1].is_number() || !o[2].is_number())
      throw InputError(sfile, "/origin", o.dump(), "expected 3 finite numbers");
    map.origin = {o[0].get<double>(), o[1].get<double>(), o[2].get<double>()};
    for (int k = 0; k < 3; ++k)
      if (!(std::abs(map.origin[k]) <= kMaxSceneMagnitude))  // NaN too
        throw InputError(sfile, "/origin", o.dump(), "expected 3 finite numbers within +-1e12, as a scene's");
  }
  if (side.contains("guard")) {  // optional: files from before it was written have none
    const json& g = side["guard"];
    if (!g.is_number_integer()) throw InputError(sfile, "/guard", g.dump().substr(0, 40), "expected a whole number");
    checkDepthMapGuard(g.get<std::int64_t>(), map.width, map.height, sfile, "/guard");
    map.guard = int(g.get<std::int64_t>());
  }
}

}  // namespace

void checkDepthMapPath(const std::filesystem::path& pfm, const std::string& source, const std::string& field) {
  const std::string ext = mesh_readers::lowerCase(pfm.extension().string());
  if (pfm.empty()) throw InputError(source, field, "\"\"", "a .pfm file name is required");
  if (ext != ".pfm") throw InputError(source, field, pfm.string(), "depth maps are written as PFM: use a .pfm file name");
}

DepthMap readDepthMap(const std::filesystem::path& pfm) {
  const std::string file = pfm.string();
  requireRegularFile(pfm, "the depth map");
  std::ifstream in(pfm, std::ios::binary);
  if (!in) throw InputError(file, "", "", "cannot open the depth map");
  std::string magic, wText, hText;
  double scale = 0;
  in.width(8);  // header tokens are short: "Pf"
  in >> magic;
  // Size tokens of at most 24 characters (a longer one, cut there, is quoted with "..." after it).
  auto token = [&in](std::string& t) {
    in.width(24);
    in >> t;
    in.width(0);
    const int next = in ? in.peek() : EOF;
    if (next != EOF && !std::isspace(next)) t += "...";
  };
  token(wText);
  token(hText);
  if (magic != "Pf") throw InputError(file, "header", magic, "not a single-channel PFM (expected \"Pf\")");
  // The size as written is what the message quotes (a number too large for int is not clamped).
  auto side = [](const std::string& t) {
    int v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    return ec == std::errc() && end == t.data() + t.size() && v >= 1 && v <= 65536 ? v : 0;
  };
  const int w = side(wText), h = side(hText);
  if (!in || w == 0 || h == 0)
    throw InputError(file, "header", wText + " " + hText, "bad PFM size (width and height: whole numbers 1 to 65536)");
  std::string scaleText;
  in.width(32);
  in >> scaleText;
  in.width(0);
  char* end = nullptr;
  scale = std::strtod(scaleText.c_str(), &end);
  if (scaleText.empty() || *end != '\0' || !std::isfinite(scale) || scale == 0.0)
    throw InputError(file, "header scale", scaleText, "expected a finite, non-zero number (its sign is the byte order)");
  if (!(scale < 0)) throw InputError(file, "header scale", scaleText, "only little-endian PFM is supported");
  if (in.get() == '\r')  // the single whitespace after the scale
    throw InputError(file, "header", "CR LF", "a PFM header's lines end with a single newline (\\n), not CR LF "
                                              "(the depths would be read one byte off)");
  // The data's length is checked against the file before anything is allocated: exactly the
  // header's W x H depths, no more (a wrong size in the header would read the wrong texels).
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(pfm, ec);
  const auto dataBytes = std::uintmax_t(w) * std::uintmax_t(h) * sizeof(float);
  if (ec || in.tellg() < 0 || bytes - std::uintmax_t(in.tellg()) < dataBytes)
    throw InputError(file, "data", std::to_string(w) + "x" + std::to_string(h),
                     "the file is shorter than its header says (" + std::to_string(dataBytes) + " bytes of depths)");
  if (bytes - std::uintmax_t(in.tellg()) > dataBytes)
    throw InputError(file, "data", std::to_string(w) + "x" + std::to_string(h),
                     "the file holds " + std::to_string(bytes - std::uintmax_t(in.tellg()) - dataBytes) +
                         " bytes after the header's " + std::to_string(dataBytes) + " bytes of depths");
  DepthMap map;
  map.width = w;
  map.height = h;
  map.depth.resize(std::size_t(w) * std::size_t(h));
  in.read(reinterpret_cast<char*>(map.depth.data()), std::streamsize(map.depth.size() * sizeof(float)));
  if (!in) throw InputError(file, "data", "", "the file is shorter than its header says");
  checkDepthValues(map, file);

  readSideFile(depthSidecarPath(pfm), file, map);
  return map;
}

}  // namespace shadowvol

#include "shadowvol/depth_map_io.h"

#include <bit>
#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "shadowvol/error.h"
#include "shadowvol/mesh_io.h"

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

}  // namespace

std::filesystem::path depthSidecarPath(const std::filesystem::path& pfm) {
  return std::filesystem::path(pfm.string() + ".json");
}

void writeDepthMap(const DepthMap& map, const std::filesystem::path& pfm) {
  static_assert(std::endian::native == std::endian::little, "PFM writer assumes a little-endian host");
  json side = {
      {"format", "shadowvol depth map 1"},
      {"width", map.width},
      {"height", map.height},
      {"quantity", "light-view depth (-z in light view space), world units; +inf = no hit"},
      {"light", map.lightType == LightType::Spot ? "spot" : "directional"},
      {"capture", toString(map.capture)},
      {"near", map.nearPlane},
      {"far", map.farPlane},
      {"lightView", matrixToJson(map.lightView)},
      {"lightProjection", matrixToJson(map.lightProjection)},
  };
  const auto sidecar = depthSidecarPath(pfm);
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
      js << side.dump(2) << '\n';
      js.flush();
      if (!js) throw InputError(sidecar.string(), "", "", "writing the file failed");
    });
  });
}

DepthMap readDepthMap(const std::filesystem::path& pfm) {
  const std::string file = pfm.string();
  std::ifstream in(pfm, std::ios::binary);
  if (!in) throw InputError(file, "", "", "cannot open the depth map");
  std::string magic;
  int w = 0, h = 0;
  double scale = 0;
  in >> magic >> w >> h >> scale;
  if (magic != "Pf") throw InputError(file, "header", magic, "not a single-channel PFM (expected \"Pf\")");
  if (!in || w <= 0 || h <= 0 || w > 65536 || h > 65536)
    throw InputError(file, "header", std::to_string(w) + "x" + std::to_string(h), "bad PFM size");
  if (!(scale < 0)) throw InputError(file, "header", std::to_string(scale), "only little-endian PFM is supported");
  in.get();  // the single whitespace after the scale
  DepthMap map;
  map.width = w;
  map.height = h;
  map.depth.resize(std::size_t(w) * std::size_t(h));
  in.read(reinterpret_cast<char*>(map.depth.data()), std::streamsize(map.depth.size() * sizeof(float)));
  if (!in) throw InputError(file, "data", "", "the file is shorter than its header says");
  for (std::size_t k = 0; k < map.depth.size(); ++k) {
    const float d = map.depth[k];
    if (std::isnan(d) || (std::isinf(d) && d < 0) || d < 0)
      throw InputError(file, "texel " + std::to_string(k % w) + "," + std::to_string(k / w), std::to_string(d),
                       "depth must be >= 0 or +inf (no hit)");
  }

  const auto sidecar = depthSidecarPath(pfm);
  const std::string sfile = sidecar.string();
  std::ifstream js(sidecar);
  if (!js) throw InputError(sfile, "", "", "cannot open the depth map's side file");
  json side;
  try {
    side = json::parse(js);
  } catch (const json::exception& e) {
    throw InputError(sfile, "", "", std::string("malformed JSON: ") + e.what());
  }
  auto need = [&](const char* key) -> const json& {
    if (!side.contains(key)) throw InputError(sfile, std::string("/") + key, "", "required field is missing");
    return side[key];
  };
  if (need("width") != w || need("height") != h)
    throw InputError(sfile, "/width", side["width"].dump(), "does not match the PFM's size");
  const std::string light = need("light").is_string() ? need("light").get<std::string>() : "";
  if (light == "spot") map.lightType = LightType::Spot;
  else if (light == "directional") map.lightType = LightType::Directional;
  else throw InputError(sfile, "/light", need("light").dump(), "expected \"spot\" or \"directional\"");
  const std::string cap = need("capture").is_string() ? need("capture").get<std::string>() : "";
  if (!parseCaptureMode(cap, map.capture))
    throw InputError(sfile, "/capture", need("capture").dump(), "expected front, back or midpoint");
  if (!need("near").is_number() || !need("far").is_number())
    throw InputError(sfile, "/near", side["near"].dump(), "near and far must be numbers");
  map.nearPlane = side["near"].get<double>();
  map.farPlane = side["far"].get<double>();
  if (!(map.farPlane > map.nearPlane))
    throw InputError(sfile, "/far", side["far"].dump(), "far must be greater than near");
  map.lightView = matrixFromJson(need("lightView"), sfile, "/lightView");
  map.lightProjection = matrixFromJson(need("lightProjection"), sfile, "/lightProjection");
  return map;
}

}  // namespace shadowvol

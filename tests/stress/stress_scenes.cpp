#include "stress_scenes.h"

#include <cmath>
#include <cstdio>

namespace shadowvol::stress {

using nlohmann::json;

Vec3 operator+(Vec3 a, Vec3 b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
Vec3 operator-(Vec3 a, Vec3 b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
Vec3 operator*(double s, Vec3 a) {
  return {s * a.x, s * a.y, s * a.z};
}
double dot(Vec3 a, Vec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Vec3 normalized(Vec3 a) {
  return (1.0 / std::sqrt(dot(a, a))) * a;
}
json toJson(Vec3 a) {
  return json::array({a.x, a.y, a.z});
}
Vec3 vec3Of(const json& a) {
  return {a.at(0).get<double>(), a.at(1).get<double>(), a.at(2).get<double>()};
}

json defaultCamera() {
  return {{"eye", {0, 6, 11}}, {"target", {0, 1, 0}}, {"fov", 45}, {"width", 640}, {"height", 480}};
}

json defaultSpotScene() {
  return {
      {"objects",
       {{{"type", "plane"}, {"name", "ground"}, {"size", 20}},
        {{"type", "sphere"},
         {"name", "sphere"},
         {"radius", kSphereRadius},
         {"detail", 4},
         {"transform", {{"translate", toJson(kSphereCentre)}}}}}},
      {"light", {{"type", "spot"}, {"position", toJson(kSpotPosition)}, {"target", toJson(kSpotTarget)}, {"fov", 55}}},
      {"camera", defaultCamera()}};
}

json defaultDirectionalScene() {
  json s = defaultSpotScene();
  s["light"] = {{"type", "directional"}, {"direction", toJson(kSpotTarget - kSpotPosition)}};
  return s;
}

json groundObjectsScene() {
  return {{"objects",
           {{{"type", "plane"}, {"name", "ground"}, {"size", 20}},
            {{"type", "hemisphere"}, {"name", "dome"}, {"radius", 1}, {"segments", 96}, {"rings", 24}},
            {{"type", "sphere"},
             {"name", "ball"},
             {"radius", 0.5},
             {"detail", 3},
             {"transform", {{"translate", {-2, 0.5, 1}}}}}}},
          {"camera", defaultCamera()}};
}

namespace {

void scaleLength(json& obj, const char* key, double s) {
  if (!obj.contains(key)) return;
  json& v = obj[key];
  if (v.is_array())
    for (auto& e : v) e = e.get<double>() * s;
  else
    v = v.get<double>() * s;
}

void mapPoint(json& obj, const char* key, double s, Vec3 offset) {
  if (obj.contains(key)) obj[key] = toJson(s * vec3Of(obj[key]) + offset);
}

}  // namespace

json scaleAndMove(json scene, double s, Vec3 offset) {
  for (json& o : scene["objects"]) {
    for (const char* key : {"size", "radius", "height", "trunkRadius", "trunkHeight", "crownRadius"})
      scaleLength(o, key, s);
    json& t = o["transform"];  // creates an empty one where missing
    if (t.is_null()) t = json::object();
    t["translate"] = toJson(s * (t.contains("translate") ? vec3Of(t["translate"]) : Vec3{}) + offset);
  }
  json& light = scene["light"];
  mapPoint(light, "position", s, offset);
  mapPoint(light, "target", s, offset);
  for (const char* key : {"extent", "near", "far"}) scaleLength(light, key, s);
  json& camera = scene["camera"];
  mapPoint(camera, "eye", s, offset);
  mapPoint(camera, "target", s, offset);
  for (const char* key : {"near", "far"}) scaleLength(camera, key, s);
  return scene;
}

std::string numberName(double v) {
  char buf[64];
  if (v == 0.0) return "0";
  const int e = int(std::floor(std::log10(std::abs(v)) + 1e-9));
  if (e >= 3 || e <= -3) {
    std::snprintf(buf, sizeof buf, "%ge%d", v / std::pow(10.0, e), e);
  } else {
    std::snprintf(buf, sizeof buf, "%g", v);
  }
  return buf;
}

}  // namespace shadowvol::stress

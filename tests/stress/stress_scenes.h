// The scene documents the stress configurations start from, and the similarity transform that
// scales and moves a whole scene (objects, light and camera) without changing its picture.
#pragma once

#include <array>
#include <string>

#include <nlohmann/json.hpp>

namespace shadowvol::stress {

/// A world-space point or direction (Y up, as in scene files).
struct Vec3 {
  double x = 0, y = 0, z = 0;
};
Vec3 operator+(Vec3 a, Vec3 b);
Vec3 operator-(Vec3 a, Vec3 b);
Vec3 operator*(double s, Vec3 a);
double dot(Vec3 a, Vec3 b);
Vec3 cross(Vec3 a, Vec3 b);
Vec3 normalized(Vec3 a);
nlohmann::json toJson(Vec3 a);
Vec3 vec3Of(const nlohmann::json& a);  ///< from a JSON array of 3 numbers

/// The built-in default scene (data/scenes/default.json): a ground plane of 20, a sphere of radius
/// 1 at (0, 2, 0), a spot light at (3, 9, 2) with fov 55, the camera at (0, 6, 11).
nlohmann::json defaultSpotScene();
/// The same objects and camera under a directional light along the spot light's axis; position,
/// extent and near/far fitted by the loader.
nlohmann::json defaultDirectionalScene();
/// A dome of radius 1 on a ground plane of 20 with a sphere of radius 0.5 resting on the ground
/// beside it; the light is left for the caller to set.
nlohmann::json groundObjectsScene();

/// The default camera (eye (0, 6, 11), target (0, 1, 0), fov 45).
nlohmann::json defaultCamera();

/// The sphere centre, radius and spot light position of defaultSpotScene(), for geometry on them.
inline constexpr Vec3 kSphereCentre{0, 2, 0};
inline constexpr double kSphereRadius = 1.0;
inline constexpr Vec3 kSpotPosition{3, 9, 2};
inline constexpr Vec3 kSpotTarget{-0.3, 0, -0.2};

/// The scene mapped by p -> scale * p + offset: every position (object translations, the light's
/// position and target, the camera's eye and target) and every length (sizes, radii, heights, the
/// light's extent, explicit near/far planes). Directions, angles and tessellation stay; a plane
/// without a transform gets one. Objects must use translate/scale transforms (not `matrix`).
nlohmann::json scaleAndMove(nlohmann::json scene, double scale, Vec3 offset);

/// A short file-safe spelling of a number: 1e-04 -> "1e-4", 100000 -> "1e5", 0.5 -> "0.5".
std::string numberName(double v);

}  // namespace shadowvol::stress

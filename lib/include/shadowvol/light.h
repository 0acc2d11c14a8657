// The light: spot (perspective), directional (orthographic) or point (six 90-degree spot views,
// cube_map.h), and its matrices.
// Spaces: world -> light view (lightView) -> light clip/NDC (lightProjection). OpenGL conventions:
// the light looks down -Z of its view space, NDC z in [-1, 1], right-handed world, Y up.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "shadowvol/enum_names.h"

namespace shadowvol {

enum class LightType { Spot, Directional, Point };

/// "spot", "directional", "point".
inline constexpr EnumNames<LightType, 3> kLightTypeNames{
    {{LightType::Spot, "spot"}, {LightType::Directional, "directional"}, {LightType::Point, "point"}}};

const char* toString(LightType type);
/// Parses "spot", "directional" or "point"; returns false for anything else.
bool parseLightType(const std::string& text, LightType& type);

/// The fewest single-precision steps, at the magnitude of its coordinates, that a light's window
/// must span: narrower, the map's texels collapse onto each other (a depth side file's far window,
/// a scene's directional light's extent).
inline constexpr double kMinWindowFloatSteps = 64.0;

struct Light {
  LightType type = LightType::Spot;
  glm::dvec3 position{0.0, 10.0, 0.0};    ///< world; spot and point: apex. Directional: origin of the view
                                          ///< (fitted behind the scene when fitPosition is true)
  bool fitPosition = false;               ///< directional only: place position from the scene bounds
  glm::dvec3 direction{0.0, -1.0, 0.0};   ///< world, unit length: the way the light shines (not
                                          ///< used by a point light)
  glm::dvec3 up{0.0, 0.0, 0.0};           ///< world; zero = pick deterministically (see lightUp)
  double fovYDegrees = 60.0;              ///< spot only: full vertical (= horizontal) opening angle
  double halfExtent = 0.0;                ///< directional only: half width of the square view, world units
  double nearPlane = 0.0;                 ///< distance along the light axis, world units (> 0 for
                                          ///< spot and point: along each cube face's axis, the
                                          ///< largest |coordinate| of the offset from the light);
                                          ///< 0 = fitted to the scene by fitLightAndCamera,
                                          ///< which also tightens given planes to the scene
  double farPlane = 0.0;                  ///< distance along the light axis (> near); 0 = fitted
  double intensity = 1.0;                 ///< factor of the diffuse term (>= 0; the renderer's
                                          ///< RenderOptions::diffuse x this): several lights'
                                          ///< terms add up, so a scene may scale each down
};

/// The up vector used for the light's view: Light::up when non-zero, else world +Y, or world -Z
/// when the direction is within about 2.6 degrees of +-Y (|dir.y| > 0.999).
glm::dvec3 lightUp(const Light& light);

/// World -> light view. The light sits at `position` looking along `direction`; a point light's
/// view is the translation by -position alone (world axes; its faces' views: cube_map.h).
glm::dmat4 lightView(const Light& light);

/// Light view -> light clip. Square aspect (the depth map is W x H texels over a square window
/// only when W == H; otherwise aspect W/H). Perspective for spot, orthographic for directional.
/// A point light has none (its faces do: cubeFaceLight); asking is a programming error.
glm::dmat4 lightProjection(const Light& light, double aspect = 1.0);

/// Texels a volume's depth map reaches past the light's window on every side: the map's
/// outermost ring, which the volume puts on the far plane to close it (docs/volume.md), and the
/// sheet's slope down to it (the quads between the ring and the next texels) lie outside the
/// window, so a shadow that crosses the window's edge keeps its last texel (without the band, a
/// lit strip about a texel wide). The blur reads up to 2.5 texels away, clamped at the map's edge,
/// as anywhere near an edge. (A point light's refined GPU faces keep 4: their seams must see the
/// blur of one unbounded map, renderer_impl.h.)
inline constexpr int kVolumeGuardTexels = 2;

/// The widest guard band a caller may ask for (texels a side).
inline constexpr int kMaxGuardTexels = 64;

/// A spot or directional light widened by `guard` texels on every side of a W x H map: a
/// (W + 2 guard) x (H + 2 guard) map of it has the W x H map's texel centres and texel size,
/// texel (i, j) of the W x H map being its texel (i + guard, j + guard). Spot: the opening's
/// tangent times (H + 2 guard) / H; directional: the extent times the same; position, direction,
/// up and planes kept. The light's own window (what it lights) stays the given light's.
Light guardedLight(const Light& light, int width, int height, int guard);

}  // namespace shadowvol

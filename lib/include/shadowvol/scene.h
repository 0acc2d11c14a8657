// A scene: world-space triangle meshes, one or more lights, one camera. Loaded from the JSON format
// documented in README.md ("Scene files"), or the built-in default scene.
#pragma once

#include <filesystem>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "shadowvol/camera.h"
#include "shadowvol/enum_names.h"
#include "shadowvol/light.h"
#include "shadowvol/triangle_mesh.h"

namespace shadowvol {

/// One object of the scene with its transform already applied (and rebased: see Scene::origin).
struct SceneObject {
  std::string name;   ///< "name" from the file, else "<type>#<index>"
  std::string type;   ///< plane, sphere, box, cylinder, tree, mesh
  TriangleMesh mesh;  ///< world space, relative to Scene::origin
};

/// The default limit on a scene's triangles (parseScene's maxTriangles).
inline constexpr std::size_t kMaxSceneTriangles = 50'000'000;

/// The most lights a scene may have: each costs a capture, a volume and a stencil pass per frame.
inline constexpr std::size_t kMaxSceneLights = 16;
/// Every number of a scene file, and a depth map's origin, lies within +-kMaxSceneMagnitude
/// (README "Scene files"): double keeps 1e-4 units there, and products of two such numbers stay
/// far from overflow.
inline constexpr double kMaxSceneMagnitude = 1e12;

struct Scene {
  std::string source = "default";  ///< file path it was loaded from, or "default"
  /// The files it was read from: the scene file (loadScene), then each mesh object's file, as
  /// opened (relative paths resolved against the scene's folder); empty for the built-in scene.
  /// The command line refuses to write over any of them.
  std::vector<std::filesystem::path> files;
  /// Local origin, world units, double: every position in this struct (objects, light, camera,
  /// bounds) is relative to it, world = stored + origin. loadScene picks the centre of the
  /// objects' bounds when that centre lies further from the world origin than the bounds' radius
  /// (a scene placed far away), else 0; but the camera's target (clamped into the bounds) when
  /// that lies more than 1e3 view distances from the first choice (detail beside a huge ground).
  /// Geometry is transformed and rebased in double before it is
  /// stored as float, so a scene at 1e6 keeps the precision it has at the origin (README "Far from
  /// the origin").
  glm::dvec3 origin{0.0};
  std::vector<SceneObject> objects;
  /// The first light: the file's `light`, or `lights[0]`. Near/far (and for directional lights
  /// position/extent) fitted when not given. Every one-light tool (build, depth, the sweep) works
  /// on this one; forEachLight makes each light in turn this one.
  Light light;
  /// The lights after the first of a `lights` array, fitted like `light`. Each has its own
  /// capture, volume and stencil pass; its diffuse term is added where its stencil is 0.
  std::vector<Light> otherLights;
  bool lightsArray = false;  ///< the file gave `lights` (error pointers say /lights/k), not `light`
  Camera camera;   ///< near/far fitted when not given

  std::size_t lightCount() const { return 1 + otherLights.size(); }
  const Light& lightAt(std::size_t k) const { return k == 0 ? light : otherLights.at(k - 1); }
  Light& lightAt(std::size_t k) { return k == 0 ? light : otherLights.at(k - 1); }
  /// The JSON pointer of light k in the file: "/light", or "/lights/k" when it gave an array.
  std::string lightPointer(std::size_t k) const;
  /// A copy with light k as its one light (`light`, no otherLights): for the per-light checks.
  Scene withOnlyLight(std::size_t k) const;

  std::size_t triangleCount() const;
  Bounds3 bounds() const;        ///< of all objects, world space
  TriangleMesh merged() const;   ///< all objects in one mesh, in object order
};

/// Calls f(k) for k = 0 .. lightCount() - 1 with light k swapped into scene.light, so that code
/// written for one light (fitting, capture, validation) runs for each; the lights are back in
/// their places afterwards, also when f throws.
template <class F>
void forEachLight(Scene& scene, F&& f) {
  struct Restore {
    Scene& s;
    std::size_t k = 0;
    ~Restore() {
      if (k > 0) std::swap(s.light, s.otherLights[k - 1]);
    }
  } restore{scene};
  for (std::size_t k = 0; k < scene.lightCount(); ++k) {
    if (k > 0) {
      restore.k = k;
      std::swap(scene.light, scene.otherLights[k - 1]);
    }
    f(k);
    if (k > 0) {
      std::swap(scene.light, scene.otherLights[k - 1]);
      restore.k = 0;
    }
  }
}

/// Warnings collected while loading (for example a light inside a closed mesh).
struct SceneLoadResult {
  Scene scene;
  std::vector<std::string> warnings;
  /// Those of `warnings` that concern the camera alone (its planes moved, its view empty, its eye
  /// inside a closed mesh): commands that render no image (build, depth) leave them out.
  std::vector<std::string> cameraWarnings;
};

/// Reads a JSON scene file. Relative mesh paths are resolved against the scene file's folder.
/// Throws InputError naming the file, the JSON pointer of the field and the value on bad input.
SceneLoadResult loadScene(const std::filesystem::path& path);

/// Parses scene JSON text; `source` names it in errors, `baseDir` resolves mesh paths.
/// `maxTriangles` caps the scene's triangles (checked before a primitive is generated and after a
/// mesh file is read); a service that loads untrusted scenes may want less than the default.
SceneLoadResult parseScene(const std::string& jsonText, const std::string& source,
                           const std::filesystem::path& baseDir, std::size_t maxTriangles = kMaxSceneTriangles);

/// The built-in default scene: a sphere floating above a ground plane under a spot light.
Scene defaultScene();

/// Fills in what the file left open: light near/far (and a directional light's position and
/// half extent) from the part of the scene bounds inside the light's frustum (computed exactly:
/// the box clipped by the frustum's side planes), camera near/far likewise from the part inside
/// the camera's. The margin beyond that part is 1 % of the smaller of its depth extent and the
/// scene's radius. A given far beyond that far side, or a given near before its near side, is
/// moved there: it would capture nothing more and only cost depth precision (README "Scene
/// files", Light); the camera's near only when the part it sees lies wholly in front of it. Light planes
/// are fitted to a square map's frustum: a map wider than tall sees further in x, so a capture
/// with W > H needs the light's near and far given. Returns one note per moved plane.
std::vector<std::string> fitLightAndCamera(Scene& scene);

/// How the light's frustum is fitted. Scene: to the whole scene as given (fitLightAndCamera, what
/// loadScene does). View: narrowed to what the camera can see (fitLightToView).
enum class LightFit { Scene, View };
inline constexpr EnumNames<LightFit, 2> kLightFitNames{{{LightFit::Scene, "scene"}, {LightFit::View, "view"}}};
const char* toString(LightFit fit);
bool parseLightFit(const std::string& text, LightFit& fit);  ///< "scene" or "view"

/// What fitLightToView did; the window is the spot light's full opening angle (degrees) or the
/// directional light's half extent (world units).
struct LightFitResult {
  bool changed = false;
  double windowBefore = 0.0, windowAfter = 0.0;
  bool reaimed = false;  ///< the light's direction (spot) or position (directional) moved
  std::string note;      ///< one sentence for the log
};

/// Fits the light to the view: its frustum is narrowed to the receivers the camera can see, the
/// part of the scene's bounds inside the camera's frustum and inside the light's (the casters
/// that can shadow them lie between them and the light, so inside the same frustum). A spot
/// light re-aims at their footprint in its image and narrows its opening angle; a directional
/// light shifts and shrinks its square window; either stays inside the frustum it had (so no
/// point is lit that was not), with 2 texels of a `mapResolution` map to spare each side for
/// the volume's far-plane ring. Near and far are then fitted again, and long triangles split at
/// the new eye plane (splitSceneAcrossEyePlanes). Unchanged when the camera sees none of the lit
/// bounds, when they reach behind a spot light's eye plane, or when they fill the frustum already.
LightFitResult fitLightToView(Scene& scene, int mapResolution);

/// The light texel's footprint on the receivers the camera sees, for a map `mapResolution` texels
/// wide: smallest and largest over the vertices of the camera-visible part of the bounds inside the
/// light's frustum (world units: 2 tan(fov/2) d / N at light-view depth d; 2 halfExtent / N for a
/// directional light). nullopt when the camera sees none of the lit bounds.
std::optional<std::pair<double, double>> receiverTexelSize(const Scene& scene, int mapResolution);

/// Writes the scene's triangles as PLY (binary), OBJ, OFF or STL, chosen by the extension:
/// relative to scene.origin (recorded in the file's header comment), or with `worldCoordinates`
/// in world units and double precision (see MeshFrame). Atomic: a failure leaves no partial file.
void exportSceneMesh(const Scene& scene, const std::filesystem::path& path, bool worldCoordinates = false);

}  // namespace shadowvol

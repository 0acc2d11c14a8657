// A scene: world-space triangle meshes, one light, one camera. Loaded from the JSON format
// documented in README.md ("Scene files"), or the built-in default scene.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "shadowvol/camera.h"
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

struct Scene {
  std::string source = "default";  ///< file path it was loaded from, or "default"
  /// Local origin, world units, double: every position in this struct (objects, light, camera,
  /// bounds) is relative to it, world = stored + origin. loadScene picks the centre of the
  /// objects' bounds when that centre lies further from the world origin than the bounds' radius
  /// (a scene placed far away), else 0. Geometry is transformed and rebased in double before it is
  /// stored as float, so a scene at 1e6 keeps the precision it has at the origin (README "Far from
  /// the origin").
  glm::dvec3 origin{0.0};
  std::vector<SceneObject> objects;
  Light light;     ///< near/far (and for directional lights position/extent) fitted when not given
  Camera camera;   ///< near/far fitted when not given

  std::size_t triangleCount() const;
  Bounds3 bounds() const;        ///< of all objects, world space
  TriangleMesh merged() const;   ///< all objects in one mesh, in object order
};

/// Warnings collected while loading (for example a light inside a closed mesh).
struct SceneLoadResult {
  Scene scene;
  std::vector<std::string> warnings;
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

/// Writes the scene's triangles as PLY (binary), OBJ, OFF or STL, chosen by the extension:
/// relative to scene.origin (recorded in the file's header comment), or with `worldCoordinates`
/// in world units and double precision (see MeshFrame). Atomic: a failure leaves no partial file.
void exportSceneMesh(const Scene& scene, const std::filesystem::path& path, bool worldCoordinates = false);

}  // namespace shadowvol

// Reading and writing triangle meshes through OpenMesh's IO (OBJ, OFF, PLY, STL), plus the
// atomic-write helper every writer of this library uses.
#pragma once

#include <filesystem>
#include <functional>

#include <glm/vec3.hpp>

#include "shadowvol/triangle_mesh.h"
#include "shadowvol/volume_mesh.h"

namespace shadowvol {

/// Reads OBJ, OFF, PLY or STL (by extension); polygons are triangulated by OpenMesh.
/// Throws InputError (file named) when the file is missing, unreadable, has no triangles or has
/// non-finite coordinates.
TriangleMesh readTriangleMesh(const std::filesystem::path& path);

/// Where the stored coordinates of a mesh sit in the world (Scene::origin, DepthMap::origin).
struct MeshFrame {
  glm::dvec3 origin{0.0};         ///< world = stored + origin
  /// false: write the stored coordinates (float), and name a non-zero origin in the header comment
  /// of PLY ("comment shadowvol origin X Y Z"), OBJ ("# shadowvol origin X Y Z") and STL (its
  /// 80-byte header); OFF has no comments, so there the origin is only in the command's output.
  /// true: write stored + origin, computed in double: PLY with double properties, OBJ and OFF
  /// with 17 significant digits; STL (float only) is refused.
  bool worldCoordinates = false;
};

/// Writes PLY (binary little-endian), OBJ, OFF or STL by extension, atomically.
/// Throws InputError for an unknown extension, STL with world coordinates, or a failed write.
void writeTriangleMesh(const TriangleMesh& mesh, const std::filesystem::path& path, const MeshFrame& frame = {});

/// The same for a volume, its double positions kept when writing world coordinates; the origin
/// is the mesh's (VolumeMesh::origin).
void writeVolumeMesh(const VolumeMesh& mesh, const std::filesystem::path& path, bool worldCoordinates = false);

/// Calls write(tmp) with a temporary path beside `path`, then renames tmp to path. If write throws
/// or the rename fails, the temporary file is removed and nothing is left at `path`.
void writeAtomically(const std::filesystem::path& path, const std::function<void(const std::filesystem::path&)>& write);

}  // namespace shadowvol

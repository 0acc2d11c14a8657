// Reading and writing triangle meshes through OpenMesh's IO (OBJ, OFF, PLY, STL), plus the
// atomic-write helper every writer of this library uses.
#pragma once

#include <filesystem>
#include <functional>

#include "shadowvol/triangle_mesh.h"

namespace shadowvol {

/// Reads OBJ, OFF, PLY or STL (by extension); polygons are triangulated by OpenMesh.
/// Throws InputError (file named) when the file is missing, unreadable, has no triangles or has
/// non-finite coordinates.
TriangleMesh readTriangleMesh(const std::filesystem::path& path);

/// Writes PLY (binary little-endian), OBJ, OFF or STL by extension, atomically.
/// Throws InputError for an unknown extension or a failed write.
void writeTriangleMesh(const TriangleMesh& mesh, const std::filesystem::path& path);

/// Calls write(tmp) with a temporary path beside `path`, then renames tmp to path. If write throws
/// or the rename fails, the temporary file is removed and nothing is left at `path`.
void writeAtomically(const std::filesystem::path& path, const std::function<void(const std::filesystem::path&)>& write);

}  // namespace shadowvol

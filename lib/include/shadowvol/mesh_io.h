// Reading and writing triangle meshes (read: OBJ, OFF, PLY, STL with code of our own, any other
// format through Assimp in a child process; written: those four and glTF 2.0 with code of our
// own), plus the atomic-write helper every writer of this library uses.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <span>
#include <string_view>

#include <glm/vec3.hpp>

#include "shadowvol/triangle_mesh.h"
#include "shadowvol/volume_mesh.h"

namespace shadowvol {

/// Reads OBJ, ASCII OFF (OFF, COFF, NOFF...; '#' comments), PLY (ASCII or binary) or STL (binary
/// or ASCII) by extension, with strict readers bounded by the file's size (lib/src/core/mesh_readers/):
/// positions rounded to float as stored (readRebasedTriangleMesh keeps the detail of a mesh far
/// from its file's origin), polygons fanned from their first corner where convex and ear-clipped
/// where not (mesh_readers/polygon_triangulation.h),
/// every face kept (degenerate and non-manifold ones too; STL corners welded by position).
/// Throws InputError naming the file, the line (OBJ, OFF, ASCII STL) or element ("face 17", PLY;
/// "triangle 3", binary STL) and the value when the file is missing or malformed, declares more
/// than it holds, has a non-finite coordinate (or one beyond float), a face with fewer than 3
/// vertices or an index out of range (OBJ: 0, or counting back past the first vertex), or no
/// triangles. Any other extension that Assimp imports (.gltf, .glb, .fbx, .dae, .3ds, ...) is
/// read with Assimp in a child process (60 s, 4 GiB; mesh_readers/assimp_reader.h): every mesh of
/// the file with its node transforms, triangulated, welded by position; a crash or time-out there
/// is an InputError naming the file.
/// EmptyMesh::Allow returns a file without triangles (an empty volume as `build` writes it when
/// nothing is in shadow) instead of refusing it; every other check stays.
enum class EmptyMesh { Refuse, Allow };
TriangleMesh readTriangleMesh(const std::filesystem::path& path, EmptyMesh empty = EmptyMesh::Refuse);

/// A mesh read from a file, its positions stored relative to `origin`: world = stored + origin.
struct RebasedMesh {
  TriangleMesh mesh;
  glm::dvec3 origin{0.0};
  /// Where the file itself stores float coordinates (binary STL, binary PLY with float x, y, z, a
  /// format read through Assimp, each of its meshes before its node places it): the extent of its
  /// worst-placed part and the largest magnitude of that part's coordinates, as stored (0 and 0
  /// elsewhere). Detail finer than a float step there was lost in the file.
  double floatExtent = 0.0, floatReach = 0.0;
};

/// readTriangleMesh, rebased where float would lose the mesh's detail: positions are parsed (and
/// placed by an Assimp file's nodes) in double, and a mesh lying further from its file's origin
/// than about 8 times its size (where float keeps fewer than 2^20 steps across it) is stored
/// relative to its bounding box's centre, subtracted in double before the rounding. Every other
/// mesh is readTriangleMesh's, bit for bit, with origin 0. Scenes read their mesh files so, and
/// `check`.
RebasedMesh readRebasedTriangleMesh(const std::filesystem::path& path, EmptyMesh empty = EmptyMesh::Refuse);

/// Where positions given in double are stored as float without losing their detail (world =
/// stored + origin): 0 while float keeps about 2^20 steps across the box of the vertices that some
/// triangle uses at its distance from the world origin, else that box's centre. The rule
/// readRebasedTriangleMesh applies to a file's mesh (and the Python module's export to its arrays).
glm::dvec3 floatStorageOrigin(std::span<const glm::dvec3> positions,
                              std::span<const std::array<std::uint32_t, 3>> triangles);

/// The same readers on bytes held in memory (a mesh from an archive, a socket or a fuzzer):
/// `format` is the extension it would have (".obj", ".off", ".ply", ".stl", or one of Assimp's,
/// any case), `source` names the input in error messages. Throws InputError as readTriangleMesh
/// does. (A .gltf that refers to a separate .bin cannot be read from memory: read the file.)
TriangleMesh parseTriangleMesh(std::string_view bytes, std::string_view format, const std::string& source);

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

/// The formats the writers below write, as their extensions read in messages.
inline constexpr const char* kMeshOutputFormats = ".ply, .obj, .off, .stl, .gltf or .glb";

/// Whether the writers write `path`'s extension (any case): a caller can refuse an output path
/// before the work that produces the mesh.
bool isMeshOutputFormat(const std::filesystem::path& path);

/// Writes PLY (binary little-endian), OBJ, OFF, STL, glTF 2.0 (.gltf with the buffer embedded, or
/// binary .glb) by extension (any case), atomically. glTF holds float positions: the stored
/// coordinates, with a non-zero origin as the node's translation (so world placement is exact
/// either way). Throws InputError for an unknown extension, STL with world coordinates, a mesh too
/// large for glTF's 32-bit buffer, or a failed write.
void writeTriangleMesh(const TriangleMesh& mesh, const std::filesystem::path& path, const MeshFrame& frame = {});

/// What writeVolumeMesh wrote.
struct WrittenVolume {
  /// The origin the file names (world = written + origin; with world coordinates in PLY, OBJ or
  /// OFF the file holds world coordinates and this is only the mesh's local origin).
  glm::dvec3 origin{0.0};
  /// Vertices at the same position, as written (float or double), as an earlier vertex: readers
  /// that weld by position (STL, glTF, `shadowvol check` on them) join them.
  std::size_t coincidentVertices = 0;
  /// Triangles with two corners at the same position as written: zero area in the file.
  std::size_t collapsedTriangles = 0;
};

/// The same for a volume, its double positions kept when writing world coordinates. Float
/// positions (without world coordinates, and always in glTF) are written relative to the mesh's
/// origin (VolumeMesh::origin), moved to the centre of the volume's box where float would keep
/// fewer than about 2^20 steps across it there (floatStorageOrigin; a probe's volume 1e6 from a
/// scene origin of 0 had 60 zero-area triangles); that origin is named as MeshFrame says.
WrittenVolume writeVolumeMesh(const VolumeMesh& mesh, const std::filesystem::path& path, bool worldCoordinates = false);

/// Vertices at the same position as an earlier vertex (exactly equal doubles).
std::size_t coincidentVertices(const VolumeMesh& mesh);

/// Calls write(tmp) with a temporary path beside `path`, then renames tmp to path. If write throws
/// or the rename fails, the temporary file is removed and nothing is left at `path`.
void writeAtomically(const std::filesystem::path& path, const std::function<void(const std::filesystem::path&)>& write);

/// Creates folder `dir` and its missing parents; InputError naming it when that fails (a read-only
/// or virtual file system, a file in the way).
void createFolders(const std::filesystem::path& dir);

}  // namespace shadowvol

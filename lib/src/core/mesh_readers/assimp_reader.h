// Mesh formats beyond our own four readers (glTF, FBX, COLLADA, 3DS, Blender, ...), read with
// Assimp (Debian's libassimp, fuzzed upstream) in a child process (isolated_call.h): a file that
// crashes or hangs Assimp ends the child and becomes an InputError, never the caller's crash.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "mesh_readers/parsed_mesh.h"

namespace shadowvol::mesh_readers {

/// Whether `lowerExtension` (".fbx") is a format Assimp imports and none of our own readers
/// (.obj, .off, .ply, .stl) takes.
bool isAssimpFormat(const std::string& lowerExtension);

/// Assimp's formats as a list for messages: ".3ds, .dae, .fbx, ..." (without ours).
std::string assimpFormatList();

/// Reads every mesh of the file (a path, so that a .gltf finds its .bin and textures; or, with
/// an empty path, `bytes` with `lowerExtension` as the format hint), node transforms applied,
/// in double, polygons triangulated, points and lines dropped, corners at bit-identical positions
/// welded across all meshes (as the STL reader does, again when stored in float: weldCorners). Throws InputError naming `source` when Assimp
/// refuses the file, crashes, runs past 60 s or 4 GiB, or when a position is not finite (the
/// mesh and vertex named).
ParsedMesh readWithAssimp(const std::string& source, const std::filesystem::path& path, std::string_view bytes,
                            const std::string& lowerExtension);

}  // namespace shadowvol::mesh_readers

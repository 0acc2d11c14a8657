// The formats our own strict readers take (obj_reader, off_reader, ply_reader, stl_reader); every
// other extension goes to Assimp (assimp_reader.h) or is refused.
#pragma once

#include <string>

namespace shadowvol::mesh_readers {

/// `lowerExtension` as ".obj": one of the four formats read by our own readers.
inline bool isOwnFormat(const std::string& lowerExtension) {
  return lowerExtension == ".obj" || lowerExtension == ".off" || lowerExtension == ".ply" || lowerExtension == ".stl";
}

}  // namespace shadowvol::mesh_readers

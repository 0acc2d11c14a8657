// Independent checks of a volume written by `shadowvol build`: the binary PLY read back, its
// vertices finite, every edge shared by exactly two faces in opposite directions (closed and
// consistently oriented), and the enclosed signed volume positive (outward).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

namespace shadowvol::stress {

struct PlyCheck {
  std::string error;  ///< non-empty when the file could not be read (then nothing else is set)
  std::size_t vertices = 0;
  std::size_t faces = 0;
  std::size_t nonFinite = 0;      ///< vertices with a NaN or infinite coordinate
  std::size_t openEdges = 0;      ///< undirected edges used by one face only
  std::size_t overusedEdges = 0;  ///< undirected edges used by more than two faces
  std::size_t sameDirection = 0;  ///< edges whose two faces run them the same way (inconsistent orientation)
  double signedVolume = 0;        ///< world units cubed, about the first vertex (positive = outward)

  bool closed() const { return error.empty() && openEdges == 0 && overusedEdges == 0 && sameDirection == 0; }
  /// Outward: positive volume; an empty mesh (no faces) counts as outward.
  bool outward() const { return error.empty() && (faces == 0 || signedVolume > 0); }
};

/// Reads a binary little-endian PLY with float or double x, y, z and faces as a list of
/// uchar/int/uint counts and int/uint indices (what shadowvol writes); polygons are fanned.
PlyCheck checkPly(const std::filesystem::path& path);

}  // namespace shadowvol::stress

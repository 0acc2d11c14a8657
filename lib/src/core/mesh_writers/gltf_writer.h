// glTF 2.0 export of a triangle mesh: .gltf (JSON with the buffer embedded as a base64 data URI,
// one self-contained file) or .glb (the binary container: a JSON chunk and a BIN chunk).
// One node, one mesh, one primitive of TRIANGLES: POSITION (float VEC3, with the min/max glTF
// requires) and indices (unsigned int). glTF stores float positions; a mesh whose stored
// coordinates are relative to an origin gets that origin as the node's translation (in double,
// in the JSON), so a viewer places it in world space without rounding the world coordinates.
// An empty mesh gives a scene with one node and no mesh (glTF forbids accessors of count 0).
#pragma once

#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace shadowvol::mesh_writers {

struct GltfMesh {
  std::vector<glm::vec3> positions;                      ///< stored coordinates (world = + origin)
  std::vector<std::array<std::uint32_t, 3>> triangles;   ///< counter-clockwise seen from outside
  glm::dvec3 origin{0.0};                                ///< the node's translation
  std::string name;                                      ///< node and mesh name
};

/// Writes `mesh` as glTF 2.0 to `out`: binary (.glb) or JSON with an embedded buffer (.gltf).
void writeGltf(std::ostream& out, const GltfMesh& mesh, bool binary);

}  // namespace shadowvol::mesh_writers

// Corners at bit-identical positions welded into one vertex: the STL and Assimp readers, whose
// files store a position per corner (or per corner and attribute), build indexed meshes with it.
#pragma once

#include <cstdint>
#include <cstring>
#include <unordered_map>

#include <glm/vec3.hpp>

#include "shadowvol/triangle_mesh.h"

namespace shadowvol::mesh_readers {

// Welds corners at identical positions into one vertex, keyed by their bits (-0 counts as 0).
class CornerWelder {
 public:
  explicit CornerWelder(TriangleMesh& mesh) : mesh_(mesh) {}
  std::uint32_t vertex(const glm::vec3& p) {
    const glm::vec3 q = p + glm::vec3(0.0f);  // -0 + 0 = +0
    Key key;
    std::memcpy(key.bits, &q, sizeof key.bits);
    const auto [it, added] = index_.try_emplace(key, std::uint32_t(mesh_.positions.size()));
    if (added) mesh_.positions.push_back(q);
    return it->second;
  }

 private:
  struct Key {
    std::uint32_t bits[3];
    bool operator==(const Key& o) const { return bits[0] == o.bits[0] && bits[1] == o.bits[1] && bits[2] == o.bits[2]; }
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = k.bits[0];
      h = h * 0x9E3779B97F4A7C15ull ^ k.bits[1];
      h = h * 0x9E3779B97F4A7C15ull ^ k.bits[2];
      return std::size_t(h ^ (h >> 29));
    }
  };
  TriangleMesh& mesh_;
  std::unordered_map<Key, std::uint32_t, Hash> index_;
};

}  // namespace shadowvol::mesh_readers

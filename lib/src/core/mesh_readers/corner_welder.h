// Corners at bit-identical positions welded into one vertex: the STL and Assimp readers, whose
// files store a position per corner (or per corner and attribute), build indexed meshes with it.
#pragma once

#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

#include <glm/vec3.hpp>

namespace shadowvol::mesh_readers {

/// Welds corners at identical positions into one vertex of `positions`, keyed by their bits (-0
/// counts as 0), numbered in the order they first come. Vec: glm::vec3 (stored positions) or
/// glm::dvec3 (the Assimp reader's placed ones, before the storing).
template <class Vec>
class CornerWelder {
 public:
  explicit CornerWelder(std::vector<Vec>& positions) : positions_(positions) {}
  std::uint32_t vertex(const Vec& p) {
    const Vec q = p + Vec(0);  // -0 + 0 = +0
    Key key;
    std::memcpy(key.bits, &q, sizeof key.bits);
    const auto [it, added] = index_.try_emplace(key, std::uint32_t(positions_.size()));
    if (added) positions_.push_back(q);
    return it->second;
  }

 private:
  using Word = std::conditional_t<sizeof(typename Vec::value_type) == 8, std::uint64_t, std::uint32_t>;
  struct Key {
    Word bits[3];
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
  std::vector<Vec>& positions_;
  std::unordered_map<Key, std::uint32_t, Hash> index_;
};

}  // namespace shadowvol::mesh_readers

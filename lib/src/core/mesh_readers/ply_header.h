// The header of a PLY file, parsed strictly before any of its body is read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace shadowvol::mesh_readers {

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

/// The scalar types of PLY, under either name (char / int8, ..., double / float64).
enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::size_t plyTypeSize(PlyType t);  ///< bytes in a binary body
bool plyTypeIsInteger(PlyType t);

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;  ///< of the value, or of each list item
  bool isList = false;
  PlyType countType = PlyType::UInt8;  ///< of a list's length
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
  std::size_t line = 0;   ///< of its `element` line, for messages
  std::string_view text;  ///< that line (a view into the file's bytes)
};

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  std::size_t bodyOffset = 0;     ///< first byte after the `end_header` line
  std::size_t bodyFirstLine = 0;  ///< line number of that byte, for ASCII messages
};

/// Parses the header: `ply`, then `format ascii|binary_little_endian|binary_big_endian 1.0`, then
/// `element NAME COUNT` lines each followed by its `property TYPE NAME` / `property list TYPE TYPE
/// NAME` lines (comment and obj_info lines anywhere, other lines only before the first element),
/// then `end_header` within the first 64 KiB.
/// Also checks that the declared counts fit the body: in binary, count x the element's smallest
/// row (its scalars and list lengths, lists empty) summed over the elements; in ASCII, 2 bytes
/// per value. Throws InputError naming `source`, the header line and its text otherwise.
PlyHeader parsePlyHeader(const std::string& source, std::string_view bytes);

}  // namespace shadowvol::mesh_readers

#include "mesh_readers/ply_header.h"

#include <optional>

#include "mesh_readers/number_text.h"
#include "mesh_readers/text_lines.h"
#include "shadowvol/error.h"

namespace shadowvol::mesh_readers {
namespace {

constexpr std::size_t kMaxHeaderBytes = 64 * 1024;

std::optional<PlyType> typeNamed(std::string_view n) {
  struct Named {
    std::string_view a, b;
    PlyType t;
  };
  static constexpr Named kTypes[] = {
      {"char", "int8", PlyType::Int8},        {"uchar", "uint8", PlyType::UInt8},
      {"short", "int16", PlyType::Int16},     {"ushort", "uint16", PlyType::UInt16},
      {"int", "int32", PlyType::Int32},       {"uint", "uint32", PlyType::UInt32},
      {"float", "float32", PlyType::Float32}, {"double", "float64", PlyType::Float64},
  };
  for (const auto& k : kTypes)
    if (n == k.a || n == k.b) return k.t;
  return std::nullopt;
}

PlyType typeAt(std::string_view name, const TextPlace& at) {
  const auto t = typeNamed(name);
  if (!t)
    at.fail("unknown property type " + quoted(name) +
            " (char, uchar, short, ushort, int, uint, float, double or int8 ... float64)");
  return *t;
}

PlyProperty readProperty(std::string_view rest, const TextPlace& at) {
  PlyProperty p;
  std::string_view type = nextToken(rest);
  if (type == "list") {
    p.isList = true;
    p.countType = typeAt(nextToken(rest), at);
    if (!plyTypeIsInteger(p.countType)) at.fail("a list length must have an integer type");
    type = nextToken(rest);
  }
  p.type = typeAt(type, at);
  p.name = std::string(nextToken(rest));
  if (p.name.empty() || !isBlank(rest)) at.fail("expected \"property TYPE NAME\" or \"property list TYPE TYPE NAME\"");
  return p;
}

// Checks the declared counts against the body before anything trusts them.
void checkCountsFitBody(const std::string& source, const PlyHeader& h, std::size_t bodyBytes) {
  // What is left to hold the elements: bytes in binary, values (2 bytes each: a digit and a
  // separator, the last separator optional) in ASCII.
  std::uint64_t left = h.format == PlyFormat::Ascii ? (std::uint64_t(bodyBytes) + 1) / 2 : bodyBytes;
  for (const PlyElement& e : h.elements) {
    std::uint64_t row = 0;  // the smallest row: lists empty
    for (const PlyProperty& p : e.properties)
      row += h.format == PlyFormat::Ascii ? 1 : plyTypeSize(p.isList ? p.countType : p.type);
    if (row == 0 || e.count <= left / row) {
      left -= e.count * row;
      continue;
    }
    TextPlace{source, e.line, e.text}.fail(
        "the header declares " + std::to_string(e.count) + " " + e.name + " elements of at least " +
        std::to_string(row) + (h.format == PlyFormat::Ascii ? " values" : " bytes") + " each, more than the body of " +
        std::to_string(bodyBytes) + " bytes holds (truncated or corrupt)");
  }
}

}  // namespace

std::size_t plyTypeSize(PlyType t) {
  switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 0;
}

bool plyTypeIsInteger(PlyType t) {
  return t != PlyType::Float32 && t != PlyType::Float64;
}

PlyHeader parsePlyHeader(const std::string& source, std::string_view bytes) {
  refuseUtf16(bytes, source);
  LineReader lines(bytes);
  PlyHeader h;
  const auto magic = lines.next();
  if (!magic || magic->substr(0, 3) != "ply" || !isBlank(magic->substr(3)))
    throw InputError(source, "line 1", quoted(magic.value_or("")),
                     "cannot read the file as PLY: its first line must be \"ply\" (blanks after it allowed)");
  bool haveFormat = false;
  while (const auto line = lines.next()) {
    if (lines.offset() > kMaxHeaderBytes)
      throw InputError(source, lineField(lines.number()), "", "no end_header within the first 64 KiB");
    const TextPlace at{source, lines.number(), *line};
    std::string_view rest = *line;
    const std::string_view keyword = nextToken(rest);
    if (keyword == "comment" || keyword == "obj_info" || keyword.empty()) continue;
    if (keyword == "end_header") {
      if (!haveFormat) at.fail("the header has no format line");
      h.bodyOffset = lines.offset();
      h.bodyFirstLine = lines.number() + 1;
      checkCountsFitBody(source, h, bytes.size() - h.bodyOffset);
      return h;
    }
    if (keyword == "format") {
      if (haveFormat || !h.elements.empty()) at.fail("the format line must come once, before the elements");
      const std::string_view f = nextToken(rest), version = nextToken(rest);
      if (f == "ascii")
        h.format = PlyFormat::Ascii;
      else if (f == "binary_little_endian")
        h.format = PlyFormat::BinaryLittleEndian;
      else if (f == "binary_big_endian")
        h.format = PlyFormat::BinaryBigEndian;
      else
        at.fail("unknown format " + quoted(f) + " (ascii, binary_little_endian or binary_big_endian)");
      if (version != "1.0" || !isBlank(rest)) at.fail("expected \"format " + std::string(f) + " 1.0\"");
      haveFormat = true;
    } else if (keyword == "element") {
      if (!haveFormat) at.fail("an element before the format line");
      PlyElement e;
      e.name = std::string(nextToken(rest));
      const std::string_view countText = nextToken(rest);
      const auto count = parseInteger(countText);
      if (e.name.empty() || !count || *count < 0 || !isBlank(rest))
        at.fail("expected \"element NAME COUNT\" with a count of 0 or more");
      e.count = std::uint64_t(*count);
      e.line = lines.number();
      e.text = *line;
      h.elements.push_back(std::move(e));
    } else if (keyword == "property") {
      if (h.elements.empty()) at.fail("a property before any element");
      PlyProperty p = readProperty(rest, at);
      // Which of two same-named columns holds the value would be a guess (a hostile-input probe:
      // a second "x" was read): refused.
      for (const PlyProperty& q : h.elements.back().properties)
        if (q.name == p.name)
          at.fail("the element " + quoted(h.elements.back().name) + " names the property " + quoted(p.name) + " twice");
      h.elements.back().properties.push_back(std::move(p));
    } else if (h.elements.empty()) {
      // Ignored before the first element, like a comment: Blender 2.47 wrote its "Created by"
      // comment without the keyword (assimp-testmodels' Wuson.ply, the unseen wusonsoup.ply).
    } else {
      at.fail("unknown header line (expected element, property, comment or end_header)");
    }
  }
  throw InputError(source, lineField(lines.number()) + " (end of file)", "",
                   "the file ends inside the PLY header (no end_header)");
}

}  // namespace shadowvol::mesh_readers

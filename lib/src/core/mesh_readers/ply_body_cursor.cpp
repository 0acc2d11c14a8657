#include "mesh_readers/ply_body_cursor.h"

#include <bit>
#include <cstdio>
#include <cstring>

#include "mesh_readers/number_text.h"

namespace shadowvol::mesh_readers {
namespace {

template <class T>
double load(const char* p, bool swap) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, p, sizeof b);
  if (swap)
    for (std::size_t k = 0; k < sizeof b / 2; ++k) std::swap(b[k], b[sizeof b - 1 - k]);
  T v;
  std::memcpy(&v, b, sizeof v);
  return double(v);
}

double loadBinary(PlyType t, const char* p, bool swap) {
  switch (t) {
    case PlyType::Int8:
      return load<std::int8_t>(p, swap);
    case PlyType::UInt8:
      return load<std::uint8_t>(p, swap);
    case PlyType::Int16:
      return load<std::int16_t>(p, swap);
    case PlyType::UInt16:
      return load<std::uint16_t>(p, swap);
    case PlyType::Int32:
      return load<std::int32_t>(p, swap);
    case PlyType::UInt32:
      return load<std::uint32_t>(p, swap);
    case PlyType::Float32:
      return load<float>(p, swap);
    case PlyType::Float64:
      return load<double>(p, swap);
  }
  return 0;
}

}  // namespace

PlyBodyCursor::PlyBodyCursor(std::string_view bytes, const PlyHeader& header)
    : ascii_(header.format == PlyFormat::Ascii),
      swap_(header.format == PlyFormat::BinaryBigEndian),
      bytes_(bytes),
      pos_(header.bodyOffset),
      lines_(bytes, header.bodyOffset),
      firstLine_(header.bodyFirstLine) {
  static_assert(std::endian::native == std::endian::little, "the PLY reader assumes a little-endian host");
}

std::string_view PlyBodyCursor::nextToken() {
  lineEnded_ = false;
  for (;;) {
    token_ = mesh_readers::nextToken(rest_);
    if (!token_.empty()) return token_;
    if (rowOpen_) {  // a row's values stay on its line (at the file's end: truncated, ended())
      lineEnded_ = lines_.bytesLeft() > 0;
      return {};
    }
    const auto line = lines_.next();
    if (!line) return {};
    rest_ = *line;
  }
}

std::string PlyBodyCursor::rowLeftover() {
  if (!ascii_) return {};
  std::string_view rest = rest_;
  const std::string_view token = mesh_readers::nextToken(rest);
  return token.empty() ? std::string() : quoted(token);
}

std::string PlyBodyCursor::dataLeft() {
  rowOpen_ = false;
  if (ascii_) {
    const std::string_view token = nextToken();
    return token.empty() ? std::string() : quoted(token);
  }
  for (std::size_t k = pos_; k < bytes_.size(); ++k) {
    const char c = bytes_[k];
    if (c != '\n' && c != '\r' && c != ' ' && c != '\0') return std::to_string(bytes_.size() - pos_) + " bytes";
  }
  return {};
}

std::optional<double> PlyBodyCursor::read(PlyType t) {
  if (ascii_) {
    const std::string_view token = nextToken();
    ended_ = token.empty() && !lineEnded_;
    if (token.empty()) return std::nullopt;
    rowOpen_ = true;
    std::optional<double> v;
    if (plyTypeIsInteger(t)) {
      if (const auto i = parseInteger(token)) v = double(*i);
    } else {
      v = parseReal(token);
    }
    if (v) last_ = *v;
    return v;
  }
  const std::size_t size = plyTypeSize(t);
  ended_ = bytes_.size() - pos_ < size;
  if (ended_) return std::nullopt;
  last_ = loadBinary(t, bytes_.data() + pos_, swap_);
  pos_ += size;
  return last_;
}

bool PlyBodyCursor::skip(PlyType t, std::uint64_t n) {
  if (!ascii_) {
    ended_ = n > valuesLeft(t);
    if (ended_) return false;
    pos_ += std::size_t(n) * plyTypeSize(t);
    return true;
  }
  for (std::uint64_t k = 0; k < n; ++k)  // ends within the file: each read takes a token
    if (!read(t)) return false;
  return true;
}

std::uint64_t PlyBodyCursor::valuesLeft(PlyType t) const {
  if (ascii_) return (lines_.bytesLeft() + rest_.size() + 1) / 2;
  return (bytes_.size() - pos_) / plyTypeSize(t);
}

std::string PlyBodyCursor::where() const {
  if (!ascii_) return "";
  return " (line " + std::to_string(std::max(lines_.number() + firstLine_ - 1, firstLine_)) + ")";
}

std::string PlyBodyCursor::lastValue() const {
  if (ascii_) return quoted(token_);
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", last_);
  return buf;
}

}  // namespace shadowvol::mesh_readers

#include "mesh_readers/text_lines.h"

#include <cctype>
#include <cstdio>

#include "shadowvol/error.h"

namespace shadowvol::mesh_readers {

void refuseUtf16(std::string_view bytes, const std::string& source) {
  if (bytes.size() >= 2 && ((bytes[0] == '\xFF' && bytes[1] == '\xFE') || (bytes[0] == '\xFE' && bytes[1] == '\xFF')))
    throw InputError(source, "", "", "the file is UTF-16 text (it begins with a UTF-16 byte-order mark): save it as "
                                     "UTF-8 or ASCII");
}
namespace {

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\v' || c == '\f';
}

}  // namespace

std::optional<std::string_view> LineReader::next() {
  if (pos_ >= text_.size()) return std::nullopt;
  const std::size_t begin = pos_;
  std::size_t end = text_.find_first_of("\r\n", begin);
  if (end == std::string_view::npos) end = text_.size();
  pos_ = end;
  if (pos_ < text_.size() && text_[pos_] == '\r') ++pos_;
  if (pos_ < text_.size() && text_[pos_] == '\n') ++pos_;
  ++number_;
  return text_.substr(begin, end - begin);
}

std::string_view nextToken(std::string_view& rest) {
  std::size_t b = 0;
  while (b < rest.size() && isSpace(rest[b])) ++b;
  std::size_t e = b;
  while (e < rest.size() && !isSpace(rest[e])) ++e;
  const std::string_view token = rest.substr(b, e - b);
  rest.remove_prefix(e);
  return token;
}

std::string_view withoutComment(std::string_view line) {
  const std::size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

bool isBlank(std::string_view line) {
  for (const char c : line)
    if (!isSpace(c)) return false;
  return true;
}

std::string lineField(std::size_t lineNumber) {
  return "line " + std::to_string(lineNumber);
}

void TextPlace::fail(const std::string& problem) const {
  throw InputError(std::string(source), lineField(line), quoted(text), problem);
}

std::string lowerCase(std::string_view text) {
  std::string s(text);
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string quoted(std::string_view text) {
  constexpr std::size_t kMaxShown = 80;
  std::string s = "\"";
  for (std::size_t k = 0; k < text.size() && k < kMaxShown; ++k) {
    const auto c = static_cast<unsigned char>(text[k]);
    if (c < 0x20 || c >= 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", c);
      s += buf;
    } else {
      s += char(c);
    }
  }
  if (text.size() > kMaxShown) s += "...";
  s += '"';
  return s;
}

}  // namespace shadowvol::mesh_readers

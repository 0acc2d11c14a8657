// Lines and whitespace-separated tokens of a text mesh file held in memory, and how a line is
// quoted in an error message. Every loop over them advances by at least one byte, so reading is
// bounded by the size of the file.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace shadowvol::mesh_readers {

/// The UTF-8 byte-order mark some editors write at the start of a text file.
inline constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

/// `bytes` without a UTF-8 byte-order mark at its start.
inline std::string_view withoutBom(std::string_view bytes) {
  return bytes.substr(0, kUtf8Bom.size()) == kUtf8Bom ? bytes.substr(kUtf8Bom.size()) : bytes;
}

/// Refuses (InputError naming `source`) text that begins with a UTF-16 byte-order mark: its
/// every other byte is 0, so no line would read (a probe's UTF-16 OBJ checked as a valid empty
/// mesh). Save it as UTF-8 or ASCII.
void refuseUtf16(std::string_view bytes, const std::string& source);

/// Walks the lines of `text` from byte `offset`. A line ends at "\n", "\r\n" or a lone "\r"; the
/// terminator is not part of the line. The last line may lack one. From offset 0, a UTF-8
/// byte-order mark is skipped (offsets stay those of `text`).
class LineReader {
 public:
  explicit LineReader(std::string_view text, std::size_t offset = 0)
      : text_(text), pos_(offset == 0 ? text.size() - withoutBom(text).size() : offset) {}

  /// The next line, or nullopt at the end of the text.
  std::optional<std::string_view> next();
  /// The 1-based number of the line next() returned last (0 before the first call).
  std::size_t number() const { return number_; }
  /// The byte offset just past the terminator of the line next() returned last.
  std::size_t offset() const { return pos_; }
  /// Bytes after offset().
  std::size_t bytesLeft() const { return text_.size() - pos_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t number_ = 0;
};

/// Removes the first whitespace-separated token of `rest` from it and returns the token; empty
/// when `rest` holds only whitespace. Whitespace is space, tab, vertical tab and form feed.
std::string_view nextToken(std::string_view& rest);

/// The line up to its first '#' (the comment character of OBJ and OFF).
std::string_view withoutComment(std::string_view line);

/// True when the line holds nothing but whitespace.
bool isBlank(std::string_view line);

/// "line N" for the field of an InputError.
std::string lineField(std::size_t lineNumber);

/// A line of a text mesh file, for refusing it: fail() throws InputError(source, "line N",
/// the quoted line, problem).
struct TextPlace {
  std::string_view source;  ///< the file, as the message names it
  std::size_t line;         ///< 1-based line number
  std::string_view text;    ///< the whole line
  [[noreturn]] void fail(const std::string& problem) const;
};

/// `text` with its ASCII letters in lower case (keywords such as STL's SOLID, file extensions).
std::string lowerCase(std::string_view text);

/// The text in double quotes for an error message: at most 80 characters (then "..."), control
/// characters and bytes >= 0x80 written as \xNN, so a hostile line cannot flood the terminal.
std::string quoted(std::string_view text);

}  // namespace shadowvol::mesh_readers

// The values of a PLY body one after another, ASCII tokens or binary scalars.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "mesh_readers/ply_header.h"
#include "mesh_readers/text_lines.h"

namespace shadowvol::mesh_readers {

/// Reads the body after the header. Every read consumes at least one byte or fails, so a loop of
/// reads ends within the size of the file whatever the counts say.
class PlyBodyCursor {
 public:
  PlyBodyCursor(std::string_view bytes, const PlyHeader& header);

  /// The next value of type t (exact in double for every PLY type), or nullopt at the end of the
  /// body or, in ASCII, when the token is not a number of that kind (an integer for integer types).
  std::optional<double> read(PlyType t);
  /// Skips n values of type t; false when the body ends first.
  bool skip(PlyType t, std::uint64_t n);
  /// An upper bound on the values of type t still in the body (bytes / size, or bytes / 2 in ASCII).
  std::uint64_t valuesLeft(PlyType t) const;

  /// After the last element: the data left in the body, or an empty string when there is none
  /// (ASCII: no token left; binary: no byte left but whitespace or NUL padding). Describes it for
  /// a message: the token (ASCII) or the byte count (binary).
  std::string dataLeft();

  /// True when the last failed read found the end of the body (rather than a malformed token).
  bool ended() const { return ended_; }

  /// ASCII PLY holds one element a line: beginRow() lets the next read start a new line; the reads
  /// after it stay on that line, and one past its end fails with lineEnded() true. Binary: no-ops.
  void beginRow() { rowOpen_ = false; }
  /// True when the last failed read found its row's line ended (ASCII).
  bool lineEnded() const { return lineEnded_; }
  /// After a row's last value: what is left on its line (quoted), empty when nothing (ASCII).
  std::string rowLeftover();

  /// Where the cursor is, for messages: " (line N)" in ASCII, empty in binary.
  std::string where() const;
  /// The last ASCII token read (quoted), or the last binary value; for messages.
  std::string lastValue() const;

 private:
  std::string_view nextToken();

  bool ascii_;
  bool swap_;  // big-endian body on a little-endian host
  std::string_view bytes_;
  std::size_t pos_;   // binary: next byte
  LineReader lines_;  // ASCII
  std::string_view rest_, token_;
  std::size_t firstLine_;
  double last_ = 0;
  bool ended_ = false;
  bool rowOpen_ = false;    // ASCII: a value of the current row was read; stay on its line
  bool lineEnded_ = false;
};

}  // namespace shadowvol::mesh_readers

// The library's input errors in the command line's words. The library names its own terms
// (RenderOptions::imageWidth, ContextOptions::platform, ...); where one of them is set from a
// flag, the message shown names the flag instead ("command line: --size = 0x5: ...").
#pragma once

#include <span>
#include <string_view>

#include "shadowvol/error.h"

namespace shadowvol::cli {

/// A library field (InputError's source and field) and the flag that sets it. A field set by a
/// negating flag (refine snap: --no-snap) must not be named by a ${field} mark ("needs --no-snap"
/// would read backwards): marks name fields that their flag turns on or sets.
struct LibraryFieldFlag {
  std::string_view source, field, flag;
};

/// Every library field that a flag of `shadowvol` sets (render_options.cpp, cli_common.cpp).
std::span<const LibraryFieldFlag> libraryFieldFlags();

/// `e` with its source and field replaced by the command line's flag when the field is one that
/// a flag sets, and the fields its problem marks (error.h's MarkedProblem) spelled as their flags;
/// otherwise `e` unchanged. The value is kept; an OptionConflict stays one.
InputError asCommandLineError(const InputError& e);

}  // namespace shadowvol::cli

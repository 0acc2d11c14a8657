// The library's input errors in the command line's words. The library names its own terms
// (RenderOptions::imageWidth, ContextOptions::platform, ...); where one of them is set from a
// flag, the message shown names the flag instead ("command line: --size = 0x5: ...").
#pragma once

#include <span>
#include <string_view>

#include "shadowvol/error.h"

namespace shadowvol::cli {

/// A library field (InputError's source and field) and the flag that sets it.
struct LibraryFieldFlag {
  std::string_view source, field, flag;
};

/// Every library field that a flag of `shadowvol` sets (render_options.cpp, cli_common.cpp).
std::span<const LibraryFieldFlag> libraryFieldFlags();

/// `e` with its source and field replaced by the command line's flag when the field is one that
/// a flag sets; otherwise `e` unchanged. The value and the problem are kept.
InputError asCommandLineError(const InputError& e);

}  // namespace shadowvol::cli

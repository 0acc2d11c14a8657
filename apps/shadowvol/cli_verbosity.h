// --quiet and --verbose, options of every subcommand (given before or after its name).
//   quiet:   nothing on stdout but a --json document; no progress; warnings and errors still on stderr.
//   normal:  the summaries and progress each subcommand prints.
//   verbose: also a note on stderr at each stage (scene loaded, depth captured, GL context made,
//            each bench cell), stamped with the seconds since the command started.
#pragma once

#include <CLI/CLI.hpp>

namespace shadowvol::cli {

enum class Verbosity { Quiet, Normal, Verbose };

/// Adds -q/--quiet and -v/--verbose to the top-level app (with fallthrough, so that they work
/// after the subcommand's name too).
void addVerbosityOptions(CLI::App& app);

/// After parsing: records the level, and under --quiet (without --json) sends stdout to /dev/null.
void applyVerbosity(const CLI::App& app);

Verbosity verbosity();

/// printf-style note on stderr, "shadowvol: [  1.23 s] ...", only under --verbose.
[[gnu::format(printf, 1, 2)]] void verboseNote(const char* format, ...);

}  // namespace shadowvol::cli

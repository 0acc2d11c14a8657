// Whole-number options in decimal only: CLI11 reads "010" as octal 8 and "0x20" as 32, so
// `--resolution 010` built an 8 x 8 map without a word (a thirteenth probe's finding), while
// `--size 0064x048`, parsed by shadowvol itself, is decimal.
#pragma once

#include <CLI/CLI.hpp>

namespace shadowvol::cli {

/// Adds to every whole-number option of `app` and its subcommands (CLI11 type INT) a check that
/// refuses a value with a leading 0 or a base prefix ("010", "0x20", "-0b1"; "0" itself is fine):
/// a usage error (exit 2) naming the option and the value.
void requireDecimalIntegers(CLI::App& app);

}  // namespace shadowvol::cli

// Names a misspelt subcommand or option, with the nearest valid one, before CLI11 parses: without
// it `shadowvol buidl` said "A subcommand is required" and `build --hepl` "--out is required".
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

namespace shadowvol::cli {

/// The first unknown subcommand (argv[1]) or long option of the chosen subcommand, as a message
/// ("unknown subcommand \"buidl\"; did you mean \"build\"?"), or nullopt when every name is known.
/// A suggestion is made when the nearest name is within a third of its length in edit distance
/// (transpositions count 1).
std::optional<std::string> misspeltName(const CLI::App& app, int argc, const char* const* argv);

}  // namespace shadowvol::cli

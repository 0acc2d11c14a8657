#include "cli_integers.h"

#include <cctype>
#include <string>

namespace shadowvol::cli {
namespace {

// "" when `text` is not a whole number CLI11 would read in another base, else why not.
std::string decimalProblem(const std::string& text) {
  std::size_t at = text.empty() || (text[0] != '+' && text[0] != '-') ? 0 : 1;
  if (text.size() < at + 2 || text[at] != '0') return {};
  const char next = char(std::tolower(static_cast<unsigned char>(text[at + 1])));
  if (std::isdigit(static_cast<unsigned char>(next)) || next == 'x' || next == 'o' || next == 'b')
    return "write whole numbers in decimal without a leading 0 (\"" + text +
           "\" would be read in another base: 010 as octal 8, 0x20 as 32)";
  return {};
}

}  // namespace

void requireDecimalIntegers(CLI::App& app) {
  for (CLI::Option* option : app.get_options())
    if (option->get_type_name().rfind("INT", 0) == 0 || option->get_type_name().rfind("UINT", 0) == 0)
      option->check(CLI::Validator(decimalProblem, "", "decimal"));
  for (CLI::App* sub : app.get_subcommands({})) requireDecimalIntegers(*sub);
}

}  // namespace shadowvol::cli

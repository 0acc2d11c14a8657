#include "cli_suggest.h"

#include <algorithm>
#include <string_view>
#include <vector>

namespace shadowvol::cli {
namespace {

// Edit distance with adjacent transpositions (optimal string alignment): "buidl" is 1 from
// "build".
std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

std::string unknown(const std::string& what, const std::string& name, const std::vector<std::string>& known) {
  std::string best;
  std::size_t bestDistance = std::string::npos;
  for (const auto& k : known) {  // ties go to the first in declaration order
    const std::size_t d = editDistance(name, k);
    if (d < bestDistance) best = k, bestDistance = d;
  }
  std::string message = "unknown " + what + " \"" + name + "\"";
  if (!best.empty() && bestDistance * 3 <= std::max<std::size_t>(best.size(), 3)) message += "; did you mean \"" + best + "\"?";
  return message;
}

}  // namespace

std::optional<std::string> misspeltName(const CLI::App& app, int argc, const char* const* argv) {
  // The top level's own flags (--quiet, --verbose) may come first; --help and --version are CLI11's.
  std::vector<std::string> options;
  for (const CLI::Option* o : app.get_options()) {
    for (const auto& n : o->get_lnames()) options.push_back("--" + n);
    for (const auto& n : o->get_snames()) options.push_back("-" + n);
  }
  int first = 1;
  while (first < argc && argv[first][0] == '-') {
    const std::string arg = argv[first];
    if (arg == "--help" || arg == "-h" || arg == "--version" ||
        std::find(options.begin(), options.end(), arg) == options.end())
      return std::nullopt;  // CLI11 answers (help, version, or its own "unknown option")
    ++first;
  }
  if (first >= argc) return std::nullopt;
  const std::string name = argv[first];
  const CLI::App* sub = nullptr;
  std::vector<std::string> subcommands;
  for (const CLI::App* s : app.get_subcommands([](const CLI::App*) { return true; })) {
    subcommands.push_back(s->get_name());
    if (s->get_name() == name) sub = s;
  }
  if (!sub) return unknown("subcommand", name, subcommands);
  for (const CLI::Option* o : sub->get_options())
    for (const auto& n : o->get_lnames()) options.push_back("--" + n);
  for (int k = first + 1; k < argc; ++k) {
    const std::string_view arg = argv[k];
    if (arg == "--") break;  // what follows is positional
    if (arg.size() < 3 || arg.substr(0, 2) != "--") continue;
    const std::string option(arg.substr(0, arg.find('=')));
    if (std::find(options.begin(), options.end(), option) == options.end())
      return unknown(std::string("option of ") + name, option, options);
  }
  return std::nullopt;
}

}  // namespace shadowvol::cli

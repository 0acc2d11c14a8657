#include "cli_verbosity.h"

#include <chrono>
#include <cstdarg>
#include <cstdio>
#include <fcntl.h>
#include <unistd.h>

namespace shadowvol::cli {
namespace {

Verbosity gVerbosity = Verbosity::Normal;
bool gQuiet = false, gVerbose = false;
const auto gStart = std::chrono::steady_clock::now();

}  // namespace

void addVerbosityOptions(CLI::App& app) {
  auto* quiet = app.add_flag("-q,--quiet", gQuiet,
                             "Print nothing on stdout but a --json document, and no progress; warnings and errors still "
                             "go to stderr");
  app.add_flag("-v,--verbose", gVerbose,
               "Also note each stage on stderr (scene loaded, depth captured, GL context, every bench cell) with the "
               "seconds since the start")
      ->excludes(quiet);
  app.fallthrough();
}

void applyVerbosity(const CLI::App& app) {
  gVerbosity = gQuiet ? Verbosity::Quiet : gVerbose ? Verbosity::Verbose : Verbosity::Normal;
  if (gVerbosity != Verbosity::Quiet) return;
  bool json = false;
  for (const CLI::App* sub : app.get_subcommands())
    if (const CLI::Option* o = sub->get_option_no_throw("--json")) json = json || o->count() > 0;
  if (json) return;
  std::fflush(stdout);
  const int null = open("/dev/null", O_WRONLY);
  if (null >= 0) {
    dup2(null, STDOUT_FILENO);
    close(null);
  }
}

Verbosity verbosity() { return gVerbosity; }

void verboseNote(const char* format, ...) {
  if (gVerbosity != Verbosity::Verbose) return;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - gStart).count();
  std::fprintf(stderr, "shadowvol: [%7.2f s] ", s);
  va_list args;
  va_start(args, format);
  std::vfprintf(stderr, format, args);
  va_end(args);
  std::fputc('\n', stderr);
}

}  // namespace shadowvol::cli

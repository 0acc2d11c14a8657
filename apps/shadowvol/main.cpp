// shadowvol: explicit shadow-volume meshes from light depth maps. One subcommand per job.
#include <cstdio>
#include <exception>

#include "cli_common.h"
#include "cli_suggest.h"
#include "cli_verbosity.h"
#include "shadowvol/error.h"
#include "shadowvol/temporary_files.h"
#include "shadowvol/version.h"

int main(int argc, char** argv) {
  using namespace shadowvol;
  removeTemporaryFilesOnSignal();  // a killed command leaves no .tmp file behind
  CLI::App app{
      "shadowvol: turn a light's depth map into a closed shadow-volume mesh, render it with OpenGL "
      "(z-fail stencil) and check it by ray casting.\n"
      "Exit codes: 0 ok, 1 bad input (file, field and value named on stderr), 2 usage, 3 validation failed, "
      "4 runtime failure (no EGL display, Embree error), 130 bench interrupted (resume with the same command)."};
  app.set_version_flag("--version", "shadowvol " SHADOWVOL_VERSION);
  app.require_subcommand(1);
  cli::addVerbosityOptions(app);
  cli::setCommandLine(argc, argv);
  cli::Runner run;
  cli::registerSceneCommand(app, run);
  cli::registerDepthCommand(app, run);
  cli::registerBuildCommand(app, run);
#ifdef SHADOWVOL_WITH_GL
  cli::registerRenderCommand(app, run);
  cli::registerValidateCommand(app, run);
  cli::registerBenchCommand(app, run);
#endif
  if (const auto misspelt = cli::misspeltName(app, argc, argv)) {
    std::fprintf(stderr, "shadowvol: error: %s\nRun with --help for more information.\n", misspelt->c_str());
    return cli::kUsage;
  }
  try {
    app.parse(argc, argv);
    cli::applyVerbosity(app);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? cli::kOk : cli::kUsage;
  }
  try {
    return run();
  } catch (const InputError& e) {
    std::fprintf(stderr, "shadowvol: error: %s\n", e.what());
    return cli::kBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowvol: error: %s\n", e.what());
    return cli::kRuntimeFailure;
  }
}

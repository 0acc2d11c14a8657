// shadowvol: explicit shadow-volume meshes from light depth maps. One subcommand per job.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <new>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "cli_common.h"
#include "cli_errors.h"
#include "cli_integers.h"
#include "cli_suggest.h"
#include "cli_verbosity.h"
#include "shadowvol/error.h"
#include "shadowvol/temporary_files.h"
#include "shadowvol/version.h"

namespace {

// The command's exit code, or bad input when what it printed did not all reach standard output (a
// full disk behind `> file`, /dev/full): a twelfth probe's finding, where `--json > /dev/full` lost
// the document and still exited 0.
int stdoutWritten(int code) {
  std::cout.flush();
  if (std::fflush(stdout) == 0 && !std::ferror(stdout) && !std::cout.bad()) return code;
  std::fprintf(stderr, "shadowvol: error: standard output: writing failed (%s); what the command printed is incomplete\n",
               std::strerror(errno));
  return code == shadowvol::cli::kOk ? shadowvol::cli::kBadInput : code;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace shadowvol;
  removeTemporaryFilesOnSignal();  // a killed command leaves no .tmp file behind
#if defined(__GLIBC__)
  // Keep freed memory in the process: a frame allocates and frees megabytes (the depth map, the
  // explicit or silhouette mesh, the images, llvmpipe's own buffers). glibc's defaults can hand
  // them back to the kernel after each frame (heap trimming, or mmap for large blocks) to be
  // faulted in again on the next: 124 ms instead of 47 a frame in one case (docs/gpu.md "Frame
  // timing and the heap"). Setting either value turns glibc's adaptive threshold off, so both are
  // set: blocks up to 32 MB (glibc's largest threshold on 64-bit) come from the heap, and the heap
  // is trimmed only beyond 256 MB free. Costs only resident memory after a peak.
  mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
  mallopt(M_TRIM_THRESHOLD, 256 * 1024 * 1024);
#endif
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
  cli::registerCheckCommand(app, run);
#ifdef SHADOWVOL_WITH_GL
  cli::registerRenderCommand(app, run);
  cli::registerValidateCommand(app, run);
  cli::registerBenchCommand(app, run);
#endif
  cli::requireDecimalIntegers(app);
  if (const auto misspelt = cli::misspeltName(app, argc, argv)) {
    std::fprintf(stderr, "shadowvol: error: %s\nRun with --help for more information.\n", misspelt->c_str());
    return cli::kUsage;
  }
  try {
    app.parse(argc, argv);
    cli::applyVerbosity(app);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return stdoutWritten(code == 0 ? cli::kOk : cli::kUsage);  // --help and --version print
  }
  try {
    const int code = run();
    return stdoutWritten(code);
  } catch (const OptionConflict& e) {  // options that contradict each other: a usage error
    std::fprintf(stderr, "shadowvol: error: %s\nRun with --help for more information.\n",
                 cli::asCommandLineError(e).what());
    return cli::kUsage;
  } catch (const InputError& e) {
    std::fprintf(stderr, "shadowvol: error: %s\n", cli::asCommandLineError(e).what());
    return cli::kBadInput;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr,
                 "shadowvol: error: out of memory: this command needs more memory than the process may use (the "
                 "machine's memory or a ulimit); what it needs grows with the depth map's resolution, the image's size "
                 "and the triangles of the scene or mesh file, whichever it takes. No output was written.\n");
    return cli::kRuntimeFailure;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowvol: error: %s\n", e.what());
    return cli::kRuntimeFailure;
  }
}

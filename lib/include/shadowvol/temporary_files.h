// The temporary files of writeAtomically (mesh_io.h), removed when a signal ends the process:
// a command killed while writing (Ctrl-C, SIGTERM, SIGHUP) leaves neither the target nor the
// temporary beside it; and the files of a several-file result already in place (OutputSetGuard). The registry is a fixed table of paths that a signal handler can walk
// with async-signal-safe calls only (unlink, signal, raise).
#pragma once

#include <filesystem>

namespace shadowvol {

/// Installs handlers for SIGINT, SIGTERM and SIGHUP that remove every registered temporary file
/// and then end the process as the signal would have. The CLI calls it once, first thing; a
/// command that installs its own SIGINT handler later (bench) takes over SIGINT.
void removeTemporaryFilesOnSignal();

/// Registers a temporary path for the lifetime of the object (at most 16 at once; beyond that a
/// path is simply not registered). Used by writeAtomically.
class TemporaryFileGuard {
 public:
  explicit TemporaryFileGuard(const std::filesystem::path& path);
  ~TemporaryFileGuard();
  TemporaryFileGuard(const TemporaryFileGuard&) = delete;
  TemporaryFileGuard& operator=(const TemporaryFileGuard&) = delete;

 private:
  int slot_ = -1;
};

/// While it lives, the files writeAtomically puts in place are noted (noteOutputPlaced), and a
/// signal that ends the process as above removes them too: a command that writes several files as
/// one result (validate's report folder, render's image and its stencil images) leaves none of
/// them when it is killed half-way, as it leaves none when a write fails (a fourteenth probe's
/// Ctrl-C left a report folder of images without its report.json). Files it did not replace are
/// not touched; one it replaced is gone either way (the new file is removed, the old one was
/// replaced by it). A signal between a rename and its note leaves that file. Guards nest (the set
/// is the outermost's); at most 128 files are noted (more are not removed).
class OutputSetGuard {
 public:
  OutputSetGuard();
  ~OutputSetGuard();  ///< forgets the noted files: they stay
  OutputSetGuard(const OutputSetGuard&) = delete;
  OutputSetGuard& operator=(const OutputSetGuard&) = delete;
};

/// Notes `path`, just renamed into place by writeAtomically, while an OutputSetGuard lives.
void noteOutputPlaced(const std::filesystem::path& path);

}  // namespace shadowvol

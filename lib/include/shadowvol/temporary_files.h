// The temporary files of writeAtomically (mesh_io.h), removed when a signal ends the process:
// a command killed while writing (Ctrl-C, SIGTERM, SIGHUP) leaves neither the target nor the
// temporary beside it. The registry is a fixed table of paths that a signal handler can walk
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

}  // namespace shadowvol

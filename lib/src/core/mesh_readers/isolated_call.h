// A call into code we do not own, run in a child process (fork) with limits, so that a crash, an
// endless loop or a runaway allocation on a hostile file ends the child, not the caller. Used for
// the meshes that Assimp reads (assimp_reader.cpp).
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace shadowvol::mesh_readers {

struct IsolationLimits {
  int seconds = 60;                        ///< wall clock and CPU time of the child
  std::size_t addressSpace = 4ull << 30;   ///< RLIMIT_AS of the child (not set in ASan builds,
                                           ///< whose shadow memory needs terabytes of it)
  std::size_t outputBytes = 1200ull << 20; ///< the most the child may hand back
};

/// What the child reported.
struct IsolatedResult {
  bool ok = false;       ///< work() returned; `output` holds what it returned
  std::string output;    ///< work()'s bytes when ok, else a sentence saying what went wrong
                         ///< (work()'s exception message, a signal, a time-out, too much output)
};

/// Runs work() in a forked child under `limits` and returns its bytes. Never throws for what the
/// child does; throws std::runtime_error only if the process cannot fork or make a pipe.
/// The child shares nothing back but those bytes, and ends with _exit (no atexit handlers, no
/// flush of the parent's stdio buffers).
IsolatedResult runIsolated(const std::function<std::string()>& work, const IsolationLimits& limits = {});

}  // namespace shadowvol::mesh_readers

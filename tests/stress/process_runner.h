// Runs a program as a child process with a time limit, its stdout and stderr in files, and says
// how it ended: an exit code, a signal, or the time limit.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace shadowvol::stress {

struct ProcessResult {
  int exitCode = -1;      ///< the exit status when it exited; -1 when it died by a signal or timed out
  int signal = 0;         ///< the signal that killed it, 0 if none
  bool timedOut = false;  ///< killed by the time limit
  bool notRun = false;    ///< the shell could not start it (exit 126/127 of the shell, or 125 of timeout)
  double seconds = 0;     ///< wall time
  std::string stdoutText;
  std::string stderrText;
};

/// Runs argv[0] with the other arguments through `timeout` (coreutils): SIGTERM after
/// `timeoutSeconds`, SIGKILL 10 s later. No core files. stdout and stderr go to the two files and
/// are read back into the result.
ProcessResult runProcess(const std::vector<std::string>& argv, const std::filesystem::path& stdoutFile,
                         const std::filesystem::path& stderrFile, int timeoutSeconds);

/// One line for a failure list: "exit 4", "killed by signal 11 (Segmentation fault)", "timed out after 120 s".
std::string describeEnd(const ProcessResult& r, int timeoutSeconds);

/// The last non-empty line of `text`, at most `maxChars` long.
std::string lastLine(const std::string& text, std::size_t maxChars = 200);

}  // namespace shadowvol::stress

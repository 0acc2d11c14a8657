#include "process_runner.h"

#include <sys/wait.h>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace shadowvol::stress {
namespace {

std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string readFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

ProcessResult runProcess(const std::vector<std::string>& argv, const std::filesystem::path& stdoutFile,
                         const std::filesystem::path& stderrFile, int timeoutSeconds) {
  // `exec` replaces the shell by timeout, which re-raises a signal that killed the program: the
  // status below then says WIFSIGNALED. 124 is timeout's own "timed out", 137 its SIGKILL.
  std::string cmd = "ulimit -c 0; exec timeout -k 10 " + std::to_string(timeoutSeconds);
  for (const auto& a : argv) cmd.append(" ").append(shellQuote(a));
  cmd.append(" > ").append(shellQuote(stdoutFile.string()));
  cmd.append(" 2> ").append(shellQuote(stderrFile.string()));
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system(cmd.c_str());
  ProcessResult r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (status == -1) {
    r.notRun = true;
  } else if (WIFSIGNALED(status)) {
    r.signal = WTERMSIG(status);
  } else if (WIFEXITED(status)) {
    const int code = WEXITSTATUS(status);
    if (code == 124 || code == 137)
      r.timedOut = true;
    else if (code >= 125 && code <= 127)
      r.notRun = true;
    else if (code > 128 && code < 128 + 65)
      r.signal = code - 128;  // a shell reporting a signal
    else
      r.exitCode = code;
  }
  r.stdoutText = readFile(stdoutFile);
  r.stderrText = readFile(stderrFile);
  return r;
}

std::string describeEnd(const ProcessResult& r, int timeoutSeconds) {
  if (r.timedOut) return "timed out after " + std::to_string(timeoutSeconds) + " s";
  if (r.notRun) return "could not be started";
  if (r.signal) {
    const char* name = strsignal(r.signal);
    return "killed by signal " + std::to_string(r.signal) + (name ? std::string(" (") + name + ")" : "");
  }
  return "exit " + std::to_string(r.exitCode);
}

std::string lastLine(const std::string& text, std::size_t maxChars) {
  std::size_t end = text.find_last_not_of("\r\n \t");
  if (end == std::string::npos) return "";
  std::size_t begin = text.rfind('\n', end);
  begin = begin == std::string::npos ? 0 : begin + 1;
  std::string line = text.substr(begin, end + 1 - begin);
  if (line.size() > maxChars) line = line.substr(0, maxChars - 3) + "...";
  return line;
}

}  // namespace shadowvol::stress

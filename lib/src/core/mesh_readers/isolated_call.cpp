#include "mesh_readers/isolated_call.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <utility>

#if defined(__SANITIZE_ADDRESS__)
#define SV_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SV_ASAN 1
#endif
#endif

namespace shadowvol::mesh_readers {
namespace {

// The child's report on the pipe: one status byte, then the bytes.
constexpr char kDone = 'D', kFailed = 'F';

bool writeAll(int fd, const char* p, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w;
    n -= std::size_t(w);
  }
  return true;
}

// The process's virtual size in bytes (/proc/self/statm, first field, in pages); 0 if unknown.
std::size_t inheritedAddressSpace() {
  FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f) return 0;
  unsigned long long pages = 0;
  const bool read = std::fscanf(f, "%llu", &pages) == 1;
  std::fclose(f);
  return read ? std::size_t(pages) * std::size_t(::sysconf(_SC_PAGESIZE)) : 0;
}

[[noreturn]] void childMain(int fd, const std::function<std::string()>& work, const IsolationLimits& limits) {
  // The parent's handlers (temporary_files.cpp removes the parent's temporary files) are not ours.
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) std::signal(sig, SIG_DFL);
  const rlim_t seconds = rlim_t(limits.seconds);
  const rlimit cpu{seconds, seconds + 1};
  ::setrlimit(RLIMIT_CPU, &cpu);
#ifndef SV_ASAN
  // On top of what the child inherits (the caller may hold a GL context, Embree, a Python heap).
  const rlim_t as = rlim_t(inheritedAddressSpace() + limits.addressSpace);
  const rlimit asLimit{as, as};
  ::setrlimit(RLIMIT_AS, &asLimit);
#endif
  char status = kDone;
  std::string out;
  try {
    out = work();
  } catch (const std::bad_alloc&) {
    status = kFailed;
    out = "ran out of memory (the reader may use " + std::to_string(limits.addressSpace >> 20) + " MiB)";
  } catch (const std::exception& e) {
    status = kFailed;
    out = e.what();
  } catch (...) {
    status = kFailed;
    out = "failed with an unknown exception";
  }
  const bool sent = writeAll(fd, &status, 1) && writeAll(fd, out.data(), out.size());
  ::close(fd);
  ::_exit(sent ? 0 : 3);
}

std::string describeStatus(int status, int seconds) {
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    if (sig == SIGXCPU || sig == SIGKILL) return "took more than " + std::to_string(seconds) + " s (stopped)";
    const char* name = ::strsignal(sig);
    return "crashed (signal " + std::to_string(sig) + ", " + (name ? name : "?") + ")";
  }
  if (WIFEXITED(status)) return "ended without a result (exit " + std::to_string(WEXITSTATUS(status)) + ")";
  return "ended without a result";
}

}  // namespace

IsolatedResult runIsolated(const std::function<std::string()>& work, const IsolationLimits& limits) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  }
  if (pid == 0) {
    // The child ends with its parent: a killed command leaves no reader behind, holding the
    // descriptors it inherited (a second reader's finding: a killed sweep's folder lock).
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(3);  // the parent ended before the line above
    ::close(fds[0]);
    childMain(fds[1], work, limits);
  }
  ::close(fds[1]);
  // Read until the child closes its end, within the time and size limits.
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::seconds(limits.seconds);
  std::string bytes;
  std::string problem;
  char buf[1 << 16];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) {
      problem = "took more than " + std::to_string(limits.seconds) + " s (stopped)";
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int r = ::poll(&p, 1, int(left));
    if (r < 0 && errno == EINTR) continue;
    if (r == 0) continue;  // the deadline check above ends it
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // end of file: the child is done (or died)
    if (bytes.size() + std::size_t(n) > limits.outputBytes + 1) {
      problem = "produced more than " + std::to_string(limits.outputBytes >> 20) + " MiB of mesh (stopped)";
      break;
    }
    bytes.append(buf, std::size_t(n));
  }
  ::close(fds[0]);
  if (!problem.empty()) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  IsolatedResult result;
  if (!problem.empty()) {
    result.output = problem;
  } else if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && !bytes.empty()) {
    result.ok = bytes[0] == kDone;
    bytes.erase(0, 1);
    result.output = std::move(bytes);
  } else {
    result.output = describeStatus(status, limits.seconds);
  }
  return result;
}

}  // namespace shadowvol::mesh_readers

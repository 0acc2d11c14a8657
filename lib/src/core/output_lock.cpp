#include "shadowvol/output_lock.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <set>
#include <thread>
#include <utility>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "shadowvol/error.h"

namespace shadowvol {
namespace {

// The folders this thread holds (device, inode): flock conflicts between two descriptors of one
// process too, so a nested lock would wait for itself. Two threads serialize as two processes do.
thread_local std::set<std::pair<dev_t, ino_t>> held;

constexpr std::chrono::milliseconds kRetry{20};

}  // namespace

OutputLock::OutputLock(const std::filesystem::path& folder, std::chrono::milliseconds wait) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0 && (errno == ENOENT || errno == ENOTDIR))
    throw InputError(folder.string(), "", "", std::string("cannot open the output folder: ") + std::strerror(errno));
  if (fd < 0) return;  // a folder one may write in but not read (mode 0733): written unlocked, as before
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    ::close(fd);
    return;
  }
  const std::pair<dev_t, ino_t> key{st.st_dev, st.st_ino};
  if (held.count(key)) {  // nested: the outer lock covers this one
    ::close(fd);
    return;
  }
  const auto until = std::chrono::steady_clock::now() + wait;
  while (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    if (errno == EINTR) continue;
    if (errno != EWOULDBLOCK) {  // no flock here (ENOLCK, EBADF on NFS's emulation, EOPNOTSUPP)
      ::close(fd);
      return;
    }
    if (std::chrono::steady_clock::now() >= until) {
      ::close(fd);
      throw InputError(folder.string(), "", "",
                       "another run holds this folder while it writes its result (waited " +
                           std::to_string(std::chrono::duration_cast<std::chrono::seconds>(wait).count()) +
                           " s): give each run its own output, or let that run end first");
    }
    std::this_thread::sleep_for(kRetry);
  }
  held.insert(key);
  fd_ = fd;
}

OutputLocks::OutputLocks(const std::vector<std::filesystem::path>& folders) {
  std::vector<std::pair<std::pair<dev_t, ino_t>, std::filesystem::path>> order;
  for (const auto& f : folders) {
    struct stat st {};
    if (::stat(f.c_str(), &st) != 0)
      throw InputError(f.string(), "", "", std::string("cannot open the output folder: ") + std::strerror(errno));
    order.push_back({{st.st_dev, st.st_ino}, f});
  }
  std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t k = 0; k < order.size(); ++k)
    if (k == 0 || order[k].first != order[k - 1].first) locks_.emplace_back(order[k].second);
}

std::filesystem::path folderOf(const std::filesystem::path& file) {
  return file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  struct stat st {};
  if (::fstat(fd_, &st) == 0) held.erase({st.st_dev, st.st_ino});
  ::close(fd_);  // releases the flock
}

}  // namespace shadowvol

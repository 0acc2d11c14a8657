// OutputLock: one run at a time writes a result of several files into one folder. Two runs given
// the same output (a report folder, a depth map and its side file) wrote their files in turn and
// left a mixed set, both exiting 0 (a fourteenth probe's finding): the report of one run beside the
// images of the other. While an OutputLock lives this process holds an exclusive advisory lock
// (flock) on the folder; another run's lock on it waits for this one's release.
#pragma once

#include <chrono>
#include <filesystem>
#include <list>
#include <vector>

namespace shadowvol {

/// How long an OutputLock waits for another run's lock before it gives up (InputError naming the
/// folder): a result's write phase takes seconds; a run that holds its folder longer (bench, for
/// its whole sweep) is another run's to finish first.
inline constexpr std::chrono::seconds kOutputLockWait{60};

class OutputLock {
 public:
  /// Locks `folder` (which must exist), waiting up to `wait` for another process's lock on it.
  /// Throws InputError naming the folder when the wait runs out, or when it does not exist. Where
  /// the file system has no flock (some network file systems), or the folder cannot be opened for
  /// reading (a write-only drop folder), nothing is locked and nothing is said. Locks of one process
  /// nest: a second lock on a folder this thread holds is a no-op; two threads take turns.
  explicit OutputLock(const std::filesystem::path& folder, std::chrono::milliseconds wait = kOutputLockWait);
  ~OutputLock();  ///< releases the lock (the kernel releases it too when the process ends)
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

 private:
  int fd_ = -1;  // the folder, open while locked by this object; -1 when nested or unlocked
};

/// OutputLocks on several folders, taken in one order (by device and inode) whatever the order
/// they are given in, so that two runs naming the same folders the other way round cannot each hold
/// one and wait for the other (a second reader's `render --out A/x --stencil B/y` against
/// `--out B/x --stencil A/y`). A folder named twice is locked once.
class OutputLocks {
 public:
  explicit OutputLocks(const std::vector<std::filesystem::path>& folders);

 private:
  std::list<OutputLock> locks_;
};

/// The folder a file path writes into ("." for a bare name): what an OutputLock for it locks.
std::filesystem::path folderOf(const std::filesystem::path& file);

}  // namespace shadowvol

#include "shadowvol/temporary_files.h"

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>

#include <unistd.h>

namespace shadowvol {
namespace {

constexpr int kSlots = 16;
constexpr std::size_t kMaxPath = 4096;

struct Slot {
  std::atomic<bool> taken{false};  // claimed by a guard
  std::atomic<bool> ready{false};  // path written: the handler may unlink it
  char path[kMaxPath];
};
std::array<Slot, kSlots> slots;

extern "C" void onFatalSignal(int sig) {
  for (Slot& s : slots)
    if (s.ready.load()) ::unlink(s.path);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

}  // namespace

void removeTemporaryFilesOnSignal() {
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, onFatalSignal);
}

TemporaryFileGuard::TemporaryFileGuard(const std::filesystem::path& path) {
  const std::string p = path.string();
  if (p.size() >= kMaxPath) return;
  for (int k = 0; k < kSlots; ++k) {
    bool expected = false;
    if (slots[k].taken.compare_exchange_strong(expected, true)) {
      std::memcpy(slots[k].path, p.c_str(), p.size() + 1);
      slots[k].ready.store(true);
      slot_ = k;
      return;
    }
  }
}

TemporaryFileGuard::~TemporaryFileGuard() {
  if (slot_ < 0) return;
  slots[slot_].ready.store(false);
  slots[slot_].taken.store(false);
}

}  // namespace shadowvol

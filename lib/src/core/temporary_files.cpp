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

// The files an OutputSetGuard has seen placed (each caller takes the next slot).
constexpr int kPlacedSlots = 128;
std::array<Slot, kPlacedSlots> placed;
std::atomic<int> outputSetDepth{0};  // guards alive (they nest: writeDepthMap's inside a command's)
std::atomic<int> placedCount{0};

extern "C" void onFatalSignal(int sig) {
  for (Slot& s : slots)
    if (s.ready.load()) ::unlink(s.path);
  if (outputSetDepth.load() > 0)
    for (Slot& s : placed)
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

OutputSetGuard::OutputSetGuard() { outputSetDepth.fetch_add(1); }

OutputSetGuard::~OutputSetGuard() {
  if (outputSetDepth.fetch_sub(1) != 1) return;  // an outer guard keeps the set
  for (Slot& s : placed) s.ready.store(false);
  placedCount.store(0);
}

void noteOutputPlaced(const std::filesystem::path& path) {
  if (outputSetDepth.load() == 0) return;
  const std::string p = path.string();
  if (p.size() >= kMaxPath) return;
  const int k = placedCount.fetch_add(1);  // a slot of its own for each caller, whatever the thread
  if (k >= kPlacedSlots) return;
  std::memcpy(placed[k].path, p.c_str(), p.size() + 1);
  placed[k].ready.store(true);
}

TemporaryFileGuard::~TemporaryFileGuard() {
  if (slot_ < 0) return;
  slots[slot_].ready.store(false);
  slots[slot_].taken.store(false);
}

}  // namespace shadowvol

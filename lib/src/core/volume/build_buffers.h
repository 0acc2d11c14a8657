// Buffers and timing shared by the volume builder's stages (internal to shadowvol_core).
#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <limits>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "shadowvol/default_init_allocator.h"

namespace shadowvol::volume {

using Clock = std::chrono::steady_clock;
using Tri = std::array<std::uint32_t, 3>;
/// "No vertex" in index buffers.
inline constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

inline double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

/// Grid-sized scratch that every pass overwrites in full before reading: no zero-fill.
template <class T>
using Scratch = std::vector<T, DefaultInitAllocator<T>>;

/// Sizes a buffer to n elements with room for `capacity`. When it must grow, the old contents are
/// dropped (never copied) and Linux is asked for transparent huge pages before the first touch:
/// at 1024^2 the 4 KiB page faults of fresh buffers otherwise cost about as much as the build
/// itself. Only a hint (no effect where THP is off or on other systems). Contents as resize(n):
/// left unwritten for a DefaultInitAllocator vector (Scratch, VolumeMesh), so the first touch, and
/// its page faults, happen in the parallel pass that fills it; a buffer reused by VolumeBuilder
/// has no faults.
template <class V>
void sizeBuffer(V& v, std::size_t n, std::size_t capacity = 0) {
  using T = typename V::value_type;
  capacity = std::max(capacity, n);
  if (v.capacity() < capacity) {
    V fresh;
    fresh.reserve(capacity);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    constexpr std::uintptr_t kHuge = std::uintptr_t(2) << 20;
    if (capacity * sizeof(T) >= 2 * kHuge) {
      const auto begin = (reinterpret_cast<std::uintptr_t>(fresh.data()) + kHuge - 1) & ~(kHuge - 1);
      const auto end = (reinterpret_cast<std::uintptr_t>(fresh.data()) + fresh.capacity() * sizeof(T)) & ~(kHuge - 1);
      if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
    }
#endif
    v.swap(fresh);
  }
  v.resize(n);
}

}  // namespace shadowvol::volume

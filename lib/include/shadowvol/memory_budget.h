// What a command may allocate: requests whose estimated buffers exceed half of the machine's
// physical memory are refused before anything is allocated (a depth map's resolution, an image's
// --size), so that a typo's 16384 does not end in the kernel's out-of-memory kill.
#pragma once

#include <cstdint>
#include <string>

namespace shadowvol {

/// The machine's physical memory in bytes (0 when the system does not say).
std::uint64_t physicalMemoryBytes();

/// Throws InputError(source, field, value, "needs about N MiB, more than half of this machine's
/// M MiB") when `need` bytes exceed half of physicalMemoryBytes(); nothing when it is unknown.
void checkFitsMemory(std::uint64_t need, const std::string& source, const std::string& field,
                     const std::string& value);

/// Peak bytes of a W x H camera frame: rendered (28 a pixel), or also scored by ray casting, as
/// validate and bench do (107 a pixel). Measured on the default scene (README "Known limits":
/// render 1,833,976 KiB at 8192², 27.98 a pixel; validate 1,747,732 KiB at 4096², 106.7), rounded up.
inline std::uint64_t frameBytes(int width, int height, bool scored) {
  const std::uint64_t pixels = std::uint64_t(width > 0 ? width : 0) * std::uint64_t(height > 0 ? height : 0);
  return pixels * (scored ? 107 : 28);
}

}  // namespace shadowvol

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

}  // namespace shadowvol

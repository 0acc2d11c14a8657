#include "shadowvol/memory_budget.h"

#include <unistd.h>

#include "shadowvol/error.h"

namespace shadowvol {

std::uint64_t physicalMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && pageSize > 0 ? std::uint64_t(pages) * std::uint64_t(pageSize) : 0;
}

void checkFitsMemory(std::uint64_t need, const std::string& source, const std::string& field,
                     const std::string& value) {
  const std::uint64_t physical = physicalMemoryBytes();
  if (physical > 0 && need > physical / 2)
    throw InputError(source, field, value,
                     "needs about " + std::to_string(need >> 20) + " MiB, more than half of this machine's " +
                         std::to_string(physical >> 20) + " MiB");
}

}  // namespace shadowvol

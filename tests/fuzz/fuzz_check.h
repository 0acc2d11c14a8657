// The fuzz harnesses' one rule for a wrong result: say what is wrong and abort, which libFuzzer
// reports as a crash with the input saved.
#pragma once

#include <cstdio>
#include <cstdlib>

namespace fuzz {

inline void check(bool ok, const char* harness, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "%s: %s\n", harness, what);
  std::abort();
}

}  // namespace fuzz

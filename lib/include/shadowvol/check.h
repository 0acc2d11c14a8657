// Programmer-error checks (the first of the two error tiers, see style.md).
// A failed check prints the expression, both operands and the source location, then aborts.
// Bad user input is never checked with these: it throws shadowvol::InputError (error.h).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

namespace shadowvol::detail {
[[noreturn]] inline void checkFailed(const char* file, int line, const std::string& what) {
  std::fprintf(stderr, "shadowvol: internal check failed at %s:%d: %s\n", file, line, what.c_str());
  std::abort();
}
template <typename A, typename B>
std::string describeOperands(const char* expr, const A& a, const B& b) {
  std::ostringstream s;
  s << expr << " with " << a << " vs " << b;
  return s.str();
}
}  // namespace shadowvol::detail

#define SV_CHECK(cond)                                                 \
  do {                                                                 \
    if (!(cond)) ::shadowvol::detail::checkFailed(__FILE__, __LINE__, #cond); \
  } while (0)

#define SV_CHECK_OP(a, op, b)                                                                  \
  do {                                                                                         \
    const auto& sv_a_ = (a);                                                                   \
    const auto& sv_b_ = (b);                                                                   \
    if (!(sv_a_ op sv_b_))                                                                     \
      ::shadowvol::detail::checkFailed(                                                        \
          __FILE__, __LINE__, ::shadowvol::detail::describeOperands(#a " " #op " " #b, sv_a_, sv_b_)); \
  } while (0)

#define SV_CHECK_EQ(a, b) SV_CHECK_OP(a, ==, b)
#define SV_CHECK_NE(a, b) SV_CHECK_OP(a, !=, b)
#define SV_CHECK_LT(a, b) SV_CHECK_OP(a, <, b)
#define SV_CHECK_LE(a, b) SV_CHECK_OP(a, <=, b)
#define SV_CHECK_GT(a, b) SV_CHECK_OP(a, >, b)
#define SV_CHECK_GE(a, b) SV_CHECK_OP(a, >=, b)

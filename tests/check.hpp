// A minimal check harness for tubeform's C++ tests: each CHECK prints the
// failing expression with its values; main returns non-zero if any failed.
#pragma once

#include <cmath>
#include <cstdio>

namespace tftest {
inline int failures = 0;
inline int checks = 0;
} // namespace tftest

#define CHECK(cond)                                                                                                    \
  do {                                                                                                                 \
    ++tftest::checks;                                                                                                  \
    if (!(cond)) {                                                                                                     \
      ++tftest::failures;                                                                                              \
      std::printf("FAILED %s:%d: %s\n", __FILE__, __LINE__, #cond);                                                    \
    }                                                                                                                  \
  } while (0)

// |a - b| <= tol, reporting both values.
#define CHECK_NEAR(a, b, tol)                                                                                          \
  do {                                                                                                                 \
    ++tftest::checks;                                                                                                  \
    const double a_ = (a), b_ = (b);                                                                                   \
    if (!(std::fabs(a_ - b_) <= (tol))) {                                                                              \
      ++tftest::failures;                                                                                              \
      std::printf("FAILED %s:%d: %s = %.15g vs %s = %.15g (tol %g)\n", __FILE__, __LINE__, #a, a_, #b, b_,             \
                  (double)(tol));                                                                                      \
    }                                                                                                                  \
  } while (0)

// Non-zero if a check failed or if none was made (a test that checks nothing verifies nothing).
inline int ReportChecks(const char *name)
{
  std::printf("%s: %d checks, %d failed\n", name, tftest::checks, tftest::failures);
  if (tftest::checks == 0) std::printf("FAILED %s: no check was made\n", name);
  return tftest::failures || tftest::checks == 0 ? 1 : 0;
}

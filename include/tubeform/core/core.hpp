// The lowest layer of tubeform: error-code conventions, plane-strain sizes and
// the constants every component shares. Nothing here includes another
// tubeform header (docs/architecture.md, "Layers").
#pragma once

#include <petscsys.h>

#include <array>
#include <cstdio>
#include <string>

#ifndef PETSC_SUCCESS
#define PETSC_SUCCESS 0 // PETSc 3.18 predates the named constant.
#endif

// An HDF5 call's negative return as a PETSc error naming the call.
#define TF_CHECK_HDF5(expr) PetscCheck((expr) >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "HDF5 call failed: %s", #expr)

namespace tf {

// Voigt order used everywhere: {xx, yy, zz, xy}; strains carry gamma_xy = 2 eps_xy.
constexpr int kNumStress = 4;

// Number of displacement components per node (plane strain).
constexpr int kDim = 2;

// The r factor of an event that does not happen within the step (and the
// start value of a running minimum): larger than any factor a step can have.
constexpr double kNever = 1e300;

// Floor of a denominator that may be zero (a relative error of zero work).
constexpr double kTiny = 1e-300;

// A point or direction in the plane.
using Vec2 = std::array<double, 2>;

// printf into a string: numbers for a message by the C library's rules (PetscPrintf writes %g's integers as "3.").
template <class... T>
std::string Formatted(const char *fmt, T... v)
{
  const int n = std::snprintf(nullptr, 0, fmt, v...);
  if (n <= 0) return "";
  std::string s(n, '\0');
  std::snprintf(s.data(), s.size() + 1, fmt, v...);
  return s;
}

// A press's pass in words, as its messages name it: "first", "second", ... for pass 0, 1, ... (a press takes at
// most nine: io/options.hpp, kMaxPasses).
inline std::string PassOrdinal(int pass)
{
  static const char *const words[] = {"first", "second",  "third",  "fourth", "fifth",
                                      "sixth", "seventh", "eighth", "ninth"};
  return pass >= 0 && pass < 9 ? words[pass] : "later";
}

} // namespace tf

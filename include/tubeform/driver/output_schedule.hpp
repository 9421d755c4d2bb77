#pragma once

#include <cmath>

#include <petscsys.h>

namespace tf {

// When the driver writes fields: every `every`-th increment, or, with a path
// interval `dl` > 0 (the option -output_stroke as a fraction of the load
// path's stage), each time the load parameter crosses a multiple of dl and at
// every stage end. The last state is always written.
class OutputSchedule {
public:
  OutputSchedule(PetscInt every, double dl) : every_(every), dl_(dl) {}

  // After an increment ending at `lambda` (`stage_end`: on a breakpoint of the
  // path; `last`: the run ends here).
  bool Due(PetscInt inc, double lambda, bool stage_end, bool last)
  {
    if (dl_ <= 0) return last || inc % every_ == 0;
    const double bin = std::floor(lambda / dl_ + kBinTol);
    const bool due = last || stage_end || bin > written_;
    if (due) written_ = bin;
    return due;
  }

  // Where the schedule stands (a checkpoint keeps it).
  double written() const { return written_; }
  void Continue(double written) { written_ = written; }

private:
  // A step that ends within this fraction of dl below a multiple of dl has
  // reached it (steps end on lambda = k dl only up to round-off).
  static constexpr double kBinTol = 1e-9;
  PetscInt every_;
  double dl_;
  double written_ = 0; // the bin of the last write (the initial state is bin 0)
};

} // namespace tf

// The counts each step reports (StepReport: the guards' firings, the models' events, what set dt) summed from one
// output to the next, for the next row of diagnostics.csv (io/diagnostics.hpp). One table pairs each row column
// with the report's field it sums (step_counts.cpp): a new count is declared there once.
#pragma once

#include "io/diagnostics.hpp"
#include "mps/solver.hpp"

namespace mistfall {

class StepCounts {
 public:
  // Adds one step's report.
  void add(const StepReport& step);
  // Sets the row's counts to the sums since the last call (or the start) and starts the sums afresh.
  void moveInto(DiagnosticsRow& row);

 private:
  DiagnosticsRow sums_;
};

}  // namespace mistfall

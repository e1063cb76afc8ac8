// StepCounts (src/cli/step_counts.cpp): a diagnostics row's sums over the steps since the previous row. The largest
// shift is the row's maximum, and its particle and step start come from the same step; the next row starts afresh.
#include <gtest/gtest.h>

#include "cli/step_counts.hpp"

using namespace mistfall;

TEST(StepCounts, TheLargestShiftKeepsItsParticleAndStep) {
  struct Step {
    double shift;
    std::int64_t id;
    double time;
    std::size_t cuts;
  };
  const Step steps[] = {{0.1, 5, 0.10, 0}, {0.7, 9, 0.20, 1}, {0.3, 2, 0.30, 0}, {0.7, 4, 0.40, 2}};
  StepCounts counts;
  for (const Step& s : steps) {
    StepReport report;
    report.largest_shift = s.shift;
    report.largest_shift_id = s.id;
    report.largest_shift_time = s.time;
    report.shift_cuts = s.cuts;
    counts.add(report);
  }
  DiagnosticsRow row;
  counts.moveInto(row);
  EXPECT_EQ(0.7, row.largest_shift);
  EXPECT_EQ(9, row.largest_shift_id);  // the first of equal shifts
  EXPECT_EQ(0.20, row.largest_shift_time);
  EXPECT_EQ(3, row.shift_cuts);
  DiagnosticsRow next;
  counts.moveInto(next);
  EXPECT_EQ(0.0, next.largest_shift);
  EXPECT_EQ(-1, next.largest_shift_id);
  EXPECT_EQ(0, next.shift_cuts);
}

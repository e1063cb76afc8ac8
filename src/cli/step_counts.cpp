#include "cli/step_counts.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace mistfall {

namespace {

// A diagnostics.csv column and the StepReport field it sums (particle-steps, pair-steps or events).
struct CountColumn {
  std::int64_t DiagnosticsRow::*row;
  std::size_t StepReport::*step;
};

constexpr CountColumn kCounts[] = {
    {&DiagnosticsRow::gas_capped, &StepReport::gas_corrections_capped},
    {&DiagnosticsRow::gas_correction_capped, &StepReport::gas_correction_cuts},
    {&DiagnosticsRow::gas_speed_capped, &StepReport::gas_speed_cuts},
    {&DiagnosticsRow::collisions, &StepReport::collisions},
    {&DiagnosticsRow::collision_wall_limits, &StepReport::collision_wall_limits},
    {&DiagnosticsRow::liquid_wall_collisions, &StepReport::liquid_wall_collisions},
    {&DiagnosticsRow::gradient_fallbacks, &StepReport::gradient_fallbacks},
    {&DiagnosticsRow::thin_support, &StepReport::thin_support},
    {&DiagnosticsRow::neighbour_surfaces, &StepReport::neighbour_surfaces},
    {&DiagnosticsRow::dispersed_gas, &StepReport::dispersed_gas},
    {&DiagnosticsRow::entrained_swaps, &StepReport::entrained_gas_swaps},
    {&DiagnosticsRow::entrained_gas, &StepReport::entrained_gas},
    {&DiagnosticsRow::regularised_rows, &StepReport::regularised_rows},
    {&DiagnosticsRow::shift_cuts, &StepReport::shift_cuts},
    {&DiagnosticsRow::shift_bounded, &StepReport::shift_bounded},
    {&DiagnosticsRow::shift_wall_stops, &StepReport::shift_wall_stops},
    {&DiagnosticsRow::respacing_wall_stops, &StepReport::respacing_wall_stops},
    {&DiagnosticsRow::respacing_cuts, &StepReport::respacing_cuts},
    {&DiagnosticsRow::bubble_gas_wall_stops, &StepReport::bubble_gas_wall_stops},
    {&DiagnosticsRow::curvature_unfitted, &StepReport::curvature_unfitted},
    {&DiagnosticsRow::long_respacings, &StepReport::long_respacings},
    {&DiagnosticsRow::respacing_fluid_stops, &StepReport::respacing_fluid_stops},
    {&DiagnosticsRow::points_made, &StepReport::bubble_points_made},
    {&DiagnosticsRow::points_released, &StepReport::bubble_points_released},
    {&DiagnosticsRow::point_wall_stops, &StepReport::bubble_point_wall_stops},
    {&DiagnosticsRow::points_unpaired, &StepReport::bubble_points_unpaired},
    {&DiagnosticsRow::points_coalesced, &StepReport::bubble_points_coalesced},
    {&DiagnosticsRow::gap_water_floors, &StepReport::gap_water_floors},
    {&DiagnosticsRow::vent_crowded_out, &StepReport::vent_crowded_out},
    {&DiagnosticsRow::vent_liquid_stops, &StepReport::vent_liquid_stops},
};

}  // namespace

void StepCounts::add(const StepReport& step) {
  for (const CountColumn& c : kCounts) sums_.*c.row += static_cast<std::int64_t>(step.*c.step);
  sums_.gas_set_dt += step.dt_set_by_gas ? 1 : 0;
  if (step.liquid_dt > 0.0) sums_.liquid_dt_steps += step.dt / step.liquid_dt;
  if (step.largest_shift > sums_.largest_shift) {
    sums_.largest_shift = step.largest_shift;
    sums_.largest_shift_id = step.largest_shift_id;
    sums_.largest_shift_time = step.largest_shift_time;
  }
}

void StepCounts::moveInto(DiagnosticsRow& row) {
  for (const CountColumn& c : kCounts) row.*c.row = std::exchange(sums_.*c.row, 0);
  row.gas_set_dt = std::exchange(sums_.gas_set_dt, 0);
  row.liquid_dt_steps = std::exchange(sums_.liquid_dt_steps, 0.0);
  row.largest_shift = std::exchange(sums_.largest_shift, 0.0);
  row.largest_shift_id = std::exchange(sums_.largest_shift_id, -1);
  row.largest_shift_time = std::exchange(sums_.largest_shift_time, 0.0);
}

}  // namespace mistfall

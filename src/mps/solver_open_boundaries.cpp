// The step's open-boundary stages (MpsSolver, solver.hpp): the inflows' new water (open_boundaries.hpp), and at the
// step's end the vents' exchange with the ambient air (gas_vent.hpp), the particles that left the domain and the
// outflows' removals. Each stage keeps its own counts in the step's report and the run's state.
#include "mps/gas_vent.hpp"
#include "mps/open_boundaries.hpp"
#include "mps/solver.hpp"

namespace mistfall {

// The vents' particles at the step's start: which vent each is in and where it was. The vents drive them from there
// at the step's end, and their gas is the gas system's Dirichlet boundary during the step.
template <int D>
void MpsSolver<D>::holdVentStart() {
  if (config_.vents.empty()) return;
  vent_at_start_ = ventOf<D>(state_.particles, config_);
  vent_start_position_ = state_.particles.position;
}

// The inflows advance their driven water and release what crossed into the domain; the new water belongs to the
// liquid system and to no gas region.
template <int D>
void MpsSolver<D>::admitInflow(double dt) {
  report_.created = advanceInflows<D>(state_.particles, config_, dt);
  state_.created += report_.created;
  if (report_.created == 0) return;
  const std::size_t n = state_.particles.size();
  roles_.extendForLiquid(n);
  regions_.region_of.resize(n, -1);
  regions_.enclosed_particle.resize(n, 0);
}

// The step's end at the open boundaries: the vents let air in and out and take the water that reaches them; then
// particles outside the domain are marked escaped, the outflows remove what passed them, and the entrained points
// released in the step go.
template <int D>
void MpsSolver<D>::ventAndRemove(double dt) {
  if (!config_.vents.empty()) {
    const VentExchange vented =
        exchangeVentGas<D>(state_.particles, config_, vent_at_start_, vent_start_position_, dt,
                           phases_[static_cast<int>(Phase::Gas)].density, gravity_);
    report_.vented_in = vented.gas_in;
    report_.vented_out = vented.gas_out;
    report_.vent_crowded_out = vented.gas_crowded_out;
    report_.vent_liquid_stops = static_cast<std::size_t>(vented.liquid_stops);
    report_.vented_in_by_vent = vented.gas_in_by_vent;
    report_.vented_out_by_vent = vented.gas_out_by_vent;
    report_.vented_liquid_by_vent = vented.liquid_out_by_vent;
    report_.removed += vented.liquid_out;
    state_.vented_in += vented.gas_in;
    state_.vented_out += vented.gas_out;
    state_.removed += vented.liquid_out;
  }
  markEscaped();
  const std::int64_t outflow = removeOutflow<D>(state_.particles, config_);
  report_.removed += outflow;
  state_.removed += outflow;
  removeReleasedPoints();
}

#define MISTFALL_INSTANTIATE(D) \
  template void MpsSolver<D>::holdVentStart(); \
  template void MpsSolver<D>::admitInflow(double); \
  template void MpsSolver<D>::ventAndRemove(double);
MISTFALL_INSTANTIATE(2)
MISTFALL_INSTANTIATE(3)
#undef MISTFALL_INSTANTIATE

}  // namespace mistfall

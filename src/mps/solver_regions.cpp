// The gas regions of a step and the particles' roles in the pressure systems (MpsSolver, solver.hpp): delta_gl of
// eq. (7), which gas is enclosed by liquid (enclosed_gas.hpp) and who belongs to which system (phase_coupling.hpp).
#include "mps/bubble_gas_motion.hpp"
#include "mps/solver.hpp"

namespace mistfall {

// delta_gl of eq. (7): which gas regions are enclosed by liquid (enclosed_gas.hpp), then the roles of the
// particles in the two pressure systems. Without gas every active particle belongs to the liquid system.
template <int D>
void MpsSolver<D>::findBubbles() {
  if (oneEquation()) {  // every active particle in the one equation, each gas particle with its own momentum
    // Which gas is enclosed by water: in an open gas domain the rest of the gas may border empty space; with
    // entrained points, the pockets below a bubble's resolution that may become points (entrained_bubbles.hpp).
    regions_ = GasRegions{};
    auto& p = state_.particles;
    if (phase_present_[static_cast<int>(Phase::Gas)] &&
        (config_.numerics.gas_domain == GasDomain::Open || entrainedPoints())) {
      findGasRegions<D>(p, near_neighbours_, constants_.re_number_density, constants_.l0, regions_,
                        gasRegionOptions(&p.enclosed));
      p.enclosed = regions_.enclosed_particle;
      for (char e : regions_.enclosed) report_.bubbles += (e != 0);
    }
    assignCouplingRoles<D>(state_.particles, GasRegions{}, roles_);
    for (std::size_t i = 0; i < state_.particles.size(); ++i) {
      roles_.in_liquid_system[i] = isActive(state_.particles.kind[i]);
      roles_.open_gas[i] = 0;
    }
    return;
  }
  if (phase_present_[static_cast<int>(Phase::Gas)]) {
    auto& p = state_.particles;
    findGasRegions<D>(p, near_neighbours_, constants_.re_number_density, constants_.l0, regions_,
                      gasRegionOptions(&p.enclosed));
    // Gas that was open and is enclosed now joins the water's system and is carried by the water.
    std::vector<char> joined(p.size(), 0);
    bool any_joined = false;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const bool was_enclosed = i < p.enclosed.size() && p.enclosed[i];
      joined[i] = regions_.enclosed_particle[i] && !was_enclosed;
      any_joined = any_joined || joined[i];
    }
    if (any_joined) adoptLiquidVelocity<D>(p, near_neighbours_, joined, constants_.re_number_density);
    p.enclosed = regions_.enclosed_particle;
    for (char e : regions_.enclosed) report_.bubbles += (e != 0);
    report_.dispersed_gas = regions_.dispersed;
  } else {
    regions_ = GasRegions{};
  }
  assignCouplingRoles<D>(state_.particles, regions_, roles_,
                         static_cast<std::size_t>(config_.numerics.bubble_min_particles));
  report_.entrained_gas = roles_.entrained_count;
}

// The rules of findGasRegions from the case (enclosed_gas.hpp): in a closed gas domain a gas region below a
// bubble's resolution that touches liquid is entrained gas (0, off, when the gas borders open space); the join
// radius numerics.gas_region_link in metres (0: the number-density radius); numerics.dispersed_gas_fraction.
template <int D>
GasRegionOptions MpsSolver<D>::gasRegionOptions(const std::vector<char>* was_enclosed) const {
  GasRegionOptions options;
  options.was_enclosed = was_enclosed;
  if (config_.numerics.gas_domain == GasDomain::Closed)
    options.closed_small_region = static_cast<std::size_t>(config_.numerics.bubble_min_particles);
  // numerics.closed_pockets = "unvented": the vents' gas at the step's start is the atmosphere
  if (config_.numerics.closed_pockets == NumericsConfig::ClosedPockets::Unvented) options.vent_of = &vent_at_start_;
  options.join_radius = config_.numerics.gas_region_link * constants_.l0;
  options.dispersed_fraction = config_.numerics.dispersed_gas_fraction;
  options.dispersed_touch = config_.numerics.dispersed_gas_touch * constants_.l0;
  return options;
}

template <int D>
std::vector<BubbleStats> MpsSolver<D>::currentBubbles() {
  if (!phase_present_[static_cast<int>(Phase::Gas)]) return {};
  buildNeighbours();
  GasRegions regions;
  findGasRegions<D>(state_.particles, near_neighbours_, constants_.re_number_density, constants_.l0, regions,
                    gasRegionOptions(&state_.particles.enclosed));
  return bubbleStatistics<D>(state_.particles, regions, constants_.l0);
}

#define MISTFALL_INSTANTIATE(D) \
  template void MpsSolver<D>::findBubbles(); \
  template GasRegionOptions MpsSolver<D>::gasRegionOptions(const std::vector<char>*) const; \
  template std::vector<BubbleStats> MpsSolver<D>::currentBubbles();
MISTFALL_INSTANTIATE(2)
MISTFALL_INSTANTIATE(3)
#undef MISTFALL_INSTANTIATE

}  // namespace mistfall

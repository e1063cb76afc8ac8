// The step's collision stages (MpsSolver, solver.hpp): the collision model of collision.hpp after the prediction, and
// the guards that run it once more after the liquid's and the gas's corrections.
#include "mps/collision.hpp"
#include "mps/solver.hpp"

namespace mistfall {

template <int D>
void MpsSolver<D>::collide(double dt) {
  if (config_.numerics.collision_distance <= 0.0) return;
  const auto& p = state_.particles;
  // Momentum is shared by mass, so the liquid hardly feels the gas; it ignores open gas altogether. With
  // numerics.bubble_gas_inertia = "liquid" a bubble's gas that follows the liquid meets it with the water's inertia.
  const auto& open_gas = roles_.open_gas;
  const CollisionCount count = collideWhere(
      dt, [&](std::int64_t i, std::int32_t j) { return !(open_gas[j] && p.phase[i] == Phase::Liquid); },
      config_.numerics.bubble_gas_liquid_inertia && bubbleGasFollowsLiquid());
  report_.collisions = count.reversals;
  report_.collision_wall_limits = count.wall_limits;
}

// The collision model (collision.hpp) with numerics.collision_distance and collision_restitution, over the pairs
// (i, j) where j may change i's velocity, with numerics.collision_wall_limit; the reversals and wall limits it made.
// `bubble_gas_as_liquid`: a bubble's gas takes the water's mass (numerics.bubble_gas_inertia = "liquid").
template <int D>
template <class Affects>
CollisionCount MpsSolver<D>::collideWhere(double dt, Affects&& affects, bool bubble_gas_as_liquid) {
  auto& p = state_.particles;
  // A vent's gas moves as its column prescribes (gas_vent.hpp: the vent sets its place across the vent and its
  // velocity at the step's end), so it takes no share of a reversal: the particle meeting it takes it all, as at a
  // wall.
  constexpr double kPrescribedMass = 1e30;
  std::vector<double> mass(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    mass[i] = isVentGas(i) ? kPrescribedMass : particleMass(i, bubble_gas_as_liquid);
  const CollisionModel model{config_.numerics.collision_distance * constants_.l0,
                             config_.numerics.collision_restitution, config_.numerics.collision_wall_limit};
  return resolveCollisionPasses<D>(config_.numerics.collision_passes, p.position, p.velocity, p.kind, mass,
                                   near_neighbours_, model, dt, affects);
}

// numerics.gas_collision_after_correction: the collision model once more, after the gas system's correction, for gas
// approaching liquid, walls or dummies (the gas takes the whole reversal: it shares momentum by mass). Measured on
// waterfall_small at 3.78 s: a lone spray droplet (n = 1.1 against n0 = 6.5) held a lower pressure in the gas system
// than the air around it, the minimum-neighbour gradient pushed the air particle beside it onto it (0.64 -> 0.155 l0
// in one step, 11.9 m/s approach), and the next step's gas rows, with a pair at 0.155 l0, kicked the air to 1,300
// m/s and two particles out of the domain (docs/two-phase.md).
template <int D>
void MpsSolver<D>::collideCorrectedGas(double dt) {
  if (!config_.numerics.gas_collision_after_correction || config_.numerics.collision_distance <= 0.0) return;
  const auto& p = state_.particles;
  const CollisionCount count = collideWhere(dt, [&](std::int64_t i, std::int32_t j) {
    return roles_.inGasSystem(i) && !isVentGas(static_cast<std::size_t>(i)) &&
           (p.phase[j] == Phase::Liquid || isFixed(p.kind[j]));
  });
  report_.collisions += count.reversals;
  report_.collision_wall_limits += count.wall_limits;
}

// numerics.liquid_collision_after_correction: the collision model once more, after the liquid correction, for water
// approaching a wall or dummy particle (the water takes the whole reversal). The mirrored walls hold each particle's
// own pressure (wall_mirror.hpp), so a particle the correction sends into a corner meets no pressure that sends it
// back: traced at 5 mm (runs/wf5_tr30, docs/waterfall.md), the collision after the prediction turned water particle
// 13312 away from the floor/weir corner every step and the correction turned it in again; over its last 20 ms the
// prediction carried it 0.3-0.4 l0 into the corner on the velocity the correction left, until it passed into the
// weir at 2.93 s and was lost.
template <int D>
void MpsSolver<D>::collideCorrectedLiquid(double dt) {
  if (!config_.numerics.liquid_collision_after_correction || config_.numerics.collision_distance <= 0.0) return;
  const auto& p = state_.particles;
  const CollisionCount count = collideWhere(dt, [&](std::int64_t i, std::int32_t j) {
    return p.phase[i] == Phase::Liquid && roles_.in_liquid_system[i] && isFixed(p.kind[j]);
  });
  report_.liquid_wall_collisions = count.reversals;
  report_.collision_wall_limits += count.wall_limits;
}

#define MISTFALL_INSTANTIATE(D) \
  template void MpsSolver<D>::collide(double); \
  template void MpsSolver<D>::collideCorrectedGas(double); \
  template void MpsSolver<D>::collideCorrectedLiquid(double);
MISTFALL_INSTANTIATE(2)
MISTFALL_INSTANTIATE(3)
#undef MISTFALL_INSTANTIATE

}  // namespace mistfall

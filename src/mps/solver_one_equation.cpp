// numerics.coupling = "one_equation": water and air in one pressure equation (docs/two-phase.md), the step's
// pressure stage in place of the liquid system, the bubbles and the gas system. Every fluid particle of both
// phases carries its own pressure and momentum; eqs. (5)-(8) become the variable-density projection
//   u^{n+1} = u* - dt (1/rho) grad p,   div u^{n+1} = 0 (water),   div u^{n+1} = -(p - p^n)/(rho c^2 dt) (air, eq. (17)),
// so that row i reads (pressure_poisson.hpp, the variable-density form)
//   2D0/(n0 lambda) sum_j w_ij (p_i - p_j)/rho_ij + p_i/(rho_i dt^2 c_i^2)
//     = -<div u*>_i/dt + gamma/dt^2 (n*_i - n0)/n0 + (1 - gamma) p_i^n/(rho_i dt^2 c_i^2) + known terms,
// with the interparticle density rho_ij of interface_density.hpp (exact for a straight interface at rest) and the
// stabilised scheme's known terms (solver_liquid_stabilised.cpp) written per unit density: a mirrored wall seen
// from i holds p_i + rho_i g . r_ib (the pair's term g . r_ib), the missing neighbours of a truncated support carry
// the last step's (1/rho) grad p, and a free-surface particle holds (l0/2) rho_s |(1/rho) grad p|_s. The correction
// is the corrected gradient (Khayyer & Gotoh 2011) of the pair terms (p_j - p_i)/rho_ij. Water and air at rest
// under gravity are then an exact solution, as still water is on the stabilised scheme.
#include "mps/interface_density.hpp"
#include "mps/laplacian_consistency.hpp"
#include "mps/number_density.hpp"
#include "mps/gas_vent.hpp"
#include "mps/gap_water_floor.hpp"
#include "mps/inflow_pressure.hpp"
#include "mps/solver.hpp"
#include "mps/surface_pressure.hpp"
#include "mps/wall_mirror.hpp"

namespace mistfall {

// <(1/rho) grad p>_i: the corrected gradient of (p_j - p_i)/rho_ij (mirrored walls: g . r_ij).
template <int D>
CorrectedGradient<D> MpsSolver<D>::oneEquationGradient(std::size_t i, bool repulsive) const {
  const auto& p = state_.particles;
  const auto& rho = problem_.density_of;
  const auto& phi = problem_.interface_distance;
  auto carries = [&](std::int32_t j) { return problem_.takes_part[j] != 0 || isMirroredWall(p.kind[j]); };
  auto difference = [&](std::int32_t j, const Vec<D>& rij) {
    if (isMirroredWall(p.kind[j])) return gravity_.dot(rij);
    return (p.pressure[j] - p.pressure[i]) / pairDensity(rho[i], rho[j], phi[i], phi[j]);
  };
  return gradientWithRepulsion(i, repulsive, carries, difference);
}

template <int D>
void MpsSolver<D>::solveOneEquationPressure(double dt) {
  auto& p = state_.particles;
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  const double beta_n0 = config_.numerics.surface_threshold * constants_.n0;
  const bool closed = config_.numerics.gas_domain == GasDomain::Closed;
  auto gasWithin = [&](std::int64_t i) {
    bool any = false;
    forEachPairWithin<D>(i, p.position, near_neighbours_, constants_.re_number_density,
                         [&](std::int32_t j) { return p.kind[j] == ParticleKind::Fluid && p.phase[j] == Phase::Gas; },
                         [&](std::int32_t, const Vec<D>&, double, double) { any = true; });
    return any;
  };
  auto vented = [&](std::int64_t i) { return isVentGas(static_cast<std::size_t>(i)); };
  // Who takes part: every fluid particle; walls are mirrored (no unknown). Densities, sound speeds, phi.
  problem_.takes_part.assign(n, 0);
  problem_.unknown.assign(n, 0);
  problem_.carries_velocity.assign(n, 0);
  problem_.sound_speed.assign(n, std::numeric_limits<double>::infinity());
  problem_.density_of.assign(n, phases_[static_cast<int>(Phase::Liquid)].density);
  // The inflow's driven water (open_boundaries.hpp) takes part as water, as in the liquid system: an unknown, its
  // velocity in the divergence, not corrected.
  auto inEquation = [&](std::int64_t i) {
    return p.kind[i] == ParticleKind::Fluid || p.kind[i] == ParticleKind::Inflow;
  };
  for (std::int64_t i = 0; i < n; ++i) {
    if (!inEquation(i)) continue;
    const PhaseProperties& phase = phases_[static_cast<int>(p.phase[i])];
    problem_.takes_part[i] = 1;
    problem_.carries_velocity[i] = 1;
    problem_.density_of[i] = phase.density;
    problem_.sound_speed[i] = phase.sound_speed;
    // A void inside the fluid is not empty space: in a closed box nothing is a free surface; in an open one a
    // particle short of neighbours is, if it is gas that water does not enclose (the air's top; a bubble's gas always
    // carries an unknown) or water with no gas around it (water bordering empty space, not a gap at an interface).
    const bool sparse = p.number_density[i] < beta_n0;
    const bool short_of_neighbours = sparse || !hasFullNeighbourhood(i, roles_.in_liquid_system);
    auto bordersSpace = [&] { return p.phase[i] == Phase::Gas ? !p.enclosed[i] : !gasWithin(i); };
    problem_.unknown[i] = closed || !short_of_neighbours || !bordersSpace();  // bordersSpace only when short
    if (!problem_.unknown[i] && !sparse) ++report_.neighbour_surfaces;
    if (vented(i)) {  // a vent's gas holds the ambient pressure (below); numerics.vent_outlet
      problem_.unknown[i] = 0;
      if (config_.numerics.vent_zero_gradient) problem_.carries_velocity[i] = 0;
    }
  }
  problem_.sourceless = harmonicInflowRows<D>(p, config_);  // [[inflow]] pressure = "harmonic"
  problem_.interface_distance = interfaceDistances<D>(p, neighbours_, search_.radius(), constants_.l0);
  makeThinRowsFreeSurface();  // solver_liquid_stabilised.cpp
  // The known terms, from the last step's pressure at r* (solver_liquid_stabilised.cpp, per unit density).
  std::vector<Vec<D>> last(n, Vec<D>::Zero());
  surface_pressure_.assign(n, 0.0);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (!problem_.takes_part[i]) continue;
    last[i] = oneEquationGradient(i).value;
    if (!problem_.unknown[i])
      surface_pressure_[i] = problem_.density_of[i] * surfaceParticlePressure<D>(last[i], constants_.l0);
  }
  // The vents' gas (ventGasPressure, solver.hpp): the ambient pressure, a Dirichlet value like a surface particle's.
  for (std::int64_t i = 0; i < n; ++i)
    if (vented(i)) surface_pressure_[i] = ventGasPressure(static_cast<std::size_t>(i), problem_.density_of[i]);
  findSurfaceTangents(last);
  const PressureSourceTerm source = sourceTermFor(config_.numerics, dt);  // pressure_poisson.hpp
  problem_.extra_rhs.assign(n, 0.0);
  problem_.velocity_group.clear();
  const double factor = constants_.laplacianFactor();
  const auto& rho = problem_.density_of;
  const auto& phi = problem_.interface_distance;
  auto inLaplacian = [&](std::int32_t j) { return problem_.takes_part[j] || isMirroredWall(p.kind[j]); };
  auto atSurface = [&](std::int32_t j) { return surface_pressure_[j] != 0.0; };
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (!problem_.unknown[i]) continue;
    double extra = mirroredWallTerm<D>(i, p.position, p.velocity, p.kind, neighbours_, constants_, 1.0, gravity_, dt,
                                       !problem_.isSourceless(i));  // inflow_pressure.hpp
    extra += laplacianConsistencyTerm<D>(i, p.position, neighbours_, constants_, last[i], inLaplacian);
    double surface = 0.0;
    forEachPairWithin<D>(i, p.position, neighbours_, constants_.re_laplacian, atSurface,
                         [&](std::int32_t j, const Vec<D>&, double, double w) {
                           surface += w * surface_pressure_[j] / pairDensity(rho[i], rho[j], phi[i], phi[j]);
                         });
    // eq. (17)'s memory on the compressible rows (pressure_poisson.hpp), per unit density
    extra += compressibleMemoryTerm(source, p.pressure[i], dt, problem_.sound_speed[i]) / rho[i];
    problem_.extra_rhs[i] = extra + factor * surface;
  }
  assemblePressureSystem<D>(p, p.number_density, neighbours_, constants_, problem_, source, dt, system_,
                            &near_neighbours_);
  solveSystem(p.pressure, "liquid", report_.ppe_iterations);
  report_.ppe_unknowns = system_.particle_of.size();
  for (std::int64_t i = 0; i < n; ++i)
    if (inEquation(i)) p.pressure[i] = surface_pressure_[i];
  for (std::size_t r = 0; r < system_.particle_of.size(); ++r) p.pressure[system_.particle_of[r]] = pressure_unknowns_[r];
  if (config_.numerics.gap_water_floor)  // gap_water_floor.hpp
    report_.gap_water_floors = floorGapWaterPressure<D>(p, near_neighbours_, constants_.re_number_density, beta_n0,
                                                        phases_[static_cast<int>(Phase::Gas)].density, gravity_,
                                                        p.pressure);
}

// u' = -dt <(1/rho) grad p>, u = u* + u', r = r* + dt u', for every fluid particle of both phases.
template <int D>
void MpsSolver<D>::correctOneEquation(double dt) {
  auto& p = state_.particles;
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  std::vector<Vec<D>> change(n, Vec<D>::Zero());
  std::size_t fallbacks = 0;
#pragma omp parallel for schedule(static) reduction(+ : fallbacks)
  for (std::int64_t i = 0; i < n; ++i) {
    if (p.kind[i] != ParticleKind::Fluid) continue;
    const auto gradient = oneEquationGradient(i, true);
    fallbacks += gradient.fell_back;
    change[i] = -dt * gradient.value;
  }
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (p.kind[i] != ParticleKind::Fluid) continue;
    p.velocity[i] += change[i];
    p.position[i] += dt * change[i];
  }
  report_.gradient_fallbacks = fallbacks;
}

#define MISTFALL_INSTANTIATE(D)                                                          \
  template CorrectedGradient<D> MpsSolver<D>::oneEquationGradient(std::size_t, bool) const; \
  template void MpsSolver<D>::solveOneEquationPressure(double);                        \
  template void MpsSolver<D>::correctOneEquation(double);
MISTFALL_INSTANTIATE(2)
MISTFALL_INSTANTIATE(3)
#undef MISTFALL_INSTANTIATE

}  // namespace mistfall

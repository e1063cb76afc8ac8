#include <algorithm>
// numerics.scheme = "stabilised": the parts of the liquid's pressure stage that differ from the paper's MPS
// (docs/validation.md). Still water is an exact equilibrium of the discrete equations (hydrostatic pressure, zero
// velocity, whatever the arrangement of the particles), which the paper's scheme is not:
//  * mirrored walls (wall_mirror.hpp, after Adami, Hu & Adams 2012): walls carry no unknown; seen from a fluid
//    particle they hold its pressure continued hydrostatically, and their velocity enters the divergence source;
//  * the first-order consistent Laplacian (laplacian_consistency.hpp) and the free-surface particles' pressure half
//    a spacing inside the surface (surface_pressure.hpp), both from the last step's corrected gradient;
//  * the corrected gradient (corrected_gradient.hpp, Khayyer & Gotoh 2011) in the correction;
//  * the repulsive term of numerics.pressure_repulsion in the correction (pressure_repulsion.hpp), and the particle
//    shifting of numerics.particle_shifting after it (particle_shifting.hpp), both along the surface near it;
//  * rows whose liquid-side support is below numerics.liquid_support_fraction of n0 are free surface (counted).
#include "mps/laplacian_consistency.hpp"
#include "mps/number_density.hpp"
#include "mps/particle_shifting.hpp"
#include "mps/shift_stability.hpp"
#include "mps/solver.hpp"
#include "mps/surface_pressure.hpp"
#include "mps/wall_mirror.hpp"
#include "mps/wall_stop.hpp"

namespace mistfall {

// The corrected gradient of the liquid's pressure at particle i (mirrored walls hold p_i + rho g . r_ib); with
// `repulsive`, on a particle carrying an unknown, plus the repulsive term (pressure_repulsion.hpp).
template <int D>
CorrectedGradient<D> MpsSolver<D>::stabilisedGradient(std::size_t i, bool repulsive) const {
  const auto& p = state_.particles;
  const double rho = phases_[static_cast<int>(Phase::Liquid)].density;
  const auto& in_system = roles_.in_liquid_system;
  auto carries = [&](std::int32_t j) { return in_system[j] != 0; };
  auto difference = [&](std::int32_t j, const Vec<D>& rij) {
    return isMirroredWall(p.kind[j]) ? rho * gravity_.dot(rij) : p.pressure[j] - p.pressure[i];
  };
  return gradientWithRepulsion(i, repulsive, carries, difference);
}

// After the unknowns are chosen (solveLiquidPressure): thin rows become free surface, then the known terms of every
// row (problem_.extra_rhs) and the Dirichlet values of the free-surface particles (surface_pressure_), from the
// last step's pressure p^n at r*.
// Rows whose liquid support (the liquid taking part, within the Laplacian radius) is below
// numerics.liquid_support_fraction of n0 would be set by the mirrored walls or a bubble's gas alone: they become free
// surface (counted in report_.thin_support). Bubble rows and walls are left alone. The bubbles' gas is not support:
// it is an unknown of the liquid's density here (bubble_pressure.hpp), and a droplet among it with an unknown of its
// own was a particle in incompressible water, held by a pressure of tens of kPa (the divergence of the 5 mm
// waterfall at 1.07 s, docs/waterfall.md); such a row holds its bubble's pressure (stabilisedPressureTerms).
template <int D>
void MpsSolver<D>::makeThinRowsFreeSurface() {
  const auto& p = state_.particles;
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  const double support = config_.numerics.liquid_support_fraction * constants_.n0_laplacian;
  auto fluidSide = [&](std::int32_t j) { return problem_.takes_part[j] != 0 && !roles_.enclosed_gas[j]; };
  std::size_t thin = 0;
  thin_row_.assign(n, 0);
#pragma omp parallel for schedule(static) reduction(+ : thin)
  for (std::int64_t i = 0; i < n; ++i) {
    if (!problem_.unknown[i] || roles_.enclosed_gas[i] || p.kind[i] != ParticleKind::Fluid) continue;
    if (numberDensityAt<D>(i, p.position, neighbours_, constants_.re_laplacian, fluidSide) < support) {
      problem_.unknown[i] = 0;
      thin_row_[i] = 1;
      ++thin;
    }
  }
  report_.thin_support = thin;
}

// A free-surface liquid particle with a bubble's gas within the Laplacian radius lies on that bubble's inside (a
// droplet in it, or a film one particle thick): its Dirichlet value is the bubble's pressure of the last step, P_B^n
// (the weighted mean over that gas, uniform in one bubble). None: no bubble's gas within reach.
template <int D>
std::optional<double> MpsSolver<D>::bubbleSidePressure(std::size_t i) const {
  const auto& p = state_.particles;
  double sum = 0.0, weight = 0.0;
  forEachPairWithin<D>(i, p.position, neighbours_, constants_.re_laplacian,
                       [&](std::int32_t j) { return roles_.enclosed_gas[j] != 0 && problem_.takes_part[j] != 0; },
                       [&](std::int32_t j, const Vec<D>&, double, double w) { sum += w * p.pressure[j], weight += w; });
  if (weight == 0.0) return std::nullopt;
  return sum / weight;
}

// numerics.thin_row_pressure = "liquid": the Dirichlet value of a thin row (makeThinRowsFreeSurface), the last
// step's pressure of the liquid within the Laplacian radius continued hydrostatically to it, as the mirrored walls
// continue a particle's own (wall_mirror.hpp, continuedPressureAt):
//   p_i = sum_j w_ij (p_j^n + rho g . (r_i - r_j)) / sum_j w_ij.
// A thin row is thin because walls, not void, fill its neighbourhood: a particle crowded into a corner, with a
// quadrant of water beside it, or a film on a wall. The free surface's value (half a spacing of the last gradient)
// gave a corner particle tens of pascals under water at a kilopascal, and the water around pushed it into the walls
// (LiquidWallCollision.*, docs/waterfall.md, forty-fifth session). A film's liquid is at the surface's pressure, so
// its rows keep about that. None: no liquid within reach.
template <int D>
std::optional<double> MpsSolver<D>::thinRowLiquidPressure(std::size_t i, double rho) const {
  const auto& p = state_.particles;
  auto liquid = [&](std::int32_t j) {
    return p.kind[j] == ParticleKind::Fluid && p.phase[j] == Phase::Liquid && problem_.takes_part[j] != 0 &&
           !roles_.enclosed_gas[j];
  };
  return continuedPressureAt<D>(i, p.position, p.pressure, neighbours_, constants_.re_laplacian,
                                [rho](std::int32_t) { return rho; }, gravity_, liquid);
}

template <int D>
void MpsSolver<D>::stabilisedPressureTerms(double dt) {
  auto& p = state_.particles;
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  const double rho = phases_[static_cast<int>(Phase::Liquid)].density;
  makeThinRowsFreeSurface();
  // Walls do not carry velocity in the divergence: mirroredWallTerm adds theirs against u* - g dt. Nor does a
  // bubble's gas that follows the liquid: its velocity is the liquid's of the last step extended into it
  // (bubble_gas_motion.hpp), not a flow the water must follow; the bubble's volume is its own row's
  // (bubble_pressure.hpp). Counted, it held the water beside a bubble to that velocity, and a water particle
  // crossing a bubble's gas at 2-3 m/s reached 30-140 kPa (the 5 mm waterfall at 1.07 and 1.19 s, docs/waterfall.md).
  const bool gas_follows = bubbleGasFollowsLiquid();
  for (std::int64_t i = 0; i < n; ++i)
    if (isMirroredWall(p.kind[i]) || (gas_follows && roles_.enclosed_gas[i])) problem_.carries_velocity[i] = 0;
  std::vector<Vec<D>> last_gradient(n, Vec<D>::Zero());
  surface_pressure_.assign(n, 0.0);
  const bool thin_liquid = config_.numerics.thin_rows_hold_liquid;
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (!problem_.takes_part[i] || roles_.enclosed_gas[i]) continue;
    last_gradient[i] = stabilisedGradient(i).value;
    if (!problem_.unknown[i] && p.kind[i] == ParticleKind::Fluid) {
      const double surface = surfaceParticlePressure<D>(last_gradient[i], constants_.l0);
      std::optional<double> value = bubbleSidePressure(i);
      if (!value && thin_liquid && thin_row_[i]) value = thinRowLiquidPressure(static_cast<std::size_t>(i), rho);
      surface_pressure_[i] = value.value_or(surface);
    }
  }
  findSurfaceTangents(last_gradient);
  problem_.extra_rhs.assign(n, 0.0);
  const double factor = constants_.laplacianFactor();
  auto inLaplacian = [&](std::int32_t j) { return problem_.takes_part[j] || isMirroredWall(p.kind[j]); };
  auto atSurface = [&](std::int32_t j) { return surface_pressure_[j] != 0.0; };
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (!problem_.unknown[i] || roles_.enclosed_gas[i]) continue;
    double extra = mirroredWallTerm<D>(i, p.position, p.velocity, p.kind, neighbours_, constants_, rho, gravity_, dt,
                                       !problem_.isSourceless(i));  // inflow_pressure.hpp
    extra += laplacianConsistencyTerm<D>(i, p.position, neighbours_, constants_, last_gradient[i], inLaplacian);
    double surface = 0.0;
    forEachPairWithin<D>(i, p.position, neighbours_, constants_.re_laplacian, atSurface,
                         [&](std::int32_t j, const Vec<D>&, double, double w) { surface += w * surface_pressure_[j]; });
    problem_.extra_rhs[i] = extra + factor * surface;
  }
}

// The particles near a free surface (fluid taking part without an unknown) and its normal, for the repulsion and the
// shifting (when either is on), once the unknowns are chosen.
template <int D>
void MpsSolver<D>::findSurfaceTangents(const std::vector<Vec<D>>& last_gradient) {
  if (config_.numerics.pressure_repulsion <= 0.0 && config_.numerics.particle_shifting <= 0.0) return;
  const auto& p = state_.particles;
  auto freeSurface = [&](std::int32_t j) {
    return p.kind[j] == ParticleKind::Fluid && problem_.takes_part[j] && !problem_.unknown[j];
  };
  surface_tangents_ = surfaceTangents<D>(p.position, neighbours_, constants_.re_laplacian, last_gradient, freeSurface);
}

// Particle shifting (particle_shifting.hpp) of the fluid particles the correction moved: the liquid system's, or
// every fluid particle of the one equation, but a vent's gas, which its column moves (gas_vent.hpp). The first
// moment counts both phases and the walls in either coupling: under the two systems the open gas is invisible to
// the liquid's pressure, but a water particle beside it is not at a free surface, and counting only the water
// shifted it into the air wherever the surface normal (the last pressure gradient, noise in a falling sheet) missed
// the interface (docs/two-phase.md, "The stabilised liquid under the two-systems coupling").
// Jacobi-style: all displacements from the positions before the stage.
template <int D>
void MpsSolver<D>::shiftParticles(double dt) {
  auto& p = state_.particles;
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  const double a = config_.numerics.particle_shifting;
  if (a <= 0.0 || surface_tangents_.empty()) return;
  const bool one = oneEquation();
  auto inSum = [&](std::int32_t j) {
    return one ? (problem_.takes_part[j] || isMirroredWall(p.kind[j]))
               : (roles_.in_liquid_system[j] != 0 || roles_.open_gas[j] != 0);
  };
  std::vector<Vec<D>> shift(n, Vec<D>::Zero());
  const auto kernel = config_.numerics.shifting_kernel;
  const double beta = config_.numerics.shift_stability;
  std::size_t bounded = 0;
#pragma omp parallel for schedule(static) reduction(+ : bounded)
  for (std::int64_t i = 0; i < n; ++i) {
    if (p.kind[i] != ParticleKind::Fluid) continue;
    if (!one && (!roles_.in_liquid_system[i] || roles_.enclosed_gas[i])) continue;
    if (isVentGas(static_cast<std::size_t>(i))) continue;
    const Vec<D>& normal = surface_tangents_.normal[i];
    if (surface_tangents_.near[i] && normal.squaredNorm() == 0.0) continue;
    shift[i] = shiftingDisplacement<D>(i, p.position, neighbours_, constants_, a, p.velocity[i], dt, normal, inSum,
                                       kernel);
    // numerics.shift_stability: the explicit shift's stability bound (shift_stability.hpp; counted)
    const double factor = shiftStabilityFactor<D>(i, p.position, neighbours_, constants_, a, p.velocity[i].norm(), dt,
                                                  beta, inSum, kernel);
    if (factor < 1.0) shift[i] *= factor, ++bounded;
  }
  report_.shift_bounded = bounded;
  // numerics.shift_limit (a guard, counted): a shift longer than limit l0 is shortened to it.
  const double limit = config_.numerics.shift_limit * constants_.l0;
  // numerics.shift_wall_stop (a guard, counted): the shift does not approach a wall particle it would bring within
  // collision_distance (wall_stop.hpp; only fixed particles are read, so the loop may move the fluid as it goes).
  const bool wall_stop = config_.numerics.shift_wall_stop;
  const double stop_distance = config_.numerics.collision_distance * constants_.l0;
  auto fixed = [&](std::int32_t j) { return isFixed(p.kind[j]); };
  std::vector<double> length(n, 0.0);
  std::size_t cuts = 0, stops = 0;
#pragma omp parallel for schedule(static) reduction(+ : cuts, stops)
  for (std::int64_t i = 0; i < n; ++i) {
    length[i] = shift[i].norm();
    if (limit > 0.0 && length[i] > limit) shift[i] *= limit / length[i], ++cuts;
    if (wall_stop && length[i] > 0.0)
      stops += stopDisplacementAtWalls<D>(static_cast<std::size_t>(i), p.position, neighbours_, stop_distance, fixed,
                                          shift[i]);
    p.position[i] += shift[i];
  }
  // The largest shift as computed (before the limit) and its particle, the first of equals in index order.
  const auto largest = std::max_element(length.begin(), length.end());
  report_.largest_shift = largest == length.end() ? 0.0 : *largest / constants_.l0;
  report_.largest_shift_id = largest == length.end() || *largest == 0.0 ? -1 : p.id[largest - length.begin()];
  report_.largest_shift_time = state_.time;
  report_.shift_cuts = cuts;
  report_.shift_wall_stops = stops;
}

#define MISTFALL_INSTANTIATE(D)                                                         \
  template CorrectedGradient<D> MpsSolver<D>::stabilisedGradient(std::size_t, bool) const; \
  template void MpsSolver<D>::stabilisedPressureTerms(double);                       \
  template void MpsSolver<D>::makeThinRowsFreeSurface();                            \
  template std::optional<double> MpsSolver<D>::bubbleSidePressure(std::size_t) const; \
  template std::optional<double> MpsSolver<D>::thinRowLiquidPressure(std::size_t, double) const; \
  template void MpsSolver<D>::shiftParticles(double);                              \
  template void MpsSolver<D>::findSurfaceTangents(const std::vector<Vec<D>>&);
MISTFALL_INSTANTIATE(2)
MISTFALL_INSTANTIATE(3)
#undef MISTFALL_INSTANTIATE

}  // namespace mistfall

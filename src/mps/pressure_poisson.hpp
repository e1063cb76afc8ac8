// Pressure Poisson equation of MPS, eq. (9), with the compressible extension of eq. (12)/(17):
//   (A - E / (dt^2 c^2)) p = -rho / dt^2 * (n* - n0) / n0
// A is the Laplacian matrix of eq. (16) (eq. (13) applied to p). We assemble the negated system, which is
// symmetric positive definite. One system holds one density rho (the liquid's or the gas's, docs/two-phase.md);
// the sound speed c_i is per row (eq. (17) may apply to some rows only). For each unknown particle i:
//   2D0/(n0 lambda) * sum_j w_ij (p_i - p_j) + p_i / (dt^2 c_i^2) = rho / dt^2 * (n*_i - n0) / n0
// Boundary particles (taking part but not unknown: the free surface, n*_i < beta n0) hold p = 0 (Dirichlet):
// they add to the diagonal only (a vent's gas holds the ambient pressure: PressureProblem::boundary_value). Particles that do not take part (dummies) are left out.
// c = infinity gives the incompressible equation (9) exactly.
// With the mixed source (Tanaka & Masunaga 2010) the right-hand side becomes
//   rho * (-1 / dt * <div u*>_i + gamma / dt^2 * (n*_i - n0) / n0)      (divergence by divergence.hpp)
// and a compressible row (finite c_i) then needs the last pressure p_i^n (numerics.gas_pressure_memory): the gas's
// continuity equation (1/(rho c^2)) Dp/Dt = -div u integrated over the step, with u^{n+1} = u* - dt/rho grad p, reads
//   -<lap p>_i + p_i / (dt^2 c_i^2) = -rho/dt <div u*>_i + p_i^n / (dt^2 c_i^2),
// and the relaxation toward the compression replaces gamma of the memory by the number-density error:
//   rhs_i += (1 - gamma) p_i^n / (dt^2 c_i^2)      (compressibleMemoryTerm)
// so gas at rest compressed by delta holds p = rho c^2 delta whatever gamma is. Without the memory term it settles
// at gamma rho c^2 delta: an effective sound speed sqrt(gamma) c, 34 m/s for air at gamma = 0.01.
#pragma once

#include <Eigen/Sparse>
#include <cstdint>
#include <vector>

#include "case/case_config.hpp"
#include "mps/neighbour_search.hpp"
#include "mps/reference_density.hpp"

namespace mistfall {

struct PressureSystem {
  Eigen::SparseMatrix<double, Eigen::RowMajor> matrix;
  Eigen::VectorXd rhs;
  std::vector<std::int32_t> row_of;       // particle -> row, -1 when not an unknown
  std::vector<std::int32_t> particle_of;  // row -> particle
};

// Which particles the system is about, per particle (all vectors of particle count).
struct PressureProblem {
  std::vector<char> takes_part;     // in the Laplacian: an unknown or a Dirichlet (p = 0) boundary
  std::vector<char> unknown;        // carries an unknown (implies takes_part)
  std::vector<char> carries_velocity;  // neighbours of the divergence (mixed source only)
  std::vector<double> sound_speed;  // c_i [m/s], infinity = incompressible
  double density = 1.0;             // rho [kg/m^3] of the system's fluid
  // Water and air in one equation (numerics.coupling = "one_equation", interface_density.hpp): when not empty, the
  // density of each particle, and the system is the variable-density one, every row divided by rho:
  //   2D0/(n0 lambda) sum_j w_ij (p_i - p_j) / rho_ij + p_i / (rho_i dt^2 c_i^2) = -<div u*>_i / dt + gamma/dt^2 (n*-n0)/n0
  // with rho_ij = pairDensity(rho_i, rho_j, phi_i, phi_j) (phi: interface_distance); `density` is then unused.
  std::vector<double> density_of;
  std::vector<double> interface_distance;
  std::vector<double> extra_rhs;    // known terms added to row i's right-hand side (empty = none)
  // Rows without the divergence and compression source (empty = none): an inflow buffer's driven water with
  // `[[inflow]] pressure = "harmonic"` (inflow_pressure.hpp), whose pressure is that of a uniform flow, lap p = 0.
  std::vector<char> sourceless;
  bool isSourceless(std::size_t i) const { return !sourceless.empty() && sourceless[i]; }
  // The pressure a Dirichlet boundary holds (taking part, not unknown; empty = 0 for all): a gas vent's ambient
  // pressure (gas_vent.hpp). Row i's known neighbour j adds (its coefficient) * boundary_value[j] to the right.
  std::vector<double> boundary_value;
  // Rows of one group count each other's velocity in the divergence, whether they carry it or not (>= 0; empty or
  // -1 = none): a bubble's gas with numerics.bubble_divergence = "whole_bubble", so that the sum of its rows is the
  // flux through its interface (bubble_pressure.hpp), while the water beside it does not count the gas's velocity.
  std::vector<std::int32_t> velocity_group;
};

// Free-surface flags of the single-phase system: fluid or wall particles with n*_i < beta n0.
template <int D>
std::vector<char> freeSurfaceFlags(const Particles<D>& p, double beta, double n0) {
  std::vector<char> surface(p.size(), 0);
  for (std::size_t i = 0; i < p.size(); ++i)
    surface[i] = hasPressureUnknown(p.kind[i]) &&
                 p.number_density[i] < beta * n0;
  return surface;
}

// The single-phase problem: fluid and wall particles take part, those off the free surface are unknowns, with
// the liquid's density and sound speed.
template <int D>
PressureProblem singlePhaseProblem(const Particles<D>& p, const PhaseProperties& liquid,
                                   const std::vector<char>& surface);

struct PressureSourceTerm {
  PressureSource kind = PressureSource::Standard;
  double relaxation = 1.0;  // gamma (mixed source only)
};

// The source of a step of length dt from the case (numerics.source_relaxation_basis): gamma as given ("step"), or
// gamma dt/dt_max for a step shorter than dt_max ("time"). The number-density term moves a particle by about
// gamma delta l0 in a step, so it gives it a velocity ~ gamma delta L/dt over a region of size L: per step, a step
// cut 30x short by the Courant limit kicks all the water 30x harder; per time, the correction keeps its rate,
// gamma/dt_max per second, and its velocity. The memory term below takes the same gamma, so compressed gas still
// holds rho c^2 delta at rest.
inline PressureSourceTerm sourceTermFor(const NumericsConfig& numerics, double dt) {
  double gamma = numerics.source_relaxation;
  if (numerics.source_relaxation_per_time && dt < numerics.dt_max) gamma *= dt / numerics.dt_max;
  return {numerics.pressure_source, gamma};
}

// The memory term above for a compressible row with last pressure `previous` (0 for the standard source, whose
// right-hand side already holds the whole compression, and for c = infinity).
inline double compressibleMemoryTerm(PressureSourceTerm source, double previous, double dt, double sound_speed) {
  if (source.kind != PressureSource::Mixed || !(sound_speed < std::numeric_limits<double>::infinity())) return 0.0;
  return (1.0 - source.relaxation) * previous / (dt * dt * sound_speed * sound_speed);
}

// `number_density` holds n* and p.velocity u* (after the explicit stage). `near` (optional): a list of the pairs
// within the number-density radius (neighbour_search.hpp filterNeighbours) for the mixed source's divergence; the
// same bits as with `nl`, fewer pairs visited.
template <int D>
void assemblePressureSystem(const Particles<D>& p, const std::vector<double>& number_density,
                            const NeighbourList& nl, const MpsConstants& c, const PressureProblem& problem,
                            PressureSourceTerm source, double dt, PressureSystem& sys,
                            const NeighbourList* near = nullptr);

}  // namespace mistfall

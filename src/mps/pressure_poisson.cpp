#include "mps/pressure_poisson.hpp"

#include <algorithm>
#include <cmath>

#include "mps/divergence.hpp"
#include "mps/interface_density.hpp"
#include "mps/pair_loop.hpp"

namespace mistfall {

template <int D>
PressureProblem singlePhaseProblem(const Particles<D>& p, const PhaseProperties& liquid,
                                   const std::vector<char>& surface) {
  const std::size_t n = p.size();
  PressureProblem problem;
  problem.takes_part.resize(n);
  problem.unknown.resize(n);
  problem.carries_velocity.resize(n);
  problem.sound_speed.assign(n, liquid.sound_speed);
  problem.density = liquid.density;
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = p.kind[i];
    problem.takes_part[i] = hasPressureUnknown(k);
    problem.unknown[i] = problem.takes_part[i] && !surface[i];
    problem.carries_velocity[i] = isActive(k);
  }
  return problem;
}

template <int D>
void assemblePressureSystem(const Particles<D>& p, const std::vector<double>& number_density,
                            const NeighbourList& nl, const MpsConstants& c, const PressureProblem& problem,
                            PressureSourceTerm source, double dt, PressureSystem& sys, const NeighbourList* near) {
  const NeighbourList& divergence_list = near ? *near : nl;
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  const auto& takes_part = problem.takes_part;
  const bool variable = !problem.density_of.empty();
  const double rho = variable ? 1.0 : problem.density;
  // The pair weight 1/rho_ij of the variable-density system (1 for one density: rho multiplies the source instead).
  auto coefficient = [&](std::int32_t i, std::int32_t j) {
    if (!variable) return 1.0;
    const auto& d = problem.density_of;
    const auto& phi = problem.interface_distance;
    return 1.0 / pairDensity(d[i], d[j], phi[i], phi[j]);
  };

  sys.row_of.assign(n, -1);
  sys.particle_of.clear();
  for (std::int64_t i = 0; i < n; ++i)
    if (problem.unknown[i]) {
      sys.row_of[i] = static_cast<std::int32_t>(sys.particle_of.size());
      sys.particle_of.push_back(static_cast<std::int32_t>(i));
    }
  const std::int64_t rows = static_cast<std::int64_t>(sys.particle_of.size());

  // Row lengths (diagonal + unknown neighbours inside re), then fill CSR directly.
  std::vector<std::int64_t> start(rows + 1, 0);
  const double re = c.re_laplacian;
  auto isUnknown = [&](std::int32_t j) { return sys.row_of[j] >= 0; };
  auto takesPart = [&](std::int32_t j) { return takes_part[j] != 0; };
#pragma omp parallel for schedule(static)
  for (std::int64_t r = 0; r < rows; ++r) {
    std::int64_t count = 1;
    forEachPairWithin<D>(sys.particle_of[r], p.position, nl, re, isUnknown,
                         [&](std::int32_t, const Vec<D>&, double, double) { ++count; });
    start[r + 1] = count;
  }
  for (std::int64_t r = 0; r < rows; ++r) start[r + 1] += start[r];

  sys.matrix.resize(rows, rows);
  sys.matrix.resizeNonZeros(start[rows]);
  auto* outer = sys.matrix.outerIndexPtr();
  auto* inner = sys.matrix.innerIndexPtr();
  auto* value = sys.matrix.valuePtr();
  for (std::int64_t r = 0; r <= rows; ++r) outer[r] = static_cast<int>(start[r]);
  sys.rhs.resize(rows);

  const double factor = c.laplacianFactor();
#pragma omp parallel for schedule(static)
  for (std::int64_t r = 0; r < rows; ++r) {
    const auto i = sys.particle_of[r];
    // Neighbour lists are in ascending index order and rows are numbered in particle order, so the columns come
    // sorted (as Eigen requires); the diagonal goes in before the first column above it.
    std::int64_t at = start[r];
    std::int64_t diagonal_at = -1;
    double diagonal = 0.0;
    double known = 0.0;  // the Dirichlet neighbours' sum of k p_j
    const bool boundary_values = !problem.boundary_value.empty();
    forEachPairWithin<D>(i, p.position, nl, re, takesPart, [&](std::int32_t j, const Vec<D>&, double, double w) {
      const double k = factor * w * coefficient(i, j);
      diagonal += k;
      if (sys.row_of[j] >= 0) {
        if (diagonal_at < 0 && j > i) diagonal_at = at++;
        inner[at] = sys.row_of[j];
        value[at] = -k;
        ++at;
      } else if (boundary_values) {
        known += k * problem.boundary_value[j];
      }
    });
    if (diagonal_at < 0) diagonal_at = at++;
    const double ci = problem.sound_speed[i];
    if (std::isfinite(ci)) diagonal += 1.0 / ((variable ? problem.density_of[i] : 1.0) * dt * dt * ci * ci);
    inner[diagonal_at] = static_cast<int>(r);
    value[diagonal_at] = diagonal;
    const double compression = (number_density[i] - c.n0) / c.n0;
    if (problem.isSourceless(i)) {
      sys.rhs[r] = 0.0;
    } else if (source.kind == PressureSource::Standard) {
      sys.rhs[r] = rho / (dt * dt) * compression;
    } else {
      const std::int32_t group = problem.velocity_group.empty() ? -1 : problem.velocity_group[i];
      auto carriesVelocity = [&](std::int32_t j) {
        return problem.carries_velocity[j] != 0 || (group >= 0 && problem.velocity_group[j] == group);
      };
      const double divergence = divergenceAt<D>(i, p.position, p.velocity, divergence_list, c, carriesVelocity);
      sys.rhs[r] = -rho / dt * divergence + source.relaxation * rho / (dt * dt) * compression;
    }
    if (!problem.extra_rhs.empty()) sys.rhs[r] += problem.extra_rhs[i];
    sys.rhs[r] += known;
  }
}

template PressureProblem singlePhaseProblem<2>(const Particles<2>&, const PhaseProperties&,
                                               const std::vector<char>&);
template PressureProblem singlePhaseProblem<3>(const Particles<3>&, const PhaseProperties&,
                                               const std::vector<char>&);
template void assemblePressureSystem<2>(const Particles<2>&, const std::vector<double>&, const NeighbourList&,
                                        const MpsConstants&, const PressureProblem&, PressureSourceTerm, double,
                                        PressureSystem&, const NeighbourList*);
template void assemblePressureSystem<3>(const Particles<3>&, const std::vector<double>&, const NeighbourList&,
                                        const MpsConstants&, const PressureProblem&, PressureSourceTerm, double,
                                        PressureSystem&, const NeighbourList*);

}  // namespace mistfall

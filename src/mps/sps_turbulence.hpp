// Sub-particle-scale (SPS) turbulence energy, eqs. (25)-(26) of Gotoh et al.:
//   k_i = (Cv / Ce) Ds^2 P_i,   P = 2 S_ab S_ab,   S = (grad u + grad u^T) / 2
// (in 2D: P = 2 (du/dx)^2 + 2 (dv/dy)^2 + (du/dy + dv/dx)^2), Cv = 0.08, Ce = 1.0, Ds = particle size.
// The velocity gradient is the plain MPS gradient model (gradient.hpp, GradientForm::Plain) applied to each
// velocity component, computed in one tensor loop:
//   (grad u)_ab = du_a/dx_b = D0 / n0 * sum_{j != i} (u_j - u_i)_a (r_j - r_i)_b / |r_ij|^2 * w(|r_ij|)
// which is exact for linear velocity fields inside a full lattice. k feeds the turbulent fluctuation of
// eqs. (23)-(24), u_f = U + xi sqrt(2k/3).
#pragma once

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "mps/pair_loop.hpp"
#include "mps/particles.hpp"
#include "mps/reference_density.hpp"

namespace mistfall {

template <int D>
using Tensor = Eigen::Matrix<double, D, D>;

struct SpsParameters {
  double cv = 0.08;  // Cv of eq. (26)
  double ce = 1.0;   // Ce of eq. (26)
  double ds = 0.0;   // Ds: the particle size (spacing l0) [m]; set by the caller, must be positive
};

// Throws std::invalid_argument with a one-line message on non-physical parameters.
inline void checkSpsParameters(const SpsParameters& s) {
  if (!(s.ds > 0.0) || !std::isfinite(s.ds))
    throw std::invalid_argument("SPS turbulence: Ds (particle size) must be positive, got " + std::to_string(s.ds));
  if (!(s.ce > 0.0) || !std::isfinite(s.ce))
    throw std::invalid_argument("SPS turbulence: Ce must be positive, got " + std::to_string(s.ce));
  if (!(s.cv >= 0.0) || !std::isfinite(s.cv))
    throw std::invalid_argument("SPS turbulence: Cv must be non-negative, got " + std::to_string(s.cv));
}

// MPS velocity gradient (grad u)_ab = du_a/dx_b at particle i over the neighbours `include(j)` admits
// within re_number_density (the neighbour list must have been built with at least that radius).
template <int D, class Include>
Tensor<D> velocityGradientAt(std::size_t i, const std::vector<Vec<D>>& position, const std::vector<Vec<D>>& u,
                             const NeighbourList& nl, const MpsConstants& c, Include&& include) {
  Tensor<D> sum = Tensor<D>::Zero();
  forEachPairWithin<D>(i, position, nl, c.re_number_density, include,
                       [&](std::int32_t j, const Vec<D>& rij, double r2, double w) {
                         sum.noalias() += (u[j] - u[i]) * (rij.transpose() * (w / r2));
                       });
  return sum * (double(D) / c.n0);
}

// P = 2 S_ab S_ab with S the symmetric part of the velocity gradient, eq. (26).
template <int D>
double strainProduction(const Tensor<D>& grad_u) {
  const Tensor<D> s = 0.5 * (grad_u + grad_u.transpose());
  return 2.0 * s.squaredNorm();
}

// k_i of eq. (25) at particle i; `include(j)` picks the neighbours (the caller passes "same phase, active").
// The parameters are not checked here (hot loop): see checkSpsParameters.
template <int D, class Include>
double spsTurbulenceEnergyAt(std::size_t i, const Particles<D>& p, const NeighbourList& nl, const MpsConstants& c,
                             const SpsParameters& s, Include&& include) {
  const double production = strainProduction<D>(velocityGradientAt<D>(i, p.position, p.velocity, nl, c, include));
  return s.cv / s.ce * s.ds * s.ds * production;
}

// Turbulence intensity sqrt(2k/3): the standard deviation of each fluctuation component, eqs. (23)-(24).
inline double turbulenceIntensity(double k) { return std::sqrt(2.0 * k / 3.0); }

// k for every particle into `k` (resized to p.size()); OpenMP-parallel over particles.
// `include(i, j)` says whether neighbour j takes part in the gradient at particle i. Escaped particles get 0.
template <int D, class PairInclude>
void spsTurbulenceEnergy(const Particles<D>& p, const NeighbourList& nl, const MpsConstants& c, const SpsParameters& s,
                         std::vector<double>& k, PairInclude&& include) {
  checkSpsParameters(s);
  if (nl.particleCount() != p.size())
    throw std::invalid_argument("SPS turbulence: the neighbour list holds " + std::to_string(nl.particleCount()) +
                                " particles, expected " + std::to_string(p.size()));
  const auto n = static_cast<std::int64_t>(p.size());
  k.assign(p.size(), 0.0);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    const auto pi = static_cast<std::size_t>(i);
    if (!isActive(p.kind[pi])) continue;
    k[pi] = spsTurbulenceEnergyAt<D>(pi, p, nl, c, s, [&](std::int32_t j) { return include(pi, j); });
  }
}

// The neighbour rule of the SPS model in mistfall: same phase as particle i and not escaped.
template <int D>
auto samePhaseActive(const Particles<D>& p) {
  return [&p](std::size_t i, std::int32_t j) { return p.phase[j] == p.phase[i] && isActive(p.kind[j]); };
}

}  // namespace mistfall

// The interparticle density of water and air in one pressure equation (numerics.coupling = "one_equation";
// docs/two-phase.md). The variable-density projection -div((1/rho) grad p) = -div u* / dt, written with MPS pair
// sums, carries a pair weight 1/rho_ij. Across the interface the exact weight follows from the continuity of the
// flux (1/rho) dp/ds along the segment i-j: with a length d_i of it in i's phase and d_j in j's,
//   p_j - p_i = -q (rho_i d_i + rho_j d_j),   so   rho_ij = (rho_i d_i + rho_j d_j) / (d_i + d_j),
// the length-weighted mean of the densities along the segment (the effective coefficient of the ghost-fluid method
// for Poisson's equation with a jump in its coefficient: Liu, Fedkiw & Kang 2000, J. Comput. Phys. 160, 151). With
// it, water and air at rest under gravity hold (p_j - p_i)/rho_ij = g . r_ij for every pair, whichever phase each
// particle is in and wherever the interface cuts the segment, so the hydrostatic state is an exact solution; the
// arithmetic mean of the two densities is exact only where the interface lies midway between the two particles.
//
// The lengths come from each particle's distance to the interface, phi_i, interpolated linearly along the segment:
// d_i : d_j = phi_i : phi_j. The interface is located from the particles around i: the midpoints of the adjacent
// water-air pairs (closer than 1.5 l0) within the Laplacian radius 3.1 l0 of i, weighted (1 - r/3.1 l0)^2 by their
// pair's first particle's distance from i, and the line (plane in 3D) fitted through them by least squares;
//   phi_i = max(distance of i from that line on its own phase's side, l0/10).
// A lattice cut by a straight interface midway between two rows gives phi = (k + 1/2) l0 for the k-th row (exact).
// Moving one particle moves the fitted line by a fraction of that: the distance to the nearest particle of the other
// phase instead (phi = dmin - l0/2, the first version) counts the whole gap that a separating pair opens in the
// distance of both, and that feedback grew a separation at the interface's corners with the walls into a
// divergence (measured: docs/two-phase.md). The nearest rule remains where no adjacent pair is near (a lone
// particle of one phase in the other): phi = max(dmin - l0/2, dmin/4).
#pragma once

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

#include "mps/neighbour_search.hpp"
#include "mps/particles.hpp"

namespace mistfall {

namespace detail {

// Per particle: the midpoints of its adjacent pairs with the other phase (sum, sum of outer products, count) and the
// sum of the pairs' unit vectors from water to air.
template <int D>
struct InterfaceMoments {
  std::vector<Vec<D>> first, normal;
  std::vector<Eigen::Matrix<double, D, D>> second;
  std::vector<double> count;
};

template <int D>
InterfaceMoments<D> adjacentPairMidpoints(const Particles<D>& p, const NeighbourList& nl, double l0) {
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  InterfaceMoments<D> m;
  m.first.assign(n, Vec<D>::Zero());
  m.normal.assign(n, Vec<D>::Zero());
  m.second.assign(n, Eigen::Matrix<double, D, D>::Zero());
  m.count.assign(n, 0.0);
  const double adjacent = 1.5 * l0, adjacent2 = adjacent * adjacent;
#pragma omp parallel for schedule(static)
  for (std::int64_t a = 0; a < n; ++a) {
    if (p.kind[a] != ParticleKind::Fluid) continue;
    for (auto s = nl.begin(a); s < nl.end(a); ++s) {
      const auto b = nl.indices[s];
      if (p.kind[b] != ParticleKind::Fluid || p.phase[b] == p.phase[a]) continue;
      const Vec<D> rab = p.position[b] - p.position[a];
      const double r2 = rab.squaredNorm();
      if (r2 >= adjacent2) continue;
      const Vec<D> mid = p.position[a] + 0.5 * rab;
      const double r = std::sqrt(r2), fall = 1.0 - r / adjacent;  // a pair's weight: smoothly to 0 at 1.5 l0
      const double w = fall * fall;
      m.first[a] += w * mid;
      m.second[a] += w * mid * mid.transpose();
      m.count[a] += w;
      m.normal[a] += (p.phase[a] == Phase::Liquid ? w : -w) / r * rab;
    }
  }
  return m;
}

}  // namespace detail

// phi_i of every fluid particle (0 for walls and escaped particles; they never form a pair across the interface).
// `reach`: the neighbour list's radius (at least the Laplacian radius 3.1 l0).
template <int D>
std::vector<double> interfaceDistances(const Particles<D>& p, const NeighbourList& nl, double reach, double l0) {
  using Matrix = Eigen::Matrix<double, D, D>;
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  const auto moments = detail::adjacentPairMidpoints<D>(p, nl, l0);
  const double fit_radius = std::min(reach, 3.1 * l0);
  std::vector<double> phi(n, 0.0);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (p.kind[i] != ParticleKind::Fluid) continue;
    double nearest2 = reach * reach, weight = moments.count[i];
    Vec<D> first = moments.first[i], normal_sum = moments.normal[i];
    Matrix second = moments.second[i];
    for (auto s = nl.begin(i); s < nl.end(i); ++s) {
      const auto k = nl.indices[s];
      if (p.kind[k] != ParticleKind::Fluid) continue;
      const double r2 = (p.position[k] - p.position[i]).squaredNorm();
      if (p.phase[k] != p.phase[i]) nearest2 = std::min(nearest2, r2);
      if (moments.count[k] == 0.0 || r2 >= fit_radius * fit_radius) continue;
      const double w = (1.0 - std::sqrt(r2) / fit_radius) * (1.0 - std::sqrt(r2) / fit_radius);
      first += w * moments.first[k];
      second += w * moments.second[k];
      normal_sum += w * moments.normal[k];
      weight += w * moments.count[k];
    }
    const double nearest = std::sqrt(nearest2);
    phi[i] = std::max(nearest - 0.5 * l0, 0.25 * nearest);  // no adjacent pair near: the nearest rule
    if (weight == 0.0 || normal_sum.squaredNorm() == 0.0) continue;
    const Vec<D> centre = first / weight;
    const Matrix spread = second / weight - centre * centre.transpose();
    Vec<D> normal = normal_sum.normalized();  // from water to air
    Eigen::SelfAdjointEigenSolver<Matrix> eigen(spread);
    if (eigen.eigenvalues()(D - 1) > 1e-4 * l0 * l0) {  // the midpoints span a line: the direction of least spread
      normal = eigen.eigenvectors().col(0);
      if (normal.dot(normal_sum) < 0.0) normal = -normal;
    }
    const double above = (p.position[i] - centre).dot(normal);  // > 0 on the air's side
    phi[i] = std::max(p.phase[i] == Phase::Liquid ? -above : above, 0.1 * l0);
  }
  return phi;
}

// rho_ij of the pair (i, j) of fluid particles with densities rho_i, rho_j and interface distances phi_i, phi_j.
inline double pairDensity(double rho_i, double rho_j, double phi_i, double phi_j) {
  if (rho_i == rho_j) return rho_i;
  return (rho_i * phi_i + rho_j * phi_j) / (phi_i + phi_j);
}

}  // namespace mistfall

// Pressure Poisson equation of MPS, eq. (9), with the compressible extension of eq. (12)/(17):
//   (A - E / (dt^2 c^2)) p = -rho / dt^2 * (n* - n0) / n0
// A is the Laplacian matrix of eq. (16) (eq. (13) applied to p). We assemble the negated system, which is
// symmetric positive definite: for each unknown particle i (fluid or wall, not on the free surface)
//   2D0/(n0 lambda) * sum_j w_ij (p_i - p_j) + p_i / (dt^2 c_i^2) = rho_i / dt^2 * (n*_i - n0) / n0
// Free-surface particles (n*_i < beta n0) hold p = 0 (Dirichlet): they add to the diagonal only.
// Dummy particles take no part. c = infinity gives the incompressible equation (9) exactly.
// With the mixed source (Tanaka & Masunaga 2010) the right-hand side becomes
//   -rho_i / dt * <div u*>_i + gamma rho_i / dt^2 * (n*_i - n0) / n0      (divergence by divergence.hpp)
#pragma once

#include <Eigen/Sparse>
#include <array>
#include <vector>

#include "case/case_config.hpp"
#include "mps/neighbor_search.hpp"
#include "mps/reference_density.hpp"

namespace mistfall {

struct PressureSystem {
  Eigen::SparseMatrix<double, Eigen::RowMajor> matrix;
  Eigen::VectorXd rhs;
  std::vector<std::int32_t> row_of;       // particle -> row, -1 when not an unknown
  std::vector<std::int32_t> particle_of;  // row -> particle
};

// Which particles carry an unknown pressure: fluid or wall particles off the free surface.
template <int D>
std::vector<char> freeSurfaceFlags(const Particles<D>& p, double beta, double n0) {
  std::vector<char> surface(p.size(), 0);
  for (std::size_t i = 0; i < p.size(); ++i)
    surface[i] = (p.kind[i] == ParticleKind::Fluid || p.kind[i] == ParticleKind::Wall) &&
                 p.number_density[i] < beta * n0;
  return surface;
}

struct PressureSourceTerm {
  PressureSource kind = PressureSource::Standard;
  double relaxation = 1.0;  // gamma (mixed source only)
};

// p.number_density must hold n* and p.velocity u* (after the explicit stage).
template <int D>
void assemblePressureSystem(const Particles<D>& p, const NeighborList& nl, const MpsConstants& c,
                            const std::array<PhaseProperties, 2>& phases, const std::vector<char>& surface,
                            PressureSourceTerm source, double dt, PressureSystem& sys);

}  // namespace mistfall

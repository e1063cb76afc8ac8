// One pressure unknown per bubble in the liquid system (the gas-liquid coupling of eqs. (5)-(7), docs/two-phase.md).
// Gas enclosed in the liquid is ~10^3 times lighter, so its pressure is uniform over the bubble; the liquid system is
// assembled with every enclosed gas particle as an unknown of the liquid's density and sound speed infinity, and
// then the unknowns of each bubble B are merged into one, P_B (sum of their rows and of their columns):
//   A' = T^T A T,  b' = T^T b,  T = the 0/1 matrix that maps P_B to each of B's particles.
// Row B of A' then says: the flux of the liquid's pressure into the bubble equals its summed compression, eq. (9)
// summed over B. Eq. (17) for the bubble's gas adds to its diagonal the sum of its particles' shifts,
//   N_B rho_ref / (rho_g dt^2 c_g^2),
// so a bubble squeezed uniformly by (n* - n0)/n0 = delta holds P_B = rho_g c_g^2 delta; c_g = infinity keeps its
// volume. The system stays symmetric positive definite.
#pragma once

#include <Eigen/Sparse>
#include <cstdint>
#include <vector>

#include "mps/pressure_poisson.hpp"

namespace mistfall {

struct LumpedPressureSystem {
  Eigen::SparseMatrix<double, Eigen::RowMajor> matrix;
  Eigen::VectorXd rhs;
  std::vector<std::int32_t> column_of_row;  // row of the particle system -> row of the lumped system
  std::int32_t first_group_row = 0;         // lumped row of group 0; group g is first_group_row + g
};

// `group_of`: per particle, the group (bubble) whose unknown it joins, or -1. `group_shift`: added to each group's
// diagonal. Every particle of a group must be an unknown of `sys`.
void lumpPressureGroups(const PressureSystem& sys, const std::vector<std::int32_t>& group_of,
                        const std::vector<double>& group_shift, LumpedPressureSystem& out);

}  // namespace mistfall

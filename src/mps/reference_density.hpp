// Reference constants of MPS from a full initial lattice around one particle:
//   n0     = sum_j w(|r_j - r_i|)                      (number density of an interior particle)
//   lambda = sum_j |r_j - r_i|^2 w / sum_j w           (Laplacian model constant of eq. (13))
// Computed for the number-density radius (n0, gradient, PPE source) and the Laplacian radius.
#pragma once

#include <cmath>

#include "mps/weight.hpp"

namespace mistfall {

struct MpsConstants {
  int dimension = 2;
  double l0 = 0.0;             // particle spacing [m]
  double re_number_density = 0.0;  // [m]
  double re_laplacian = 0.0;       // [m]
  double n0 = 0.0;             // reference number density with re_number_density
  double n0_laplacian = 0.0;   // reference number density with re_laplacian
  double lambda = 0.0;         // eq. (13) constant with re_laplacian [m^2]

  // 2 D0 / (n0 lambda): the factor in front of the Laplacian sum, eq. (13).
  double laplacianFactor() const { return 2.0 * dimension / (n0_laplacian * lambda); }
};

// Sums over a square (2D) or cubic (3D) lattice of spacing l0 centred on the particle.
inline MpsConstants referenceConstants(int dimension, double l0, double re_number_density_ratio,
                                       double re_laplacian_ratio) {
  MpsConstants c;
  c.dimension = dimension;
  c.l0 = l0;
  c.re_number_density = re_number_density_ratio * l0;
  c.re_laplacian = re_laplacian_ratio * l0;
  const int reach = static_cast<int>(std::ceil(std::max(re_number_density_ratio, re_laplacian_ratio))) + 1;
  const int kmin = dimension == 3 ? -reach : 0;
  const int kmax = dimension == 3 ? reach : 0;
  double sum_w_lap = 0.0, sum_r2w_lap = 0.0;
  for (int i = -reach; i <= reach; ++i)
    for (int j = -reach; j <= reach; ++j)
      for (int k = kmin; k <= kmax; ++k) {
        if (i == 0 && j == 0 && k == 0) continue;
        const double r = l0 * std::sqrt(double(i * i + j * j + k * k));
        c.n0 += weight(r, c.re_number_density);
        const double w = weight(r, c.re_laplacian);
        sum_w_lap += w;
        sum_r2w_lap += r * r * w;
      }
  c.n0_laplacian = sum_w_lap;
  c.lambda = sum_r2w_lap / sum_w_lap;
  return c;
}

}  // namespace mistfall

// Mirrored walls (numerics.scheme = "stabilised"; after the generalised wall boundary condition of Adami, Hu &
// Adams 2012, J. Comput. Phys. 231, 7057, eqs. (22)-(27), for walls at rest): wall and dummy particles carry no
// pressure unknown. Seen from a fluid particle i, a wall particle b holds the fluid's pressure continued
// hydrostatically into the wall,
//   p_b|i = p_i + rho g . r_ib,                                                   (r_ib = r_b - r_i)
// so the wall exerts the hydrostatic reaction (the Neumann condition dp/dn = rho g . n of the projection for a wall
// at rest) and still water is an exact equilibrium. In row i of the pressure equation (pressure_poisson.hpp, the
// negated Laplacian of eq. (13)) the walls' part of the Laplacian is known and moves to the right-hand side:
//   + 2D0/(n0 lambda) sum_b w(r_ib) rho g . r_ib
// The walls' velocity (zero) enters the divergence source against the fluid's velocity without this step's gravity,
// u*_i - g dt (gravity's push on the wall is the mirrored pressure above):
//   - rho/dt D0/n0 sum_b (0 - (u*_i - g dt)) . r_ib w(r_ib) / r_ib^2
// so water moving at a wall is stopped by the pressure equation, and water at rest is not pushed.
// For output and wall loads each wall particle gets the average of the mirrored values over its fluid neighbours,
//   p_b = sum_j w_bj (p_j + rho g . (r_b - r_j)) / sum_j w_bj   (Adami et al. eq. (27) at rest).
#pragma once

#include <optional>
#include <vector>

#include "mps/pair_loop.hpp"
#include "mps/reference_density.hpp"

namespace mistfall {

inline bool isMirroredWall(ParticleKind k) { return k == ParticleKind::Wall || k == ParticleKind::Dummy; }

// The walls' known part of row i (fluid particle i at r*, velocity u*): both terms above.
// With `with_divergence` false, the hydrostatic part alone (a row without a divergence source: inflow_pressure.hpp).
template <int D>
double mirroredWallTerm(std::size_t i, const std::vector<Vec<D>>& position, const std::vector<Vec<D>>& velocity,
                        const std::vector<ParticleKind>& kind, const NeighbourList& nl, const MpsConstants& c,
                        double rho, const Vec<D>& gravity, double dt, bool with_divergence = true) {
  auto wall = [&](std::int32_t j) { return isMirroredWall(kind[j]); };
  double hydrostatic = 0.0;
  forEachPairWithin<D>(i, position, nl, c.re_laplacian, wall,
                       [&](std::int32_t, const Vec<D>& rib, double, double w) { hydrostatic += w * gravity.dot(rib); });
  if (!with_divergence) return c.laplacianFactor() * rho * hydrostatic;
  const Vec<D> own = velocity[i] - gravity * dt;
  double divergence = 0.0;
  forEachPairWithin<D>(i, position, nl, c.re_number_density, wall,
                       [&](std::int32_t, const Vec<D>& rib, double r2, double w) { divergence -= own.dot(rib) * w / r2; });
  return c.laplacianFactor() * rho * hydrostatic - rho / dt * divergence * (double(D) / c.n0);
}

// The pressure of the particles j within re of particle b with carries(j), each continued hydrostatically to b
// with its density density(j) (Adami et al. eq. (27) at rest):
//   p_b = sum_j w_bj (p_j + rho_j g . (r_b - r_j)) / sum_j w_bj.
// None: no such particle within re.
template <int D, class Density, class Carries>
std::optional<double> continuedPressureAt(std::size_t b, const std::vector<Vec<D>>& position,
                                          const std::vector<double>& pressure, const NeighbourList& nl, double re,
                                          Density&& density, const Vec<D>& gravity, Carries&& carries) {
  double sum = 0.0, sum_w = 0.0;
  forEachPairWithin<D>(b, position, nl, re, carries, [&](std::int32_t j, const Vec<D>& rbj, double, double w) {
    sum += w * (pressure[j] - density(j) * gravity.dot(rbj));
    sum_w += w;
  });
  if (sum_w == 0.0) return std::nullopt;
  return sum / sum_w;
}

// Sets pressure[b] of every wall and dummy particle b from the fluid particles j with carries(j) (0 without any),
// each continuing its pressure with its density density(j).
template <int D, class Density, class Carries>
void averageMirroredWallPressure(const std::vector<Vec<D>>& position, const std::vector<ParticleKind>& kind,
                                 std::vector<double>& pressure, const NeighbourList& nl, double re, Density&& density,
                                 const Vec<D>& gravity, Carries&& carries) {
  const std::int64_t n = static_cast<std::int64_t>(position.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t b = 0; b < n; ++b) {
    if (!isMirroredWall(kind[b])) continue;
    pressure[b] = continuedPressureAt<D>(static_cast<std::size_t>(b), position, pressure, nl, re, density, gravity,
                                         carries).value_or(0.0);
  }
}

}  // namespace mistfall

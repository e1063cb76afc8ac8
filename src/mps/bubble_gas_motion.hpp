// Motion of the gas inside a bubble (gas enclosed in the liquid, docs/two-phase.md). The bubble's pressure is one
// unknown of the liquid system (bubble_pressure.hpp), so its gas particles carry no pressure force of their own;
// they mark where the bubble is and must fill it as the liquid around it moves:
//  * velocity: the liquid's velocity at the interface extended into the bubble, a harmonic extension by Jacobi
//    sweeps of the weighted mean over neighbours, u_i <- sum_j w_ij u_j / sum_j w_ij (j: liquid, walls and the
//    bubble's gas; open gas excluded), with w of eq. (14);
//  * position: r = r* + dt (u - u*), then the gas system's pressure correction moves them without changing their
//    velocity (re-spacing: gas squeezed by the liquid spreads through the bubble instead of blocking the liquid).
// With numerics.bubble_gas_motion = "follow_void" the gas keeps the extension's departure from its mean over the
// bubble and moves on average with the bubble's translation U_B: a harmonic extension carries no net motion of a
// void that rises (the potential flow round a cylinder rising at U has the interface velocity U (sin 2t, -cos 2t),
// whose harmonic extension is zero at the centre and zero on average), so without U_B the gas stays behind a bubble
// that moves and only a soft gas lets the void move on. U_B is the velocity of the void's centroid X (Reynolds'
// transport theorem on the bubble: d/dt int_B x dV = oint x (u.n) dS):
//   V_B U_B = oint_B (x - X)(u.n) dS.
// The liquid's velocity at the interface is known only at particles a spacing or two away, where a rising bubble's
// dipole flow has decayed by (a/r)^2, so the surface integral is turned into one over the fluid around the bubble:
// with a window psi = 1 on and near the bubble, falling smoothly to 0 (divergence theorem on the fluid F outside B,
// div u = 0 there),
//   V_B U_B = -int_F [psi u + (x - X)(u . grad psi)] dV,
// which for the dipole flow gives U exactly at any window. Summed over the particles j around B (every active
// particle but B's own gas: liquid, walls and dummies at rest, other gas with its velocity), each of volume l0^D:
//   A U_B = M,  M = -l0^D sum_j [psi_j u_j + (x_j - X)(u_j . grad psi_j)],
//              A = -l0^D sum_j [psi_j I + (x_j - X) grad psi_j^T],
// A being the same sum for a uniform velocity (V_B I in the continuum), so a rigid translation is reproduced exactly.
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <optional>
#include <vector>

#include "mps/neighbour_search.hpp"
#include "mps/particles.hpp"
#include "mps/phase_coupling.hpp"
#include "mps/wall_stop.hpp"
#include "mps/weight.hpp"

namespace mistfall {

inline constexpr int kBubbleVelocitySweeps = 4;  // each sweep reaches re further into the bubble
// The window psi of U_B: 1 to kVoidWindowInner l0 beyond the bubble's farthest gas particle from its centroid, then
// falling smoothly to 0 over kVoidWindowWidth l0; U_B is trusted where A's smallest eigenvalue is at least
// kVoidWindowTrust V_B (A = V_B I in the continuum; a threshold, not physics).
inline constexpr double kVoidWindowInner = 0.5, kVoidWindowWidth = 3.0, kVoidWindowTrust = 0.5;

// The translation U_B of each bubble (region of `region_of`, `regions` of them) from the velocity of everything around
// it (see above), spacing l0; none for a region that is no bubble and for one whose A is far from V_B I (V_B I in the
// continuum for any shape; the lattice sum departs from it where its window holds few particles), whose gas then
// moves as the extension alone.
template <int D>
std::vector<std::optional<Vec<D>>> voidTranslation(const Particles<D>& p, const CouplingRoles& roles,
                                                   const std::vector<std::int32_t>& region_of, std::size_t regions,
                                                   double l0) {
  using Mat = Eigen::Matrix<double, D, D>;
  const std::size_t n = p.size();
  std::vector<Vec<D>> centroid(regions, Vec<D>::Zero());
  std::vector<std::optional<Vec<D>>> translation(regions);
  std::vector<double> count(regions, 0.0), reach(regions, 0.0);
  auto inBubble = [&](std::size_t i) { return roles.enclosed_gas[i] && region_of[i] >= 0; };
  for (std::size_t i = 0; i < n; ++i)
    if (inBubble(i)) centroid[region_of[i]] += p.position[i], count[region_of[i]] += 1;
  for (std::size_t b = 0; b < regions; ++b)
    if (count[b] > 0) centroid[b] /= count[b];
  for (std::size_t i = 0; i < n; ++i)
    if (inBubble(i)) {
      const auto b = region_of[i];
      reach[b] = std::max(reach[b], (p.position[i] - centroid[b]).norm());
    }
  const double cell = std::pow(l0, D);
#pragma omp parallel for schedule(dynamic)
  for (std::int64_t b = 0; b < static_cast<std::int64_t>(regions); ++b) {
    if (count[b] == 0) continue;
    const double inner = reach[b] + kVoidWindowInner * l0, width = kVoidWindowWidth * l0;
    Mat a = Mat::Zero();
    Vec<D> m = Vec<D>::Zero();
    for (std::size_t j = 0; j < n; ++j) {
      if (!isActive(p.kind[j]) || (inBubble(j) && region_of[j] == b)) continue;
      const Vec<D> arm = p.position[j] - centroid[b];
      const double d = arm.norm();
      if (d >= inner + width) continue;
      double psi = 1.0;
      Vec<D> grad = Vec<D>::Zero();
      if (d > inner) {  // psi = 1 - smoothstep((d - inner) / width)
        const double s = (d - inner) / width;
        psi = 1.0 - s * s * (3.0 - 2.0 * s);
        grad = (-6.0 * s * (1.0 - s) / (width * d)) * arm;
      }
      a -= cell * (psi * Mat::Identity() + arm * grad.transpose());
      m -= cell * (psi * p.velocity[j] + arm * grad.dot(p.velocity[j]));
    }
    const double volume = count[b] * cell;
    Eigen::SelfAdjointEigenSolver<Mat> eigen(0.5 * (a + a.transpose()));
    if (eigen.eigenvalues().minCoeff() > kVoidWindowTrust * volume)
      translation[b] = Vec<D>(a.colPivHouseholderQr().solve(m));
  }
  return translation;
}

// Sets the velocity of every enclosed gas particle (roles.enclosed_gas) to the extension of its neighbours'
// velocities and moves it by dt times the change. The neighbour list must reach `re`. With `translation`
// (voidTranslation, indexed by `region_of`), the gas of each bubble that has one keeps the extension's departure from
// its mean and moves on average with it.
// With `wall_stop` > 0 (numerics.bubble_gas_wall_stop, a guard): the move loses its approach to each wall or dummy
// particle it would bring within that distance (wall_stop.hpp), and the velocity keeps only the change that the
// stopped move carries, u = u* + move / dt (the gas has no pressure force of its own to stop it: traced on the 5 mm
// waterfall, the water's velocity extended into a bubble carried its gas to 0.25 l0 from the floor's first wall
// row, docs/waterfall.md). The neighbour list must then reach wall_stop + |move| too. Returns the moves stopped.
template <int D>
std::size_t extendVelocityIntoBubbles(Particles<D>& p, const NeighbourList& nl, const CouplingRoles& roles, double re,
                                      double dt, const std::vector<std::optional<Vec<D>>>* translation = nullptr,
                                      const std::vector<std::int32_t>* region_of = nullptr, double wall_stop = 0.0) {
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  std::vector<Vec<D>> before(p.velocity.begin(), p.velocity.end()), next(n);
  for (int sweep = 0; sweep < kBubbleVelocitySweeps; ++sweep) {
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < n; ++i) {
      next[i] = p.velocity[i];
      if (!roles.enclosed_gas[i]) continue;
      Vec<D> sum = Vec<D>::Zero();
      double total = 0.0;
      for (auto s = nl.begin(i); s < nl.end(i); ++s) {
        const auto j = nl.indices[s];
        if (!isActive(p.kind[j]) || p.kind[j] == ParticleKind::Dummy || roles.open_gas[j]) continue;
        const double w = weight((p.position[j] - p.position[i]).norm(), re);
        sum += w * p.velocity[j];
        total += w;
      }
      if (total > 0.0) next[i] = sum / total;
    }
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < n; ++i)
      if (roles.enclosed_gas[i]) p.velocity[i] = next[i];
  }
  // With a translation per bubble: the extension keeps its deformation (its departure from its mean over the
  // bubble), and the bubble's gas moves on average with the void, U_B (where it has one).
  if (translation) {
    std::vector<Vec<D>> mean(translation->size(), Vec<D>::Zero());
    std::vector<double> count(translation->size(), 0.0);
    const auto& bubble_of = *region_of;
    for (std::int64_t i = 0; i < n; ++i)
      if (roles.enclosed_gas[i] && bubble_of[i] >= 0) mean[bubble_of[i]] += p.velocity[i], count[bubble_of[i]] += 1;
    for (std::int64_t i = 0; i < n; ++i)
      if (roles.enclosed_gas[i] && bubble_of[i] >= 0 && (*translation)[bubble_of[i]]) {
        const auto b = bubble_of[i];
        p.velocity[i] += *(*translation)[b] - mean[b] / count[b];
      }
  }
  auto fixed = [&](std::int32_t j) { return isFixed(p.kind[j]); };
  std::size_t stops = 0;
#pragma omp parallel for schedule(static) reduction(+ : stops)
  for (std::int64_t i = 0; i < n; ++i) {
    if (!roles.enclosed_gas[i]) continue;
    Vec<D> move = dt * (p.velocity[i] - before[i]);
    if (wall_stop > 0.0 &&
        stopDisplacementAtWalls<D>(static_cast<std::size_t>(i), p.position, nl, wall_stop, fixed, move)) {
      p.velocity[i] = before[i] + move / dt;
      ++stops;
    }
    p.position[i] += move;
  }
  return stops;
}

// Gas that has just joined the liquid system (open at the last step, enclosed now: `joined[i]`) takes the
// w-weighted mean velocity of its liquid neighbours within re: it is carried by the water from now on, and the
// gas system's velocity it brings (metres per second in a splash) would otherwise enter the water's velocity
// divergence in the pressure equation as a spike. Particles without liquid neighbours keep their velocity.
template <int D>
void adoptLiquidVelocity(Particles<D>& p, const NeighbourList& nl, const std::vector<char>& joined, double re) {
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  std::vector<Vec<D>> next(p.velocity.begin(), p.velocity.end());
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (!joined[i]) continue;
    Vec<D> sum = Vec<D>::Zero();
    double total = 0.0;
    for (auto s = nl.begin(i); s < nl.end(i); ++s) {
      const auto j = nl.indices[s];
      if (p.kind[j] != ParticleKind::Fluid || p.phase[j] != Phase::Liquid) continue;
      const double w = weight((p.position[j] - p.position[i]).norm(), re);
      sum += w * p.velocity[j];
      total += w;
    }
    if (total > 0.0) next[i] = sum / total;
  }
  p.velocity.swap(next);
}

}  // namespace mistfall

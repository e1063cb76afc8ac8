// The curvature of a bubble's interface at its gas particles, for the Laplace jump of surface tension
// (numerics.bubble_surface_tension = "jump", solver_liquid.cpp):
//   P_B - p_l = sigma kappa                     (Young-Laplace; kappa = 1/R in 2D, 2/R on a sphere in 3D)
// kappa is positive where the bubble is convex. A lattice interface is a staircase, so kappa is found from a
// smoothed colour and a local least-squares circle, as the local-fitting curvature estimates of interface-tracking
// codes are:
// 1. a bubble gas particle i with liquid within `colour_radius` has the liquid fraction phi_i = sum_liquid W / sum W
//    (W = (1 - r^2/re^2)^3, a smooth kernel) and the outward normal n_i = the normalised sum of W r_ij / |r_ij| over
//    its liquid neighbours; its interface point is q_i = r_i + d(phi_i) n_i, d read from phi by the flat lattice's
//    first two layers (LiquidFractionScale);
// 2. around each interface point, the points of the same bubble within `fit_radius` whose normals face the same side
//    are fitted in the frame of n_i (height h along n_i, tangential coordinates x) by the circle (sphere)
//      h = a + b . x + A (|x|^2 + h^2)       (taper-weighted, 1 - |q - q_i|^2 / fit_radius^2),
//    exact on a circle; kappa_i = -2 (D - 1) A (in 3D the mean of the principal curvatures, doubled);
// 3. one pass of taper-weighted smoothing over the same points.
// Measured on lattice discs with fit_radius = 5 l0 (tests/test_interface_curvature.cpp): mean kappa R = 1.098, 0.962,
// 0.982 at R = 5, 9, 20 l0, the particles' spread 0.1, 14 and 26 % of 1/R; a ball of 6 l0: +7 %.
// A point with fewer neighbours than the fit's unknowns plus two gets kappa = 0 (counted: `unfitted`).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "mps/neighbour_search.hpp"
#include "mps/pair_loop.hpp"
#include "mps/vector.hpp"

namespace mistfall {

struct InterfaceCurvature {
  std::vector<double> kappa;        // per particle [1/m]; 0 off the interface
  std::vector<char> on_interface;   // a bubble gas particle whose interface point was placed
  std::size_t interface_count = 0;  // particles on the interface
  std::size_t unfitted = 0;         // interface particles with too few points for the fit (kappa = 0)
};

// The colour's kernel, (1 - q^2)^3 with q = r / radius: smooth, where eq. (14)'s 1/r lets a nearest neighbour
// dominate.
inline double smoothColourWeight(double q) { return q >= 1.0 ? 0.0 : (1.0 - q * q) * (1.0 - q * q) * (1.0 - q * q); }

// The liquid fraction phi of a gas particle on a flat lattice interface: phi_1 on the first layer (its centre l0/2
// from the interface), phi_2 on the second (3 l0/2). A particle's depth under the interface is read from its phi on
// the line through both: d / l0 = 1/2 + (phi_1 - phi) / (phi_1 - phi_2).
struct LiquidFractionScale {
  double first_layer = 0.0, second_layer = 0.0;
  double depth(double phi) const { return 0.5 + (first_layer - phi) / (first_layer - second_layer); }
};

inline LiquidFractionScale liquidFractionScale(int dimension, double radius_over_l0) {
  const int k = static_cast<int>(std::ceil(radius_over_l0));
  double all = 0.0, layer1 = 0.0, layer2 = 0.0;
  for (int x = -k; x <= k; ++x)
    for (int y = -k; y <= k; ++y)
      for (int z = (dimension == 3 ? -k : 0); z <= (dimension == 3 ? k : 0); ++z) {
        const double r = std::sqrt(double(x * x + y * y + z * z));
        if (r == 0.0) continue;
        const double w = smoothColourWeight(r / radius_over_l0);
        all += w;
        if (y >= 1) layer1 += w;  // liquid above the first layer
        if (y >= 2) layer2 += w;  // and above the second
      }
  return {layer1 / all, layer2 / all};
}

// `nl` must hold each particle's neighbours within colour_radius; `bubble_of(j)`: the bubble (>= 0) of gas
// particle j, or -1; `liquid(j)`: j is liquid.
template <int D, class BubbleOf, class Liquid>
InterfaceCurvature interfaceCurvature(const std::vector<Vec<D>>& position, const NeighbourList& nl, double l0,
                                      double colour_radius, double fit_radius, BubbleOf&& bubble_of,
                                      Liquid&& liquid) {
  const std::int64_t n = static_cast<std::int64_t>(position.size());
  InterfaceCurvature out;
  out.kappa.assign(n, 0.0);
  out.on_interface.assign(n, 0);
  // 1. the interface points
  std::vector<Vec<D>> normal(n, Vec<D>::Zero()), point(n, Vec<D>::Zero());
  const LiquidFractionScale scale = liquidFractionScale(D, colour_radius / l0);
  auto any = [](std::int32_t) { return true; };
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (bubble_of(static_cast<std::int32_t>(i)) < 0) continue;
    Vec<D> sum = Vec<D>::Zero();
    double liquid_weight = 0.0, all_weight = 0.0;
    forEachPairWithin<D>(i, position, nl, colour_radius, any, [&](std::int32_t j, const Vec<D>& rij, double r2, double) {
      const double r = std::sqrt(r2), w = smoothColourWeight(r / colour_radius);
      all_weight += w;
      if (!liquid(j)) return;
      liquid_weight += w;
      sum += rij * (w / r);
    });
    if (sum.norm() == 0.0) continue;
    const double fraction = liquid_weight / all_weight;
    if (fraction < 0.5 * scale.second_layer) continue;  // too deep to place the interface from
    normal[i] = sum.normalized();
    point[i] = position[i] + scale.depth(fraction) * l0 * normal[i];
    out.on_interface[i] = 1;
  }
  std::vector<std::int32_t> on;  // the interface's particles, and a neighbour list of their points
  for (std::int64_t i = 0; i < n; ++i)
    if (out.on_interface[i]) on.push_back(static_cast<std::int32_t>(i));
  out.interface_count = on.size();
  if (on.empty()) return out;
  std::vector<Vec<D>> q(on.size());
  Vec<D> lower = point[on[0]], upper = point[on[0]];
  for (std::size_t k = 0; k < on.size(); ++k) {
    q[k] = point[on[k]];
    lower = lower.cwiseMin(q[k]), upper = upper.cwiseMax(q[k]);
  }
  NeighbourSearch<D> search(lower.array() - l0, upper.array() + l0, fit_radius);
  NeighbourList near;
  search.build(q, std::vector<ParticleKind>(on.size(), ParticleKind::Fluid), near);
  const auto m = static_cast<std::int64_t>(on.size());
  auto sameSide = [&](std::int64_t a, std::int32_t b) {
    return bubble_of(on[b]) == bubble_of(on[a]) && normal[on[b]].dot(normal[on[a]]) > 0.0;
  };
  auto taper = [&](std::int64_t a, std::int32_t b) {
    return std::max(0.0, 1.0 - (q[b] - q[a]).squaredNorm() / (fit_radius * fit_radius));
  };
  // 2. the circle through each point's neighbourhood: unknowns a, b (D - 1), A
  constexpr int kTangent = D - 1;
  constexpr int kUnknowns = 2 + kTangent;
  std::vector<double> fitted(on.size(), 0.0);
  std::vector<char> has_fit(on.size(), 0);
  std::size_t unfitted = 0;
#pragma omp parallel for schedule(static) reduction(+ : unfitted)
  for (std::int64_t a = 0; a < m; ++a) {
    const Vec<D> ni = normal[on[a]];
    Eigen::Matrix<double, D, kTangent> tangent;  // Gram-Schmidt on the axes but the one closest to n_i
    int closest = 0;
    for (int axis = 1; axis < D; ++axis)
      if (std::abs(ni[axis]) > std::abs(ni[closest])) closest = axis;
    for (int axis = 0, filled = 0; axis < D; ++axis) {
      if (axis == closest) continue;
      Vec<D> e = Vec<D>::Unit(axis);
      e -= ni * ni.dot(e);
      for (int t = 0; t < filled; ++t) e -= tangent.col(t) * tangent.col(t).dot(e);
      tangent.col(filled++) = e.normalized();
    }
    std::vector<std::int32_t> used{static_cast<std::int32_t>(a)};
    for (auto s = near.begin(a); s < near.end(a); ++s)
      if (sameSide(a, near.indices[s]) && taper(a, near.indices[s]) > 0.0) used.push_back(near.indices[s]);
    if (static_cast<int>(used.size()) < kUnknowns + 2) {
      ++unfitted;
      continue;
    }
    Eigen::Matrix<double, Eigen::Dynamic, kUnknowns> system(used.size(), kUnknowns);
    Eigen::VectorXd heights(used.size());
    for (std::size_t r = 0; r < used.size(); ++r) {
      const Vec<D> d = q[used[r]] - q[a];
      const double w = used[r] == a ? 1.0 : taper(a, used[r]);
      const Eigen::Matrix<double, kTangent, 1> x = tangent.transpose() * d;
      system(r, 0) = w;
      for (int t = 0; t < kTangent; ++t) system(r, 1 + t) = w * x[t];
      system(r, kUnknowns - 1) = w * d.squaredNorm();
      heights[r] = w * d.dot(ni);
    }
    const Eigen::Matrix<double, kUnknowns, 1> c = system.colPivHouseholderQr().solve(heights);
    fitted[a] = -2.0 * kTangent * c[kUnknowns - 1];
    has_fit[a] = 1;
  }
  out.unfitted = unfitted;
  // 3. one pass of smoothing: each fit carries noise of about 0.04 / l0 from the staircase
#pragma omp parallel for schedule(static)
  for (std::int64_t a = 0; a < m; ++a) {
    if (!has_fit[a]) continue;
    double sum = fitted[a], weights = 1.0;
    for (auto s = near.begin(a); s < near.end(a); ++s) {
      const auto b = near.indices[s];
      if (!has_fit[b] || !sameSide(a, b)) continue;
      const double w = taper(a, b);
      sum += w * fitted[b], weights += w;
    }
    out.kappa[on[a]] = sum / weights;
  }
  return out;
}

}  // namespace mistfall

// The cavity of a bubble (numerics.bubble_cavity = "joined", experimental; docs/validation.md, "A bubble's void").
// A bubble is the space the water encloses, eq. (7)'s delta_gl region; its gas particles mark it but, moved with the
// water (bubble_gas_motion.hpp), need not fill it: where the water moves away faster, an empty cavity opens that no
// particle covers. Its edge water would be a free surface at the surface pressure and the cavity in no row, so the
// bubble's pressure P_B never sees its void grow (the stiff coarse bubble: void +104 % at 0.1 s). With the key the
// cavity is the bubble's: the water bordering it joins P_B's unknown (bubble_pressure.hpp) with its divergence, and
// the cavity's area A_c counts in the bubble's density term as gas expanded by A_c / l0^2 cells,
//   row_B += -gamma rho / dt^2 * A_c / l0^2.
// The cavity is found on a grid of samples l0/6 apart round the bubble's gas: samples within 0.75 l0 of an active
// particle are covered (by the nearest: a sample of a square lattice lies within l0/2^(1/2) of its particle); the
// cavity is the uncovered samples joined side by side to the samples the bubble's gas covers (a flood fill), and its
// edge the water covering a sample next to it. A cavity that reaches the grid's edge, 8 l0 past the gas, is open
// (the bubble has met the surface) and is left alone. 2D only (the case reader refuses 3D).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "mps/particles.hpp"

namespace mistfall {

struct BubbleCavity {
  double cells = 0.0;               // the area the bubble's gas covers (its Voronoi cells) [m^2]
  double area = 0.0;                // A_c, the cavity's [m^2]
  bool open = false;                // reached the grid's edge: not a cavity of this bubble
  std::vector<std::int32_t> edge;   // the water particles bordering it
};

// The cavity of the bubble whose gas particles are those with isGas(i) (tests/support/bubble_void.hpp measures a
// bubble's void, cells plus cavity, with it).
template <int D, class IsGas>
BubbleCavity findBubbleCavity(const Particles<D>& p, IsGas&& isGas, double l0) {
  BubbleCavity out;
  if constexpr (D != 2) {
    return out;
  } else {
    constexpr double kCover = 0.75, kMargin = 8.0;
    const double h = l0 / 6, cover = kCover * l0;  // 6 samples a spacing
    double lo[2] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
    double hi[2] = {-lo[0], -lo[1]};
    for (std::size_t i = 0; i < p.size(); ++i)
      if (isGas(i))
        for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], p.position[i][d]), hi[d] = std::max(hi[d], p.position[i][d]);
    if (lo[0] > hi[0]) return out;
    const double x0 = lo[0] - kMargin * l0, y0 = lo[1] - kMargin * l0;
    const int nx = static_cast<int>(std::ceil((hi[0] - lo[0] + 2 * kMargin * l0) / h));
    const int ny = static_cast<int>(std::ceil((hi[1] - lo[1] + 2 * kMargin * l0) / h));
    std::vector<double> nearest(static_cast<std::size_t>(nx) * ny, std::numeric_limits<double>::infinity());
    std::vector<std::int32_t> owner(nearest.size(), -1);
    const int span = static_cast<int>(std::ceil(cover / h)) + 1;
    for (std::size_t k = 0; k < p.size(); ++k) {
      if (!isActive(p.kind[k])) continue;
      const int ci = static_cast<int>(std::floor((p.position[k][0] - x0) / h));
      const int cj = static_cast<int>(std::floor((p.position[k][1] - y0) / h));
      if (ci < -span || cj < -span || ci > nx + span || cj > ny + span) continue;
      for (int j = std::max(cj - span, 0); j < std::min(cj + span + 1, ny); ++j)
        for (int i = std::max(ci - span, 0); i < std::min(ci + span + 1, nx); ++i) {
          const double d = std::hypot(x0 + (i + 0.5) * h - p.position[k][0], y0 + (j + 0.5) * h - p.position[k][1]);
          const std::size_t s = static_cast<std::size_t>(j) * nx + i;
          if (d <= cover && d < nearest[s]) nearest[s] = d, owner[s] = static_cast<std::int32_t>(k);
        }
    }
    std::vector<char> reached(nearest.size(), 0), edge(p.size(), 0);
    std::vector<std::size_t> stack;
    for (std::size_t s = 0; s < nearest.size(); ++s)
      if (owner[s] >= 0 && isGas(static_cast<std::size_t>(owner[s]))) reached[s] = 1, stack.push_back(s), out.cells += h * h;
    const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
    while (!stack.empty()) {
      const std::size_t s = stack.back();
      stack.pop_back();
      const int i = static_cast<int>(s % nx), j = static_cast<int>(s / nx);
      for (int e = 0; e < 4; ++e) {
        const int a = i + di[e], b = j + dj[e];
        if (a < 0 || b < 0 || a >= nx || b >= ny) continue;
        const std::size_t t = static_cast<std::size_t>(b) * nx + a;
        if (reached[t]) continue;
        if (owner[t] >= 0) {  // covered: water next to a cavity sample is its edge
          const auto k = static_cast<std::size_t>(owner[t]);
          if (owner[s] < 0 && p.phase[k] == Phase::Liquid && p.kind[k] == ParticleKind::Fluid) edge[k] = 1;
          continue;
        }
        reached[t] = 1, stack.push_back(t), out.area += h * h;
        if (a == 0 || b == 0 || a == nx - 1 || b == ny - 1) out.open = true;
      }
    }
    for (std::size_t k = 0; k < p.size(); ++k)
      if (edge[k]) out.edge.push_back(static_cast<std::int32_t>(k));
    return out;
  }
}

}  // namespace mistfall

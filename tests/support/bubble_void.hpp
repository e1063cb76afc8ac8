// A 2D bubble's void: the space the water leaves it, which its gas particles mark but need not fill (the measure of
// tools/bubble_void.py, docs/validation.md). On a grid of samples l0/6 apart around the bubble:
//  * the gas's cells: samples whose nearest active particle lies within 0.75 l0 and is the bubble's gas (its
//    Voronoi cells: a sample of a square lattice lies within l0/2^(1/2) of its particle);
//  * the cavity: samples no active particle covers within 0.75 l0, joined side by side to the gas's cells.
// The sum of l0^2 n0 / n_i over the gas sees a cavity only through the number density at its edge.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "mps/particles.hpp"

namespace mistfall::test_support {

struct BubbleVoid {
  double cells = 0.0;   // the gas's cells [m^2]
  double cavity = 0.0;  // the empty space joined to them [m^2]
  bool open = false;    // the cavity reached the grid's edge (8 l0 past the gas)
  double area() const { return cells + cavity; }
};

// `in_bubble`: per particle, whether it is the bubble's gas.
inline BubbleVoid bubbleVoid(const Particles<2>& p, const std::vector<char>& in_bubble, double l0) {
  constexpr int kSamples = 6;  // per spacing
  const double h = l0 / kSamples, cover = 0.75 * l0, margin = 8.0 * l0;
  double lo[2] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  double hi[2] = {-lo[0], -lo[1]};
  for (std::size_t i = 0; i < p.size(); ++i)
    if (in_bubble[i])
      for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], p.position[i][d]), hi[d] = std::max(hi[d], p.position[i][d]);
  BubbleVoid out;
  if (lo[0] > hi[0]) return out;
  const double x0 = lo[0] - margin, y0 = lo[1] - margin;
  const int nx = static_cast<int>(std::ceil((hi[0] - lo[0] + 2 * margin) / h));
  const int ny = static_cast<int>(std::ceil((hi[1] - lo[1] + 2 * margin) / h));
  std::vector<double> best(static_cast<std::size_t>(nx) * ny, std::numeric_limits<double>::infinity());
  std::vector<char> gas(best.size(), 0);
  const int span = static_cast<int>(std::ceil(cover / h)) + 1;
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (!isActive(p.kind[k])) continue;
    const int ci = static_cast<int>(std::floor((p.position[k][0] - x0) / h));
    const int cj = static_cast<int>(std::floor((p.position[k][1] - y0) / h));
    for (int j = std::max(cj - span, 0); j < std::min(cj + span + 1, ny); ++j)
      for (int i = std::max(ci - span, 0); i < std::min(ci + span + 1, nx); ++i) {
        const double d = std::hypot(x0 + (i + 0.5) * h - p.position[k][0], y0 + (j + 0.5) * h - p.position[k][1]);
        const std::size_t s = static_cast<std::size_t>(j) * nx + i;
        if (d <= cover && d < best[s]) best[s] = d, gas[s] = in_bubble[k];
      }
  }
  // the cavity: a flood fill from the gas's cells through the uncovered samples
  std::vector<char> reached(best.size(), 0);
  std::vector<std::size_t> stack;
  for (std::size_t s = 0; s < best.size(); ++s)
    if (gas[s]) reached[s] = 1, stack.push_back(s), out.cells += h * h;
  while (!stack.empty()) {
    const std::size_t s = stack.back();
    stack.pop_back();
    const int i = static_cast<int>(s % nx), j = static_cast<int>(s / nx);
    const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
    for (int e = 0; e < 4; ++e) {
      const int a = i + di[e], b = j + dj[e];
      if (a < 0 || b < 0 || a >= nx || b >= ny) continue;
      const std::size_t t = static_cast<std::size_t>(b) * nx + a;
      if (reached[t] || std::isfinite(best[t])) continue;  // covered samples are the gas's cells or the water's
      reached[t] = 1, stack.push_back(t), out.cavity += h * h;
      if (a == 0 || b == 0 || a == nx - 1 || b == ny - 1) out.open = true;
    }
  }
  return out;
}

}  // namespace mistfall::test_support

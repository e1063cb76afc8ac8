// A 2D bubble's void: the space the water leaves it, which its gas particles mark but need not fill (the measure of
// tools/bubble_void.py, docs/validation.md): its gas's cells plus the empty cavity joined to them, found as
// numerics.bubble_cavity finds a cavity (src/mps/bubble_cavity.hpp: samples l0/6 apart, covered within 0.75 l0 by
// their nearest active particle, the cavity the uncovered samples joined side by side to the gas's).
// The sum of l0^2 n0 / n_i over the gas sees a cavity only through the number density at its edge.
#pragma once

#include <vector>

#include "mps/bubble_cavity.hpp"

namespace mistfall::test_support {

struct BubbleVoid {
  double cells = 0.0;   // the gas's cells [m^2]
  double cavity = 0.0;  // the empty space joined to them [m^2]
  bool open = false;    // the cavity reached the grid's edge (8 l0 past the gas)
  double area() const { return cells + cavity; }
};

// `in_bubble`: per particle, whether it is the bubble's gas.
inline BubbleVoid bubbleVoid(const Particles<2>& p, const std::vector<char>& in_bubble, double l0) {
  const BubbleCavity c = findBubbleCavity<2>(p, [&](std::size_t i) { return in_bubble[i] != 0; }, l0);
  return {c.cells, c.area, c.open};
}

}  // namespace mistfall::test_support

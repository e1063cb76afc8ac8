// Thresholds of the six-category classification (classification.hpp, section 3.1). Every field is a key of the
// case file's [classify] table (docs/case-file.md); the defaults are chosen on lattices (tests/test_classification.cpp):
// a lone particle and a clump of 2-4 (2D) or up to 8 (3D) particles is isolated, the outermost row of a block is
// surface and everything further in is bulk (the numbers quoted below are for re = 2.1 l0).
#pragma once

namespace mistfall {

struct ClassificationParameters {
  // Isolated (droplet / bubble) when the number density over the particle's own phase (walls not counted) is below
  // this fraction of n0. A pair of particles at l0 has 0.17 n0 in 2D and 0.08 n0 in 3D; a row one particle thick
  // has 0.35 n0 in 2D.
  double isolated_number_density = 0.2;
  // Isolated also when the particle has fewer neighbours of its own phase within re than this fraction of an
  // interior lattice particle's count (12 in 2D, 32 in 3D at re = 2.1 l0): fewer than 3.6 in 2D (a 2 x 2 clump
  // has 3, a block's corner 5), fewer than 9.6 in 3D (a 2 x 2 x 2 clump has 7, a block's corner 10).
  double isolated_neighbour_fraction = 0.3;
  // Surface when the number density over the own phase and the walls is below this fraction of n0 (the solver's
  // free-surface beta). A block's outermost row has at most 0.68 n0 (2D) / 0.73 n0 (3D), the next row 0.99 n0.
  double surface_number_density = 0.97;
  // Surface also when the spatial rate of change of the number density, |grad n|_i l0 / n0 (own phase and walls),
  // exceeds this. On a lattice a block's outermost row has 0.63-0.73 (2D) and 0.50-0.56 (3D), the next row
  // 0.08-0.11 (2D) and 0.04-0.06 (3D), rows further in 0. This test finds the surface of compressed water, whose
  // number density is not low: a block squeezed to 0.87 l0 spacing has n >= n0 on its outermost row, whose gradient
  // is then 1.04 (2D) and 0.86 (3D) while the next row's is at most 0.37 (2D) and 0.32 (3D).
  double surface_gradient = 0.4;
};

}  // namespace mistfall

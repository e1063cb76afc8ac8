// Test helper: a lattice of spacing kL0 around a centre particle (index 0 at the origin), full, cut above
// the centre's row (the centre on a free surface) or jittered, and its neighbour list; for the stabilised scheme's
// pairwise terms (tests/test_pressure_repulsion.cpp, tests/test_particle_shifting.cpp).
#pragma once

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "mps/neighbour_search.hpp"
#include "lattice.hpp"

namespace mistfall::test_support {

constexpr double kL0 = 0.01;

enum class Shape { Full, CutAbove, Jittered };
struct Neighbourhood {
  Shape shape;
  const char* name;
};
inline const Neighbourhood kShapes[] = {
    {Shape::Full, "full"}, {Shape::CutAbove, "cut_above"}, {Shape::Jittered, "jittered"}};

// Positions of a lattice of spacing l0 in [-3, 3]^D, the centre (index 0) at the origin; CutAbove drops the points
// above the centre's row, Jittered moves every point but the centre by up to 0.2 l0. The last axis is vertical.
template <int D>
std::vector<Vec<D>> lattice(Shape shape) {
  std::vector<Vec<D>> x{Vec<D>::Zero()};
  std::mt19937 random(11);
  std::uniform_real_distribution<double> jitter(-0.2 * kL0, 0.2 * kL0);
  using Index = Eigen::Matrix<int, D, 1>;
  const Index lo = Index::Constant(-3), hi = Index::Constant(3);
  test_support::forEachLatticePoint<D>(lo, hi, [&](const Index& k) {
    if ((k.array() == 0).all() || (shape == Shape::CutAbove && k[D - 1] > 0)) return;
    Vec<D> r = kL0 * k.template cast<double>();
    if (shape == Shape::Jittered)
      for (int a = 0; a < D; ++a) r[a] += jitter(random);
    x.push_back(r);
  });
  return x;
}

template <int D>
NeighbourList neighboursOf(const std::vector<Vec<D>>& x, double radius) {
  NeighbourSearch<D> search(Vec<D>::Constant(-0.05), Vec<D>::Constant(0.05), radius);
  NeighbourList nl;
  search.build(x, std::vector<ParticleKind>(x.size(), ParticleKind::Fluid), nl);
  return nl;
}

inline std::string shapeName(const ::testing::TestParamInfo<Neighbourhood>& info) { return info.param.name; }

}  // namespace mistfall::test_support

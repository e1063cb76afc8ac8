// The particle shifting of the stabilised scheme (numerics.particle_shifting, src/mps/particle_shifting.hpp):
//  * a particle at rest is not shifted, whatever its neighbourhood (the still tanks stay exact);
//  * on a full lattice nothing is shifted at any speed, and on a free-surface row's (cut) lattice nothing either
//    once the normal part is removed;
//  * a particle whose neighbour crowds it from one side moves away from it, by A l0 |u| dt D0/n0 |first moment|.
#include <gtest/gtest.h>

#include "mps/particle_shifting.hpp"
#include "support/shaped_lattice.hpp"

using namespace mistfall;
using namespace mistfall::test_support;

namespace {

auto all = [](std::int32_t) { return true; };

template <int D>
void checkNoShiftAtRestOrOnALattice(Shape shape) {
  const auto x = lattice<D>(shape);
  const MpsConstants c = referenceConstants(D, kL0, 2.1, 3.1);
  const auto nl = neighboursOf<D>(x, c.re_laplacian);
  Vec<D> normal = Vec<D>::Zero();
  normal[D - 1] = -1.0;  // the pressure gradient's direction under a free surface
  const Vec<D> at_rest = shiftingDisplacement<D>(0, x, nl, c, 2.0, Vec<D>::Zero(), 1e-3, Vec<D>::Zero(), all);
  EXPECT_EQ(at_rest.norm(), 0.0);
  const Vec<D> moving = Vec<D>::Constant(0.5);
  if (shape == Shape::Full)
    EXPECT_LT(shiftingDisplacement<D>(0, x, nl, c, 2.0, moving, 1e-3, Vec<D>::Zero(), all).norm(), 1e-15);
  if (shape == Shape::CutAbove) {
    EXPECT_GT(shiftingDisplacement<D>(0, x, nl, c, 2.0, moving, 1e-3, Vec<D>::Zero(), all).norm(), 1e-7);
    EXPECT_LT(shiftingDisplacement<D>(0, x, nl, c, 2.0, moving, 1e-3, normal, all).norm(), 1e-15);
  }
}

class ShiftingOnLattices : public ::testing::TestWithParam<Neighbourhood> {};
INSTANTIATE_TEST_SUITE_P(Shapes, ShiftingOnLattices, ::testing::ValuesIn(kShapes), shapeName);

}  // namespace

TEST_P(ShiftingOnLattices, NoneAtRestNoneOnALattice2D) { checkNoShiftAtRestOrOnALattice<2>(GetParam().shape); }
TEST_P(ShiftingOnLattices, NoneAtRestNoneOnALattice3D) { checkNoShiftAtRestOrOnALattice<3>(GetParam().shape); }

// A full 2D lattice whose neighbour at +x sits at 0.6 l0: the particle, moving at 0.3 m/s with dt = 1 ms, is shifted
// towards -x by A l0 |u| dt D0/n0 times the first moment.
TEST(ParticleShifting, MovesAwayFromACrowdingNeighbourByTheFormula) {
  auto x = lattice<2>(Shape::Full);
  for (auto& r : x)
    if ((r - Vec<2>(kL0, 0.0)).norm() < 1e-12) r = Vec<2>(0.6 * kL0, 0.0);
  const MpsConstants c = referenceConstants(2, kL0, 2.1, 3.1);
  const auto nl = neighboursOf<2>(x, c.re_laplacian);
  const Vec<2> u(0.0, 0.3);
  const Vec<2> shift = shiftingDisplacement<2>(0, x, nl, c, 2.0, u, 1e-3, Vec<2>::Zero(), all);
  Vec<2> first = Vec<2>::Zero();
  for (std::size_t j = 1; j < x.size(); ++j) {
    const double r = x[j].norm();
    if (r < c.re_number_density) first += x[j] * ((c.re_number_density / r - 1.0) / (r * r));
  }
  EXPECT_LT(shift.x(), 0.0);
  EXPECT_NEAR(shift.x(), -2.0 * kL0 * 0.3 * 1e-3 * 2.0 / c.n0 * first.x(), 1e-12 * kL0);
  EXPECT_NEAR(shift.y(), 0.0, 1e-15);
}

// The repulsive term of the stabilised gradient (numerics.pressure_repulsion, src/mps/pressure_repulsion.hpp):
//  * it is zero in a linear pressure field on a full, a cut (free-surface) and a jittered neighbourhood, in 2D and
//    3D, so still water keeps its exact equilibrium;
//  * with a particle-scale pressure excess it pushes a particle away from the side where its neighbours crowd, with
//    the magnitude of the formula; near the free surface only along the surface;
// (The sloshing tank it was built for: tests/test_physics_sloshing.cpp.)
#include <gtest/gtest.h>

#include <cmath>

#include "mps/pressure_repulsion.hpp"
#include "support/shaped_lattice.hpp"

using namespace mistfall;

namespace {

using namespace mistfall::test_support;

auto all = [](std::int32_t) { return true; };

template <int D>
void checkLinearFieldGivesNoRepulsion(Shape shape) {
  const auto x = lattice<D>(shape);
  const MpsConstants c = referenceConstants(D, kL0, 2.1, 3.1);
  const auto nl = neighboursOf<D>(x, c.re_laplacian);
  const Vec<D> slope = Vec<D>::LinSpaced(-3.0, 5.0) * 1000.0;  // [Pa/m]
  auto difference = [&](std::int32_t j, const Vec<D>& rij) { return slope.dot(rij); };
  const Vec<D> repulsion = pressureRepulsion<D>(0, x, nl, c, 2.0, slope, Vec<D>::Zero(), all, difference);
  EXPECT_LT(repulsion.norm(), 1e-9 * slope.norm());
}

class RepulsionOnLinearFields : public ::testing::TestWithParam<Neighbourhood> {};
INSTANTIATE_TEST_SUITE_P(Shapes, RepulsionOnLinearFields, ::testing::ValuesIn(kShapes), shapeName);

TEST_P(RepulsionOnLinearFields, IsZero2D) { checkLinearFieldGivesNoRepulsion<2>(GetParam().shape); }
TEST_P(RepulsionOnLinearFields, IsZero3D) { checkLinearFieldGivesNoRepulsion<3>(GetParam().shape); }

// A full 2D lattice whose neighbour at +x sits at 0.6 l0 instead of l0; the centre's pressure exceeds the linear
// field by 50 Pa (every neighbour's bracket is -50 Pa). The term is K D0/n0 50 Pa times the first moment, which
// points to the crowded side: the gradient grows towards +x and the particle is pushed to -x.
TEST(PressureRepulsion, PushesAwayFromTheCrowdedSideWithTheFormulasMagnitude) {
  auto x = lattice<2>(Shape::Full);
  std::size_t close = 0;
  for (std::size_t j = 1; j < x.size(); ++j)
    if ((x[j] - Vec<2>(kL0, 0.0)).norm() < 1e-12) close = j;
  ASSERT_GT(close, 0u);
  x[close] = Vec<2>(0.6 * kL0, 0.0);
  const MpsConstants c = referenceConstants(2, kL0, 2.1, 3.1);
  const auto nl = neighboursOf<2>(x, c.re_laplacian);
  const Vec<2> slope(0.0, -9810.0);
  const double excess = 50.0;
  auto difference = [&](std::int32_t j, const Vec<2>& rij) { return slope.dot(rij) - excess; };
  const Vec<2> repulsion = pressureRepulsion<2>(0, x, nl, c, 2.0, slope, Vec<2>::Zero(), all, difference);
  Vec<2> first = Vec<2>::Zero();
  for (std::size_t j = 1; j < x.size(); ++j) {
    const double r = x[j].norm();
    if (r < c.re_number_density) first += x[j] * ((c.re_number_density / r - 1.0) / (r * r));
  }
  ASSERT_GT(first.x(), 0.0);
  EXPECT_NEAR(repulsion.x(), 2.0 * 2.0 / c.n0 * excess * first.x(), 1e-9 * repulsion.norm());
  EXPECT_GT(repulsion.x(), 0.0);  // -grad p / rho points to -x: away from the close neighbour
  EXPECT_NEAR(repulsion.y(), 0.0, 1e-9 * repulsion.norm());
}

// On a free-surface row's neighbourhood (cut above) the first moment points down; with the surface normal given, the
// term keeps only its part along the surface: a particle near the surface is not pushed into or out of it.
TEST(PressureRepulsion, NearTheSurfaceActsAlongItOnly) {
  auto x = lattice<2>(Shape::CutAbove);
  x[1] += Vec<2>(0.0, 0.3 * kL0);  // an asymmetry with both components
  x[2] += Vec<2>(0.25 * kL0, 0.0);
  const MpsConstants c = referenceConstants(2, kL0, 2.1, 3.1);
  const auto nl = neighboursOf<2>(x, c.re_laplacian);
  const Vec<2> slope(0.0, -9810.0);
  auto difference = [&](std::int32_t, const Vec<2>& rij) { return slope.dot(rij) - 50.0; };
  const Vec<2> free = pressureRepulsion<2>(0, x, nl, c, 2.0, slope, Vec<2>::Zero(), all, difference);
  const Vec<2> along = pressureRepulsion<2>(0, x, nl, c, 2.0, slope, Vec<2>(0.0, -1.0), all, difference);
  ASSERT_GT(std::abs(free.y()), 10.0 * std::abs(free.x()));  // cut above: mostly along the normal
  EXPECT_NEAR(along.y(), 0.0, 1e-12 * free.norm());
  EXPECT_NEAR(along.x(), free.x(), 1e-12 * free.norm());
}

}  // namespace


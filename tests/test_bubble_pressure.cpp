// One pressure unknown per bubble (src/mps/bubble_pressure.hpp): the merged system is T^T A T with the bubble's
// eq. (17) shift on its diagonal; a bubble squeezed uniformly holds rho_g c^2 delta; c -> infinity approaches the
// incompressible bubble as 1/c^2; merging equals the limit of infinitely strong coupling inside the bubble.
#include <gtest/gtest.h>

#include <cmath>

#include "mps/bubble_pressure.hpp"
#include "support/exact_solve.hpp"

using namespace mistfall;
using test_support::solveExactly;

namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// A chain 0 - 1 - 2 - 3 - 4 of particles (one unknown each) with unit couplings, particle 0 tied to a Dirichlet
// boundary (extra 1 on its diagonal); particles 2 and 3 form a bubble when grouped. `inside` scales the coupling
// between 2 and 3.
PressureSystem chain(double inside = 1.0) {
  PressureSystem sys;
  const int n = 5;
  std::vector<Eigen::Triplet<double>> t;
  auto couple = [&](int a, int b, double k) {
    t.emplace_back(a, a, k);
    t.emplace_back(b, b, k);
    t.emplace_back(a, b, -k);
    t.emplace_back(b, a, -k);
  };
  for (int i = 0; i + 1 < n; ++i) couple(i, i + 1, i == 2 ? inside : 1.0);
  t.emplace_back(0, 0, 1.0);
  sys.matrix.resize(n, n);
  sys.matrix.setFromTriplets(t.begin(), t.end());
  sys.rhs = Eigen::VectorXd::Zero(n);
  sys.rhs << 0.0, 0.0, 2.0, 1.0, -0.5;
  for (int i = 0; i < n; ++i) sys.particle_of.push_back(i), sys.row_of.push_back(i);
  return sys;
}

const std::vector<std::int32_t> kGroups{-1, -1, 0, 0, -1};

}  // namespace

TEST(BubblePressure, MergedSystemSumsTheBubbleRowsAndColumns) {
  const PressureSystem sys = chain();
  LumpedPressureSystem lumped;
  lumpPressureGroups(sys, kGroups, {0.25}, lumped);
  ASSERT_EQ(4, lumped.matrix.rows());
  EXPECT_EQ(3, lumped.first_group_row);
  EXPECT_EQ((std::vector<std::int32_t>{0, 1, 3, 3, 2}), lumped.column_of_row);
  const Eigen::MatrixXd a = Eigen::MatrixXd(lumped.matrix);
  // Rows 2 and 3 of the chain summed (their mutual coupling cancels): neighbours 1 and 4, diagonal 1 + 1 + shift.
  Eigen::MatrixXd expected(4, 4);
  expected << 2, -1, 0, 0,   //
      -1, 2, 0, -1,          //
      0, 0, 1, -1,           //
      0, -1, -1, 2.25;
  EXPECT_LT((a - expected).norm(), 1e-14) << a;
  EXPECT_DOUBLE_EQ(3.0, lumped.rhs[3]);
  EXPECT_DOUBLE_EQ(-0.5, lumped.rhs[2]);
  EXPECT_LT((a - a.transpose()).norm(), 1e-14);
}

TEST(BubblePressure, MergingIsTheLimitOfInfinitelyStrongCouplingInsideTheBubble) {
  LumpedPressureSystem lumped;
  lumpPressureGroups(chain(), kGroups, {0.0}, lumped);
  const Eigen::VectorXd merged = solveExactly(lumped.matrix, lumped.rhs);
  double previous = INFINITY;
  for (double inside : {1e2, 1e4, 1e6}) {
    const PressureSystem strong = chain(inside);
    const Eigen::VectorXd p = solveExactly(strong.matrix, strong.rhs);
    double error = 0.0;
    for (int r = 0; r < 5; ++r) error = std::max(error, std::abs(p[r] - merged[lumped.column_of_row[r]]));
    EXPECT_LT(error, 0.5 * previous) << "coupling " << inside;
    previous = error;
  }
  EXPECT_LT(previous, 1e-4);
}

TEST(BubblePressure, UniformlySqueezedBubbleHoldsRhoGasCSquaredDelta) {
  // A bubble of N = 3 particles, no liquid unknowns around it (only its own couplings): each row's source is
  // rho_ref / dt^2 * delta; the merged row is N rho_ref / (rho_g dt^2 c^2) P = N rho_ref / dt^2 delta.
  const double rho_ref = 1000.0, rho_g = 1.2, c = 340.0, dt = 2.5e-4, delta = 0.004;
  PressureSystem sys;
  sys.matrix.resize(3, 3);
  std::vector<Eigen::Triplet<double>> t{{0, 0, 1}, {1, 1, 2}, {2, 2, 1}, {0, 1, -1}, {1, 0, -1}, {1, 2, -1}, {2, 1, -1}};
  sys.matrix.setFromTriplets(t.begin(), t.end());
  sys.rhs = Eigen::VectorXd::Constant(3, rho_ref / (dt * dt) * delta);
  sys.particle_of = {0, 1, 2};
  LumpedPressureSystem lumped;
  lumpPressureGroups(sys, {0, 0, 0}, {3 * rho_ref / (rho_g * dt * dt * c * c)}, lumped);
  ASSERT_EQ(1, lumped.matrix.rows());
  const double p = lumped.rhs[0] / lumped.matrix.coeff(0, 0);
  EXPECT_NEAR(rho_g * c * c * delta, p, 1e-9 * p);  // 555 Pa: about the hydrostatic pressure 5.7 cm deep
}

TEST(BubblePressure, CompressibleBubbleTendsToTheIncompressibleOneAsOneOverCSquared) {
  const PressureSystem sys = chain();
  LumpedPressureSystem lumped;
  lumpPressureGroups(sys, kGroups, {0.0}, lumped);
  const Eigen::VectorXd incompressible = solveExactly(lumped.matrix, lumped.rhs);
  double previous_gap = 0.0;
  for (double c : {1e2, 1e3, 1e4}) {
    lumpPressureGroups(sys, kGroups, {2.0 / (c * c)}, lumped);  // shift ~ 1/c^2, as eq. (17)
    const double gap = (solveExactly(lumped.matrix, lumped.rhs) - incompressible).norm();
    EXPECT_GT(gap, 0.0);
    if (previous_gap > 0.0) EXPECT_NEAR(100.0, previous_gap / gap, 1.0) << "c = " << c;
    previous_gap = gap;
  }
}

TEST(BubblePressure, EmptyGroupGetsAZeroPressureRow) {
  const PressureSystem sys = chain();
  LumpedPressureSystem lumped;
  lumpPressureGroups(sys, kGroups, {0.0, 0.0}, lumped);  // group 1 has no particle
  ASSERT_EQ(5, lumped.matrix.rows());
  EXPECT_DOUBLE_EQ(1.0, lumped.matrix.coeff(4, 4));
  EXPECT_DOUBLE_EQ(0.0, lumped.rhs[4]);
  EXPECT_DOUBLE_EQ(0.0, solveExactly(lumped.matrix, lumped.rhs)[4]);
}

// The interface curvature of a bubble (src/mps/interface_curvature.hpp) against the exact one: a lattice disc of gas
// of radius R in liquid (kappa = 1/R), a lattice ball in 3D (kappa = 2/R), a straight interface (kappa = 0) and two
// bubbles side by side (each its own). The mean over the interface and the spread of single particles are checked.
#include <gtest/gtest.h>

#include <cmath>

#include "mps/interface_curvature.hpp"
#include "mps/particles.hpp"
#include "support/lattice.hpp"

using namespace mistfall;

namespace {

struct CurvatureRecord {
  double mean = 0.0;   // mean kappa over the interface [1/m]
  double spread = 0.0; // rms of kappa - mean
  std::size_t interface_count = 0, unfitted = 0;
};

// Gas inside `inside(x)` (bubble id >= 0), liquid elsewhere, on a lattice of spacing l0 over [-half, half]^D.
template <int D, class Inside>
CurvatureRecord measure(double l0, double half, Inside&& inside) {
  Particles<D> p;
  std::vector<std::int32_t> bubble;
  const int k = static_cast<int>(std::round(half / l0));
  Eigen::Matrix<int, D, 1> lo, hi;
  lo.setConstant(-k), hi.setConstant(k);
  test_support::forEachLatticePoint<D>(lo, hi, [&](const Eigen::Matrix<int, D, 1>& idx) {
    const Vec<D> x = idx.template cast<double>() * l0;
    const int b = inside(x);
    p.add(x, Vec<D>::Zero(), ParticleKind::Fluid, b >= 0 ? Phase::Gas : Phase::Liquid);
    bubble.push_back(b);
  });
  const double colour = 2.1 * l0, fit = 5.0 * l0;
  NeighbourSearch<D> search(Vec<D>::Constant(-half - l0), Vec<D>::Constant(half + l0), colour);
  NeighbourList nl;
  search.build(p.position, p.kind, nl);
  const auto c = interfaceCurvature<D>(
      p.position, nl, l0, colour, fit, [&](std::int32_t j) { return bubble[j]; },
      [&](std::int32_t j) { return p.phase[j] == Phase::Liquid; });
  CurvatureRecord out;
  out.interface_count = c.interface_count, out.unfitted = c.unfitted;
  double sum = 0.0, sum2 = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (c.on_interface[i]) sum += c.kappa[i], sum2 += c.kappa[i] * c.kappa[i];
  const double count = static_cast<double>(c.interface_count);
  out.mean = sum / count;
  out.spread = std::sqrt(std::max(0.0, sum2 / count - out.mean * out.mean));
  return out;
}

struct DiscCase {
  double radius_in_spacings;
  double mean_tolerance;    // |mean kappa R - 1| (measured: 0.098, 0.038, 0.018 at 5, 9, 20 l0)
  double spread_tolerance;  // rms(kappa) R (measured: 0.001, 0.14, 0.26)
};

}  // namespace

class InterfaceCurvatureDisc : public ::testing::TestWithParam<DiscCase> {};

TEST_P(InterfaceCurvatureDisc, MeanCurvatureIsOneOverTheRadius) {
  const DiscCase c = GetParam();
  const double l0 = 0.01, radius = c.radius_in_spacings * l0;
  const auto r = measure<2>(l0, radius + 6 * l0, [&](const Vec<2>& x) { return x.norm() < radius ? 0 : -1; });
  EXPECT_EQ(0u, r.unfitted);
  EXPECT_NEAR(1.0, r.mean * radius, c.mean_tolerance) << "R = " << c.radius_in_spacings << " l0";
  EXPECT_LT(r.spread * radius, c.spread_tolerance) << "R = " << c.radius_in_spacings << " l0";
}

INSTANTIATE_TEST_SUITE_P(Radii, InterfaceCurvatureDisc,
                         ::testing::Values(DiscCase{5.0, 0.12, 0.05}, DiscCase{9.0, 0.06, 0.20},
                                           DiscCase{20.0, 0.04, 0.35}));

TEST(InterfaceCurvature, StraightInterfaceHasNone) {
  const double l0 = 0.01;
  const auto r = measure<2>(l0, 10 * l0, [](const Vec<2>& x) { return x[1] < 0.0 ? 0 : -1; });
  EXPECT_GT(r.interface_count, 15u);
  // the lattice's edges (where the interface meets the domain's end) are the only departures
  EXPECT_LT(std::abs(r.mean) * l0, 0.02);
}

TEST(InterfaceCurvature, BallHasTwiceOneOverTheRadius) {
  const double l0 = 0.01, radius = 6 * l0;
  const auto r = measure<3>(l0, radius + 4 * l0, [&](const Vec<3>& x) { return x.norm() < radius ? 0 : -1; });
  EXPECT_EQ(0u, r.unfitted);
  EXPECT_NEAR(2.0, r.mean * radius, 0.2);
}

TEST(InterfaceCurvature, TwoBubblesKeepTheirOwnInterfaces) {
  // two discs of radius 5 l0 three spacings apart: each point is fitted on its own bubble's interface only
  const double l0 = 0.01, radius = 5 * l0, offset = radius + 1.5 * l0;
  const auto r = measure<2>(l0, 2 * radius + 6 * l0, [&](const Vec<2>& x) {
    if ((x - Vec<2>(-offset, 0.0)).norm() < radius) return 0;
    if ((x - Vec<2>(offset, 0.0)).norm() < radius) return 1;
    return -1;
  });
  EXPECT_NEAR(1.0, r.mean * radius, 0.10);
}

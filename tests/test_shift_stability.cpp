// The stability bound of the explicit particle shift (numerics.shift_stability, src/mps/shift_stability.hpp):
//  * a particle between two neighbours on a line, displaced from the middle and shifted step after step: past the
//    bound (K S = 3) the explicit shift overshoots and the displacement grows, alternating, as traced on the 5 mm
//    waterfall; with beta = 1 it is gone within a few steps, with beta = 0.5 it decays without changing side; for
//    both concentration gradients ("mps" and "wendland");
//  * on a full 2D lattice at re = 2.1 l0 the stiffness is the sum of (2 re - r) / r^3 over the neighbours
//    (17.8 / l0^2), and the factor is beta / (K S) above the bound and 1 below it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mps/particle_shifting.hpp"
#include "mps/shift_stability.hpp"
#include "support/shaped_lattice.hpp"

using namespace mistfall;
using namespace mistfall::test_support;

namespace {

auto all = [](std::int32_t) { return true; };
constexpr double kCoefficient = 3.0, kDt = 1e-3;

// K per unit speed of the shift with the given kernel (particle_shifting.hpp: A l0 dt D0/n0, or A h dt with l0^D
// inside the Wendland sum).
double coefficientPerSpeed(const MpsConstants& c, NumericsConfig::ShiftingKernel kernel) {
  return kernel == NumericsConfig::ShiftingKernel::Wendland ? kCoefficient * 0.5 * c.re_number_density * kDt
                                                            : kCoefficient * c.l0 * kDt * 2.0 / c.n0;
}

// Particle 0 between neighbours at -d and +d on the x axis, starting `offset` right of the middle, shifted `steps`
// times (the neighbours held) at a speed that puts K S at `ks` in the middle; its offsets after each step.
std::vector<double> shiftBetweenTwoNeighbours(double d, double offset, double ks, double beta, int steps,
                                              NumericsConfig::ShiftingKernel kernel) {
  const MpsConstants c = referenceConstants(2, kL0, 2.1, 3.1);
  std::vector<Vec<2>> x{Vec<2>(offset * kL0, 0.0), Vec<2>(-d * kL0, 0.0), Vec<2>(d * kL0, 0.0)};
  const std::vector<Vec<2>> middle{Vec<2>::Zero(), x[1], x[2]};
  const double stiffness = shiftStiffness<2>(0, middle, neighboursOf<2>(middle, c.re_laplacian), c, all, kernel);
  const double speed = ks / (coefficientPerSpeed(c, kernel) * stiffness);
  const Vec<2> u(0.0, speed);
  std::vector<double> offsets;
  for (int s = 0; s < steps; ++s) {
    const auto nl = neighboursOf<2>(x, c.re_laplacian);
    Vec<2> shift = shiftingDisplacement<2>(0, x, nl, c, kCoefficient, u, kDt, Vec<2>::Zero(), all, kernel);
    shift *= shiftStabilityFactor<2>(0, x, nl, c, kCoefficient, speed, kDt, beta, all, kernel);
    x[0] += shift;
    offsets.push_back(x[0].x() / kL0);
  }
  return offsets;
}

struct KernelCase {
  NumericsConfig::ShiftingKernel kernel;
  double d;  // the neighbours' distance [l0], where the pair term's Jacobian is large
  const char* name;
};
const KernelCase kKernels[] = {{NumericsConfig::ShiftingKernel::Mps, 0.8, "mps"},
                               {NumericsConfig::ShiftingKernel::Wendland, 1.3, "wendland"}};

class ShiftStability : public ::testing::TestWithParam<KernelCase> {};
INSTANTIATE_TEST_SUITE_P(Kernels, ShiftStability, ::testing::ValuesIn(kKernels),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace

TEST_P(ShiftStability, PastTheBoundTheShiftOvershootsAndGrowsWithItItSettles) {
  const auto [kernel, d, name] = GetParam();
  const double start = 0.01;
  const auto free = shiftBetweenTwoNeighbours(d, start, 3.0, 0.0, 4, kernel);
  for (std::size_t s = 0; s < free.size(); ++s) EXPECT_LT(free[s] * (s % 2 == 0 ? 1.0 : -1.0), 0.0) << s;
  EXPECT_GT(std::abs(free[3]), 8.0 * start);
  const auto limit = shiftBetweenTwoNeighbours(d, start, 3.0, 1.0, 4, kernel);
  EXPECT_LT(std::abs(limit[3]), 1e-3 * start);
  const auto half = shiftBetweenTwoNeighbours(d, start, 3.0, 0.5, 6, kernel);
  double last = start;
  for (const double o : half) {
    EXPECT_GT(o, 0.0);
    EXPECT_LT(o, 0.6 * last);
    last = o;
  }
}

TEST(ShiftStability, OnAFullLatticeTheFactorIsBetaOverKS) {
  const auto x = lattice<2>(Shape::Full);
  const MpsConstants c = referenceConstants(2, kL0, 2.1, 3.1);
  const auto nl = neighboursOf<2>(x, c.re_laplacian);
  double s = 0.0;
  for (std::size_t j = 1; j < x.size(); ++j) {
    const double r = x[j].norm();
    if (r < c.re_number_density) s += (2.0 * c.re_number_density - r) / (r * r * r);
  }
  const auto mps = NumericsConfig::ShiftingKernel::Mps;
  EXPECT_NEAR(s * kL0 * kL0, 17.8, 0.05);
  EXPECT_NEAR(shiftStiffness<2>(0, x, nl, c, all, mps), s, 1e-9 * s);
  const double k_per_speed = coefficientPerSpeed(c, mps);
  for (const double speed : {0.1, 1.0, 10.0, 100.0}) {
    const double ks = k_per_speed * speed * s;
    EXPECT_NEAR(shiftStabilityFactor<2>(0, x, nl, c, kCoefficient, speed, kDt, 1.0, all, mps),
                ks > 1.0 ? 1.0 / ks : 1.0, 1e-12);
  }
  EXPECT_EQ(1.0, shiftStabilityFactor<2>(0, x, nl, c, kCoefficient, 100.0, kDt, 0.0, all, mps));
}

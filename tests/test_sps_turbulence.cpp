// SPS turbulence energy, eqs. (25)-(26): k = (Cv/Ce) Ds^2 P with P = 2 S:S from the MPS velocity gradient,
// checked against linear velocity fields (for which the MPS gradient is exact) on interior lattice particles.
#include <gtest/gtest.h>

#include <random>

#include "mps/gradient.hpp"
#include "mps/neighbour_search.hpp"
#include "mps/sps_turbulence.hpp"

using namespace mistfall;

namespace {

constexpr double kL0 = 0.005;

// A lattice of n^D particles of spacing l0 starting at `corner`, with its neighbour list and constants.
template <int D>
struct Lattice {
  Particles<D> p;
  NeighbourList nl;
  MpsConstants c = referenceConstants(D, kL0, 2.1, 3.1);
  int n;
  explicit Lattice(int n_per_axis) : n(n_per_axis) {
    const Vec<D> corner = Vec<D>::Constant(0.123);  // off the origin: nothing may depend on it
    Eigen::Matrix<int, D, 1> k = Eigen::Matrix<int, D, 1>::Zero();
    while (true) {
      p.add(corner + kL0 * k.template cast<double>(), Vec<D>::Zero(), ParticleKind::Fluid, Phase::Liquid);
      int a = 0;
      for (; a < D; ++a) {
        if (++k[a] < n) break;
        k[a] = 0;
      }
      if (a == D) break;
    }
    rebuild();
  }
  void rebuild() {
    const Vec<D> corner = Vec<D>::Constant(0.123);
    NeighbourSearch<D> search(corner, corner.array() + kL0 * n, c.re_number_density);
    search.build(p.position, p.kind, nl);
  }
  // Lattice index of particle i along axis a.
  int index(std::size_t i, int a) const { return static_cast<int>(std::lround((p.position[i][a] - 0.123) / kL0)); }
  // Full influence circle (re = 2.1 l0) inside the lattice.
  bool interior(std::size_t i) const {
    for (int a = 0; a < D; ++a)
      if (index(i, a) < 3 || index(i, a) > n - 4) return false;
    return true;
  }
  // u = A x + b for every particle.
  void setLinearVelocity(const Tensor<D>& A, const Vec<D>& b) {
    for (std::size_t i = 0; i < p.size(); ++i) p.velocity[i] = A * p.position[i] + b;
  }
};

SpsParameters params() {
  SpsParameters s;
  s.ds = kL0;
  return s;
}

// k on every interior particle equals (Cv/Ce) Ds^2 P_expected to 1e-10 relative; returns how many were checked.
template <int D>
int expectInteriorEnergy(const Lattice<D>& L, double production, double abs_tol = 0.0) {
  std::vector<double> k;
  spsTurbulenceEnergy<D>(L.p, L.nl, L.c, params(), k, samePhaseActive(L.p));
  const double expected = 0.08 / 1.0 * kL0 * kL0 * production;
  int checked = 0;
  for (std::size_t i = 0; i < L.p.size(); ++i) {
    if (!L.interior(i)) continue;
    EXPECT_NEAR(k[i], expected, std::max(1e-10 * std::abs(expected), abs_tol)) << "particle " << i;
    ++checked;
  }
  return checked;
}

}  // namespace

TEST(SpsTurbulence, LinearShearGivesProductionGSquared) {
  Lattice<2> L(15);
  const double g = 3.7;
  Tensor<2> A = Tensor<2>::Zero();
  A(0, 1) = g;  // u = (g y, 0)
  L.setLinearVelocity(A, Vec<2>(0.4, -0.2));
  EXPECT_EQ(expectInteriorEnergy<2>(L, g * g), 9 * 9);
  // Equivalently through the production itself.
  const std::size_t centre = 7 * 15 + 7;
  auto all = [](std::int32_t) { return true; };
  const Tensor<2> grad = velocityGradientAt<2>(centre, L.p.position, L.p.velocity, L.nl, L.c, all);
  EXPECT_NEAR(strainProduction<2>(grad), g * g, 1e-10 * g * g);
  EXPECT_NEAR(turbulenceIntensity(1.5), 1.0, 1e-15);
}

TEST(SpsTurbulence, SolidRotationProducesNothing) {
  Lattice<2> L(15);
  const double w = 2.5;
  Tensor<2> A;
  A << 0.0, -w, w, 0.0;  // u = (-w y, w x)
  L.setLinearVelocity(A, Vec<2>::Zero());
  // P = 0 exactly in exact arithmetic; the gradient entries are O(w), so allow rounding of their squares.
  EXPECT_EQ(expectInteriorEnergy<2>(L, 0.0, 1e-20 * w * w), 81);
}

TEST(SpsTurbulence, PureStrainGivesFourASquared) {
  Lattice<2> L(15);
  const double a = 1.3;
  Tensor<2> A;
  A << a, 0.0, 0.0, -a;  // u = (a x, -a y)
  L.setLinearVelocity(A, Vec<2>::Zero());
  EXPECT_EQ(expectInteriorEnergy<2>(L, 4.0 * a * a), 81);
}

TEST(SpsTurbulence, GeneralLinearFieldIn3D) {
  Lattice<3> L(9);
  Tensor<3> A;
  A << 0.3, -1.2, 0.7, 2.0, -0.5, 0.1, -0.4, 0.9, 0.2;
  L.setLinearVelocity(A, Vec<3>(1.0, 2.0, 3.0));
  const Tensor<3> S = 0.5 * (A + A.transpose());
  EXPECT_EQ(expectInteriorEnergy<3>(L, 2.0 * S.squaredNorm()), 3 * 3 * 3);
}

TEST(SpsTurbulence, TensorLoopMatchesThePlainGradientPerComponent) {
  Lattice<2> L(9);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.2 * kL0, 0.2 * kL0), speed(-1.0, 1.0);
  for (std::size_t i = 0; i < L.p.size(); ++i) {
    L.p.position[i] += Vec<2>(jitter(rng), jitter(rng));
    L.p.velocity[i] = Vec<2>(speed(rng), speed(rng));
  }
  L.rebuild();
  auto all = [](std::int32_t) { return true; };
  const std::size_t i = 4 * 9 + 4;
  const Tensor<2> grad = velocityGradientAt<2>(i, L.p.position, L.p.velocity, L.nl, L.c, all);
  for (int a = 0; a < 2; ++a) {
    std::vector<double> component(L.p.size());
    for (std::size_t j = 0; j < L.p.size(); ++j) component[j] = L.p.velocity[j][a];
    const Vec<2> g = gradientAt<2>(i, L.p.position, component, L.nl, L.c, GradientForm::Plain, all);
    EXPECT_NEAR((grad.row(a).transpose() - g).norm(), 0.0, 1e-12 * g.norm());
  }
}

TEST(SpsTurbulence, PredicateExcludesOtherPhaseNeighbours) {
  Lattice<2> L(15);
  const double g = 2.0;
  Tensor<2> A = Tensor<2>::Zero();
  A(0, 1) = g;
  L.setLinearVelocity(A, Vec<2>::Zero());
  // Right half (x index >= 8) becomes gas with a velocity unrelated to the liquid's shear.
  for (std::size_t i = 0; i < L.p.size(); ++i)
    if (L.index(i, 0) >= 8) {
      L.p.phase[i] = Phase::Gas;
      L.p.velocity[i] = Vec<2>(50.0, -30.0);
    }
  std::vector<double> k1, k2;
  spsTurbulenceEnergy<2>(L.p, L.nl, L.c, params(), k1, samePhaseActive(L.p));
  for (std::size_t i = 0; i < L.p.size(); ++i)
    if (L.p.phase[i] == Phase::Gas) L.p.velocity[i] = Vec<2>(-7.0, 11.0);
  spsTurbulenceEnergy<2>(L.p, L.nl, L.c, params(), k2, samePhaseActive(L.p));
  std::vector<double> k_all;
  spsTurbulenceEnergy<2>(L.p, L.nl, L.c, params(), k_all, [](std::size_t, std::int32_t) { return true; });
  const std::size_t next_to_gas = 7 * 15 + 7;  // x index 7, y index 7: gas neighbours at x index 8, 9
  ASSERT_EQ(L.p.phase[next_to_gas], Phase::Liquid);
  EXPECT_EQ(k1[next_to_gas], k2[next_to_gas]);         // the gas velocity does not enter
  EXPECT_GT(k_all[next_to_gas], 100.0 * k1[next_to_gas]);  // it would, without the predicate
  // Far enough from the gas, the liquid still sees the exact shear.
  const std::size_t deep = 7 * 15 + 4;
  EXPECT_NEAR(k1[deep], 0.08 * kL0 * kL0 * g * g, 1e-10 * 0.08 * kL0 * kL0 * g * g);
  // And the per-particle form agrees with the whole-array one.
  EXPECT_EQ(spsTurbulenceEnergyAt<2>(next_to_gas, L.p, L.nl, L.c, params(),
                                     [&](std::int32_t j) { return L.p.phase[j] == Phase::Liquid; }),
            k2[next_to_gas]);
}

TEST(SpsTurbulence, EscapedParticlesGetZeroAndBadParametersThrow) {
  Lattice<2> L(7);
  Tensor<2> A = Tensor<2>::Identity();
  L.setLinearVelocity(A, Vec<2>::Zero());
  L.p.kind[3] = ParticleKind::Escaped;
  L.rebuild();
  std::vector<double> k;
  spsTurbulenceEnergy<2>(L.p, L.nl, L.c, params(), k, samePhaseActive(L.p));
  ASSERT_EQ(k.size(), L.p.size());
  EXPECT_EQ(k[3], 0.0);
  SpsParameters bad;  // Ds left at 0
  EXPECT_THROW(spsTurbulenceEnergy<2>(L.p, L.nl, L.c, bad, k, samePhaseActive(L.p)), std::invalid_argument);
  bad.ds = kL0;
  bad.ce = 0.0;
  EXPECT_THROW(checkSpsParameters(bad), std::invalid_argument);
  NeighbourList empty;
  EXPECT_THROW(spsTurbulenceEnergy<2>(L.p, empty, L.c, params(), k, samePhaseActive(L.p)), std::invalid_argument);
}

// The operators of numerics.scheme = "stabilised" against analytic fields, in 2D and 3D, on lattices that are full,
// cut by a free surface, or jittered (docs/validation.md):
//  * the corrected gradient is exact for linear fields on every such neighbourhood, and falls back to the standard
//    (repulsive) form on a one-dimensional one;
//  * the consistency term makes the Laplacian of a linear field zero wherever the neighbourhood is cut;
//  * the mirrored walls' term is what a hydrostatic field continued into the wall gives, and vanishes for water at
//    rest whose only velocity is this step's gravity.
#include <gtest/gtest.h>

#include <random>

#include "mps/corrected_gradient.hpp"
#include "mps/laplacian.hpp"
#include "mps/laplacian_consistency.hpp"
#include "mps/neighbour_search.hpp"
#include "mps/surface_pressure.hpp"
#include "mps/wall_mirror.hpp"

using namespace mistfall;

namespace {

constexpr double kL0 = 0.01;

// Which lattice points around the centre (index 0) exist.
enum class Shape { Full, CutAbove, Jittered, Line };

struct Neighbourhood {
  Shape shape;
  const char* name;
};

// A lattice of spacing l0 in [-4, 4]^D around the origin (the centre, index 0), shaped: CutAbove drops the points
// above the centre's row (the centre is on the free surface), Jittered moves every point but the centre by up to
// 0.2 l0, Line keeps the points on the first axis only. The last axis is vertical.
template <int D>
Particles<D> shapedLattice(Shape shape) {
  Particles<D> p;
  p.add(Vec<D>::Zero(), Vec<D>::Zero(), ParticleKind::Fluid, Phase::Liquid);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.2 * kL0, 0.2 * kL0);
  Eigen::Matrix<int, D, 1> k = Eigen::Matrix<int, D, 1>::Constant(-4);
  while (true) {
    const bool centre = (k.array() == 0).all();
    bool keep = !centre;
    if (shape == Shape::CutAbove) keep = keep && k[D - 1] <= 0;
    if (shape == Shape::Line) keep = keep && (k.tail(D - 1).array() == 0).all();
    if (keep) {
      Vec<D> x = kL0 * k.template cast<double>();
      if (shape == Shape::Jittered)
        for (int a = 0; a < D; ++a) x[a] += jitter(random);
      p.add(x, Vec<D>::Zero(), ParticleKind::Fluid, Phase::Liquid);
    }
    int a = 0;
    for (; a < D; ++a) {
      if (++k[a] <= 4) break;
      k[a] = -4;
    }
    if (a == D) break;
  }
  return p;
}

template <int D>
NeighbourList neighboursOf(const Particles<D>& p, double radius) {
  NeighbourSearch<D> search(Vec<D>::Constant(-0.06), Vec<D>::Constant(0.06), radius);
  NeighbourList nl;
  search.build(p.position, p.kind, nl);
  return nl;
}

auto all = [](std::int32_t) { return true; };

template <int D>
void checkCorrectedGradient(Shape shape) {
  const auto p = shapedLattice<D>(shape);
  const MpsConstants c = referenceConstants(D, kL0, 2.1, 3.1);
  const auto nl = neighboursOf<D>(p, c.re_laplacian);
  const Vec<D> slope = Vec<D>::LinSpaced(-3.0, 5.0);
  auto difference = [&](std::int32_t j, const Vec<D>& rij) { return slope.dot(rij); };
  const auto g = correctedGradientAt<D>(0, p.position, nl, c, 0.3, all, difference);
  if (shape == Shape::Line) {
    EXPECT_TRUE(g.fell_back);  // a line does not span the space
    // the standard form: only the component along the line, p_hat = min over the line
    EXPECT_NEAR(g.value.tail(D - 1).norm(), 0.0, 1e-12);
    return;
  }
  EXPECT_FALSE(g.fell_back);
  EXPECT_LT((g.value - slope).norm(), 1e-10 * slope.norm());
}

template <int D>
void checkConsistentLaplacian(Shape shape) {
  const auto p = shapedLattice<D>(shape);
  const MpsConstants c = referenceConstants(D, kL0, 2.1, 3.1);
  const auto nl = neighboursOf<D>(p, c.re_laplacian);
  const Vec<D> slope = Vec<D>::LinSpaced(2.0, -7.0);
  std::vector<double> phi(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) phi[i] = 40.0 + slope.dot(p.position[i]);
  // eq. (13) sees the cut: the Laplacian of a linear field is not zero there; the consistency term removes it
  const double raw = laplacianAt<D>(0, p.position, phi, nl, c, all);
  const double term = laplacianConsistencyTerm<D>(0, p.position, nl, c, slope, all);
  // the term goes to the right-hand side of the negated system: -lap phi = ... + term, i.e. lap phi + term = 0
  const double scale = c.laplacianFactor() * slope.norm() * kL0 * c.n0_laplacian;
  if (shape == Shape::CutAbove) EXPECT_GT(std::abs(raw), 0.1 * scale);
  EXPECT_NEAR(raw + term, 0.0, 1e-10 * scale);
}

}  // namespace

class StabilisedGradient : public ::testing::TestWithParam<Neighbourhood> {};
class StabilisedLaplacian : public ::testing::TestWithParam<Neighbourhood> {};

const Neighbourhood kShapes[] = {
    {Shape::Full, "full"}, {Shape::CutAbove, "cut_above"}, {Shape::Jittered, "jittered"}, {Shape::Line, "line"}};
auto shapeName = [](const auto& info) { return std::string(info.param.name); };
INSTANTIATE_TEST_SUITE_P(Shapes, StabilisedGradient, ::testing::ValuesIn(kShapes), shapeName);
// a line of particles is never a row of the pressure equation (it is a free surface)
INSTANTIATE_TEST_SUITE_P(Shapes, StabilisedLaplacian, ::testing::ValuesIn(kShapes, kShapes + 3), shapeName);

TEST_P(StabilisedGradient, IsExactForLinearFields2D) { checkCorrectedGradient<2>(GetParam().shape); }
TEST_P(StabilisedGradient, IsExactForLinearFields3D) { checkCorrectedGradient<3>(GetParam().shape); }
TEST_P(StabilisedLaplacian, OfALinearFieldIsZero2D) { checkConsistentLaplacian<2>(GetParam().shape); }
TEST_P(StabilisedLaplacian, OfALinearFieldIsZero3D) { checkConsistentLaplacian<3>(GetParam().shape); }

// A fluid particle one spacing above a floor of wall and dummy particles: the walls' known term is the Laplacian's
// part of the hydrostatic field continued into them, and the wall-velocity part vanishes for water at rest.
TEST(StabilisedWalls, MirroredWallTermIsTheHydrostaticContinuation) {
  Particles<2> p = shapedLattice<2>(Shape::Full);
  for (std::size_t i = 1; i < p.size(); ++i)
    if (p.position[i][1] < -0.5 * kL0) p.kind[i] = p.position[i][1] < -1.5 * kL0 ? ParticleKind::Dummy : ParticleKind::Wall;
  const MpsConstants c = referenceConstants(2, kL0, 2.1, 3.1);
  const auto nl = neighboursOf<2>(p, c.re_laplacian);
  const Vec<2> g(0.0, -9.81);
  const double rho = 1000.0, dt = 1e-3;
  for (auto& u : p.velocity) u = g * dt;  // at rest before this step's gravity
  const double term = mirroredWallTerm<2>(0, p.position, p.velocity, p.kind, nl, c, rho, g, dt);
  // the hydrostatic field p = -rho g . x on the wall particles, through eq. (13)
  std::vector<double> hydro(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) hydro[i] = -rho * g.dot(p.position[i]);
  auto wall = [&](std::int32_t j) { return isMirroredWall(p.kind[j]); };
  const double expected = -laplacianAt<2>(0, p.position, hydro, nl, c, wall);
  EXPECT_GT(term, 0.0);  // the floor pushes up
  EXPECT_NEAR(term, expected, 1e-9 * std::abs(expected));
  // water moving into the floor is stopped: a larger term
  for (auto& u : p.velocity) u = g * dt + Vec<2>(0.0, -0.1);
  EXPECT_GT(mirroredWallTerm<2>(0, p.position, p.velocity, p.kind, nl, c, rho, g, dt), term * 1.5);
}

TEST(StabilisedSurface, SurfacePressureIsHalfASpacingOfTheGradient) {
  EXPECT_DOUBLE_EQ(surfaceParticlePressure<2>(Vec<2>(0.0, -9810.0), 0.008), 0.5 * 0.008 * 9810.0);
  EXPECT_DOUBLE_EQ(surfaceParticlePressure<3>(Vec<3>::Zero(), 0.008), 0.0);  // free fall, lone droplet
}

// Six-category classification (src/classify, section 3.1) on constructed lattice arrangements in 2D and 3D:
// lone particles and small clumps are droplets / bubbles, block interiors are bulk, the outermost row is surface,
// liquid and gas are classified separately, walls count for the surface test but not for isolation, non-fluid
// particles get None, and the result does not depend on the thread count.
#include <gtest/gtest.h>
#include <omp.h>

#include <array>
#include <random>

#include "classify/classification.hpp"
#include "mps/number_density.hpp"
#include "support/lattice.hpp"

using namespace mistfall;

namespace {

constexpr double kL0 = 0.01;

MpsConstants constantsFor(int dimension) { return referenceConstants(dimension, kL0, 2.1, 3.1); }

// Lattice index of a particle (rounded position / l0).
template <int D>
using Index = std::array<int, D>;

template <int D>
Vec<D> at(const Index<D>& k, double spacing = kL0) {
  Vec<D> x;
  for (int a = 0; a < D; ++a) x[a] = spacing * k[a];
  return x;
}

// Adds a particle on every lattice point of the box [lo, hi] (inclusive) for which keep(k) holds; returns the
// index of the first one.
template <int D, class Keep>
std::size_t addBoxWhere(Particles<D>& p, const Index<D>& lo, const Index<D>& hi, ParticleKind kind, Phase phase,
                   Keep&& keep, double spacing = kL0) {
  const std::size_t first = p.size();
  test_support::forEachLatticePoint<D>(lo, hi, [&](const Index<D>& k) {
    if (keep(k)) p.add(at<D>(k, spacing), Vec<D>::Zero(), kind, phase);
  });
  return first;
}

template <int D>
std::size_t addBox(Particles<D>& p, const Index<D>& lo, const Index<D>& hi, ParticleKind kind, Phase phase,
                   double spacing = kL0) {
  return addBoxWhere<D>(p, lo, hi, kind, phase, [](const Index<D>&) { return true; }, spacing);
}

template <int D>
Index<D> filled(int v) {
  Index<D> k;
  k.fill(v);
  return k;
}

// Lattice index of particle i.
template <int D>
Index<D> indexOf(const Particles<D>& p, std::size_t i, double spacing = kL0) {
  Index<D> k;
  for (int a = 0; a < D; ++a) k[a] = static_cast<int>(std::lround(p.position[i][a] / spacing));
  return k;
}

// Distance in lattice rows from k to the nearest face of the box [lo, hi].
template <int D>
int rowsFromFace(const Index<D>& k, const Index<D>& lo, const Index<D>& hi) {
  int d = 1 << 20;
  for (int a = 0; a < D; ++a) d = std::min({d, k[a] - lo[a], hi[a] - k[a]});
  return d;
}

template <int D>
std::vector<Category> classify(const Particles<D>& p, const ClassificationParameters& params = {}) {
  return classifyParticles<D>(p, constantsFor(D), params);
}

template <class T>
class Classification : public ::testing::Test {};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(Classification, Dimensions);

// A block of one phase, 8 particles a side: the outermost row is surface, everything further in is bulk.
template <int D>
void expectBlockRows(Phase phase, Category surface, Category bulk, const ClassificationParameters& params = {},
                     int surface_rows = 1) {
  Particles<D> p;
  const Index<D> lo = filled<D>(0), hi = filled<D>(7);
  addBox<D>(p, lo, hi, ParticleKind::Fluid, phase);
  const auto cat = classify<D>(p, params);
  int n_surface = 0, n_bulk = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const int row = rowsFromFace<D>(indexOf<D>(p, i), lo, hi);
    const Category want = row < surface_rows ? surface : bulk;
    EXPECT_EQ(want, cat[i]) << "particle " << i << " in row " << row;
    n_surface += cat[i] == surface;
    n_bulk += cat[i] == bulk;
  }
  const int inner = 8 - 2 * surface_rows;
  EXPECT_EQ(static_cast<int>(std::pow(inner, D)), n_bulk);
  EXPECT_EQ(static_cast<int>(std::pow(8, D)) - n_bulk, n_surface);
}

}  // namespace

TYPED_TEST(Classification, LoneLiquidParticleIsADroplet) {
  constexpr int D = TypeParam::value;
  Particles<D> p;
  p.add(Vec<D>::Zero(), Vec<D>::Zero(), ParticleKind::Fluid, Phase::Liquid);
  EXPECT_EQ(Category::Droplet, classify<D>(p)[0]);
}

TYPED_TEST(Classification, LoneGasParticleIsABubble) {
  constexpr int D = TypeParam::value;
  Particles<D> p;
  p.add(Vec<D>::Zero(), Vec<D>::Zero(), ParticleKind::Fluid, Phase::Gas);
  EXPECT_EQ(Category::Bubble, classify<D>(p)[0]);
}

// A single gas particle at the centre of a liquid block: a bubble; the liquid touching it is surface (the
// bubble's wall), the rest of the block's interior stays bulk.
TYPED_TEST(Classification, GasParticleInsideLiquidIsABubble) {
  constexpr int D = TypeParam::value;
  Particles<D> p;
  const Index<D> lo = filled<D>(-4), hi = filled<D>(4), centre = filled<D>(0);
  addBoxWhere<D>(p, lo, hi, ParticleKind::Fluid, Phase::Liquid, [&](const Index<D>& k) { return k != centre; });
  const std::size_t gas = p.size();
  p.add(Vec<D>::Zero(), Vec<D>::Zero(), ParticleKind::Fluid, Phase::Gas);
  const auto cat = classify<D>(p);
  EXPECT_EQ(Category::Bubble, cat[gas]);
  for (std::size_t i = 0; i < gas; ++i) {
    const Index<D> k = indexOf<D>(p, i);
    if (rowsFromFace<D>(k, lo, hi) == 0) continue;
    const double distance = at<D>(k).norm();
    const Category want = distance < 1.5 * kL0 ? Category::LiquidSurface : Category::LiquidBulk;
    EXPECT_EQ(want, cat[i]) << "liquid particle " << i << " at " << distance / kL0 << " l0 from the bubble";
  }
}

// An entrained bubble moved as a point (numerics.entrained_bubble_diameter) inside a full liquid block, which keeps
// a water particle where it was made: a bubble, and the water around it all bulk (the point is no MPS particle).
TYPED_TEST(Classification, EntrainedPointIsABubbleInBulkWater) {
  constexpr int D = TypeParam::value;
  Particles<D> p;
  const Index<D> lo = filled<D>(-4), hi = filled<D>(4);
  addBox<D>(p, lo, hi, ParticleKind::Fluid, Phase::Liquid);
  const std::size_t point = p.size();
  p.add(Vec<D>::Constant(0.3 * kL0), Vec<D>::Zero(), ParticleKind::Point, Phase::Gas);
  const auto cat = classify<D>(p);
  EXPECT_EQ(Category::Bubble, cat[point]);
  for (std::size_t i = 0; i < point; ++i)
    if (rowsFromFace<D>(indexOf<D>(p, i), lo, hi) > 0) EXPECT_EQ(Category::LiquidBulk, cat[i]) << "particle " << i;
}

// Clumps of 2, 3 and 4 (2D) / 8 (3D) particles are droplets; a block's corner particle is not.
TYPED_TEST(Classification, SmallClumpsAreDroplets) {
  constexpr int D = TypeParam::value;
  auto expectAll = [](const Particles<D>& p, Category want, const char* what) {
    const auto cat = classify<D>(p);
    for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(want, cat[i]) << what << ", particle " << i;
  };
  Index<D> one = filled<D>(0), two = filled<D>(0);
  one[0] = 1;
  two[0] = 2;
  Particles<D> pair, line, corner, cube;
  addBox<D>(pair, filled<D>(0), one, ParticleKind::Fluid, Phase::Liquid);
  addBox<D>(line, filled<D>(0), two, ParticleKind::Fluid, Phase::Liquid);
  addBox<D>(cube, filled<D>(0), filled<D>(1), ParticleKind::Fluid, Phase::Gas);  // 2x2 or 2x2x2 gas
  expectAll(pair, Category::Droplet, "pair");
  expectAll(line, Category::Droplet, "row of three");
  expectAll(cube, Category::Bubble, "2^D clump of gas");
  // An L of three: (0,0), (1,0), (0,1).
  Index<D> up = filled<D>(0);
  up[1] = 1;
  corner.add(Vec<D>::Zero(), Vec<D>::Zero(), ParticleKind::Fluid, Phase::Liquid);
  corner.add(at<D>(one), Vec<D>::Zero(), ParticleKind::Fluid, Phase::Liquid);
  corner.add(at<D>(up), Vec<D>::Zero(), ParticleKind::Fluid, Phase::Liquid);
  expectAll(corner, Category::Droplet, "L of three");
}

TYPED_TEST(Classification, LiquidBlockInteriorIsBulkOutermostRowIsSurface) {
  expectBlockRows<TypeParam::value>(Phase::Liquid, Category::LiquidSurface, Category::LiquidBulk);
}

TYPED_TEST(Classification, GasBlockInteriorIsBulkOutermostRowIsSurface) {
  expectBlockRows<TypeParam::value>(Phase::Gas, Category::GasSurface, Category::GasBulk);
}

// Each criterion of the surface test works alone: without the level test the gradient still finds the outermost
// row; a low gradient threshold widens the surface to two rows; without both tests everything not isolated is bulk.
TYPED_TEST(Classification, SurfaceCriteriaFollowTheirParameters) {
  constexpr int D = TypeParam::value;
  ClassificationParameters gradient_only;
  gradient_only.surface_number_density = 0.0;
  expectBlockRows<D>(Phase::Liquid, Category::LiquidSurface, Category::LiquidBulk, gradient_only, 1);
  ClassificationParameters wide;
  wide.surface_gradient = 0.03;
  expectBlockRows<D>(Phase::Liquid, Category::LiquidSurface, Category::LiquidBulk, wide, 2);
  ClassificationParameters off;
  off.surface_number_density = 0.0;
  off.surface_gradient = 1e9;
  expectBlockRows<D>(Phase::Liquid, Category::LiquidSurface, Category::LiquidBulk, off, 0);
}

// A block squeezed to 0.87 l0 spacing: its outermost row has n >= 0.97 n0 (the level test alone calls it bulk)
// but a steep number-density gradient, so it is still surface.
TYPED_TEST(Classification, CompressedBlockEdgeIsSurfaceByTheGradient) {
  constexpr int D = TypeParam::value;
  const double spacing = 0.87 * kL0;
  Particles<D> p;
  const Index<D> lo = filled<D>(0), hi = filled<D>(7);
  addBox<D>(p, lo, hi, ParticleKind::Fluid, Phase::Liquid, spacing);
  const MpsConstants c = constantsFor(D);
  NeighbourSearch<D> search(Vec<D>::Zero(), Vec<D>::Constant(8 * spacing), c.re_number_density);
  NeighbourList nl;
  search.build(p.position, p.kind, nl);
  const auto cat = classifyParticles<D>(p, nl, c, {});
  int edge_mid = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Index<D> k = indexOf<D>(p, i, spacing);
    const int row = rowsFromFace<D>(k, lo, hi);
    EXPECT_EQ(row == 0 ? Category::LiquidSurface : Category::LiquidBulk, cat[i]) << "row " << row;
    // A face-centre particle of the outermost row (one coordinate 0, the others 3 or 4).
    int on_face = 0;
    for (int a = 0; a < D; ++a) on_face += (k[a] == 0) + 2 * (k[a] == 3 || k[a] == 4);
    if (on_face == 1 + 2 * (D - 1)) {
      EXPECT_GE(numberDensityAt<D>(i, p.position, nl, c.re_number_density), 0.97 * c.n0);
      ++edge_mid;
    }
  }
  EXPECT_GT(edge_mid, 0);
}

// Gas resting on liquid resting on a wall floor: each phase sees the other as empty space. The liquid's top row
// is liquid surface, the gas's bottom row is gas surface; the liquid's bottom row lies on the wall and is bulk.
TYPED_TEST(Classification, GasOnLiquidIsClassifiedPhaseByPhase) {
  constexpr int D = TypeParam::value;
  constexpr int top = D - 1;  // the vertical axis
  Particles<D> p;
  auto layer = [&](int y0, int y1, ParticleKind kind, Phase phase) {
    Index<D> lo = filled<D>(0), hi = filled<D>(9);
    lo[top] = y0;
    hi[top] = y1;
    return addBox<D>(p, lo, hi, kind, phase);
  };
  layer(-3, -2, ParticleKind::Dummy, Phase::Liquid);
  layer(-1, -1, ParticleKind::Wall, Phase::Liquid);
  const std::size_t liquid = layer(0, 4, ParticleKind::Fluid, Phase::Liquid);
  const std::size_t gas = layer(5, 9, ParticleKind::Fluid, Phase::Gas);
  const auto cat = classify<D>(p);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Index<D> k = indexOf<D>(p, i);
    if (i < liquid) {
      EXPECT_EQ(Category::None, cat[i]) << "wall or dummy " << i;
      continue;
    }
    bool side = false;  // on a side face of the column: surface there, not what this test is about
    for (int a = 0; a < top; ++a) side = side || k[a] == 0 || k[a] == 9;
    if (side) continue;
    const int y = k[top];
    if (i < gas) EXPECT_EQ(y == 4 ? Category::LiquidSurface : Category::LiquidBulk, cat[i]) << "liquid at y " << y;
    else EXPECT_EQ(y == 5 || y == 9 ? Category::GasSurface : Category::GasBulk, cat[i]) << "gas at y " << y;
  }
}

// Walls keep water lying on them from being surface, but not a lone particle from being a droplet.
TYPED_TEST(Classification, LoneParticleOnAWallIsStillADroplet) {
  constexpr int D = TypeParam::value;
  Particles<D> p;
  Index<D> lo = filled<D>(-4), hi = filled<D>(4);
  hi[D - 1] = -1;
  addBox<D>(p, lo, hi, ParticleKind::Wall, Phase::Liquid);
  const std::size_t drop = p.size();
  p.add(Vec<D>::Zero(), Vec<D>::Zero(), ParticleKind::Fluid, Phase::Liquid);
  EXPECT_EQ(Category::Droplet, classify<D>(p)[drop]);
}

// Every fluid particle gets exactly one of the six categories, of its own phase; walls, dummies, escaped and
// inflow particles get None.
TYPED_TEST(Classification, EveryFluidParticleGetsOneCategoryOfItsPhase) {
  constexpr int D = TypeParam::value;
  Particles<D> p;
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> jitter(-0.2 * kL0, 0.2 * kL0);
  std::uniform_int_distribution<int> pick(0, 9);
  addBox<D>(p, filled<D>(0), filled<D>(7), ParticleKind::Fluid, Phase::Liquid);
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int a = 0; a < D; ++a) p.position[i][a] += jitter(rng);
    const int r = pick(rng);
    if (r < 3) p.phase[i] = Phase::Gas;
    else if (r == 3) p.kind[i] = ParticleKind::Wall;
    else if (r == 4) p.kind[i] = ParticleKind::Dummy;
    else if (r == 5) p.kind[i] = ParticleKind::Escaped;
    else if (r == 6) p.kind[i] = ParticleKind::Inflow;
  }
  const auto cat = classify<D>(p);
  ASSERT_EQ(p.size(), cat.size());
  const auto counts = countCategories(cat);
  std::size_t fluid = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto v = static_cast<int>(cat[i]);
    if (p.kind[i] != ParticleKind::Fluid) {
      EXPECT_EQ(Category::None, cat[i]) << "non-fluid particle " << i;
      continue;
    }
    ++fluid;
    if (p.phase[i] == Phase::Liquid) EXPECT_TRUE(v >= 1 && v <= 3) << "liquid particle " << i << ": " << v;
    else EXPECT_TRUE(v >= 4 && v <= 6) << "gas particle " << i << ": " << v;
  }
  EXPECT_EQ(p.size() - fluid, counts[0]);
  std::size_t six = 0;
  for (int k = 1; k < kCategoryCount; ++k) six += counts[k];
  EXPECT_EQ(fluid, six);
}

// A jittered block, liquid on the left half and gas on the right, with some particles swapped to the other phase
// (droplets and bubbles): every category occurs, and 1 and 3 threads give the same categories.
TYPED_TEST(Classification, ResultDoesNotDependOnTheThreadCount) {
  constexpr int D = TypeParam::value;
  constexpr int side = D == 2 ? 30 : 12;
  Particles<D> p;
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> jitter(-0.2 * kL0, 0.2 * kL0);
  std::bernoulli_distribution swap(0.03);
  addBox<D>(p, filled<D>(0), filled<D>(side - 1), ParticleKind::Fluid, Phase::Liquid);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool gas = (indexOf<D>(p, i)[0] >= side / 2) != swap(rng);
    p.phase[i] = gas ? Phase::Gas : Phase::Liquid;
    for (int a = 0; a < D; ++a) p.position[i][a] += jitter(rng);
  }
  const int before = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto one = classify<D>(p);
  omp_set_num_threads(3);
  const auto three = classify<D>(p);
  omp_set_num_threads(before);
  EXPECT_EQ(categoryBytes(one), categoryBytes(three));
  const auto counts = countCategories(one);
  for (int k = 1; k < kCategoryCount; ++k) EXPECT_GT(counts[k], 0u) << categoryName(static_cast<Category>(k));
}

TEST(Classification, CategoryNamesAreTheCsvColumns) {
  EXPECT_EQ("none", categoryName(Category::None));
  EXPECT_EQ("liquid_bulk", categoryName(Category::LiquidBulk));
  EXPECT_EQ("liquid_surface", categoryName(Category::LiquidSurface));
  EXPECT_EQ("droplet", categoryName(Category::Droplet));
  EXPECT_EQ("gas_bulk", categoryName(Category::GasBulk));
  EXPECT_EQ("gas_surface", categoryName(Category::GasSurface));
  EXPECT_EQ("bubble", categoryName(Category::Bubble));
}

// The solver's neighbour list reaches the Laplacian radius (3.1 l0); pairs beyond re = 2.1 l0 must not count.
TYPED_TEST(Classification, LongerNeighbourListGivesTheSameCategories) {
  constexpr int D = TypeParam::value;
  Particles<D> p;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.25 * kL0, 0.25 * kL0);
  addBox<D>(p, filled<D>(0), filled<D>(D == 2 ? 15 : 7), ParticleKind::Fluid, Phase::Liquid);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int a = 0; a < D; ++a) p.position[i][a] += jitter(rng);
  const MpsConstants c = constantsFor(D);
  NeighbourSearch<D> search(Vec<D>::Constant(-kL0), Vec<D>::Constant(17 * kL0), c.re_laplacian);
  NeighbourList wide;
  search.build(p.position, p.kind, wide);
  const auto from_wide = classifyParticles<D>(p, wide, c, {});
  EXPECT_EQ(categoryBytes(classify<D>(p)), categoryBytes(from_wide));
  const auto counts = countCategories(from_wide);
  EXPECT_GT(counts[static_cast<int>(Category::LiquidBulk)], 0u);
  EXPECT_GT(counts[static_cast<int>(Category::LiquidSurface)], 0u);
}

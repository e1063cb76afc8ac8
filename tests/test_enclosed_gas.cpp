// Gas regions and enclosed bubbles (delta_gl) on hand-built lattices in 2D and 3D: a bubble in liquid, an open
// gas layer, gas at a wall, two bubbles' ids, a one-particle bubble, escaped particles, a brute-force
// reference on random gas, and thread-count independence.
#include <gtest/gtest.h>

#include <set>
#include <omp.h>

#include <random>

#include "mps/enclosed_gas.hpp"
#include "support/lattice.hpp"

using namespace mistfall;

namespace {

constexpr double kL0 = 0.01;
constexpr double kLink = 2.1 * kL0;    // the number-density radius, as the solver passes it
constexpr double kSearch = 3.1 * kL0;  // the solver's list radius (max of both radii): larger than the link

template <int D>
using Index = Eigen::Matrix<int, D, 1>;

struct Site {
  bool present = true;
  ParticleKind kind = ParticleKind::Fluid;
  Phase phase = Phase::Liquid;
};
const Site kLiquid{};
const Site kGas{true, ParticleKind::Fluid, Phase::Gas};

template <int D>
Vec<D> origin() { return Vec<D>::Constant(0.37); }  // off the origin: nothing may depend on it

template <int D>
Vec<D> at(const Index<D>& k) { return origin<D>() + kL0 * k.template cast<double>(); }

// Lattice points lo <= k <= hi (axis 0 fastest, so lower rows get smaller indices), each as classify(k) says;
// pressures are distinct per particle.
template <int D, class Classify>
Particles<D> makeLattice(const Index<D>& lo, const Index<D>& hi, Classify&& classify) {
  Particles<D> p;
  test_support::forEachLatticePoint<D>(lo, hi, [&](const Index<D>& k) {
    const Site s = classify(k);
    if (s.present) {
      p.add(at<D>(k), Vec<D>::Zero(), s.kind, s.phase);
      p.pressure.back() = 1000.0 + 37.0 * std::sin(0.1 * p.size());
    }
  });
  return p;
}

template <int D>
NeighbourList neighbours(const Particles<D>& p) {
  Vec<D> lo = origin<D>(), hi = origin<D>();
  for (const auto& x : p.position) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  NeighbourSearch<D> search(lo, hi, kSearch);
  NeighbourList nl;
  search.build(p.position, p.kind, nl);
  return nl;
}

template <int D>
GasRegions regionsOf(const Particles<D>& p) {
  GasRegions r;
  findGasRegions<D>(p, neighbours<D>(p), kLink, kL0, r);
  return r;
}

template <int D>
bool inBall(const Index<D>& k, const Index<D>& centre, double radius) {
  return (k - centre).template cast<double>().squaredNorm() <= radius * radius;
}

// Every gas particle is in some region, every other particle in none; delta_gl follows the region's flag.
template <int D>
void expectConsistent(const Particles<D>& p, const GasRegions& r) {
  ASSERT_EQ(r.region_of.size(), p.size());
  ASSERT_EQ(r.enclosed_particle.size(), p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    ASSERT_EQ(r.region_of[i] >= 0, isGas(p.kind[i], p.phase[i])) << i;
    ASSERT_LT(r.region_of[i], static_cast<std::int32_t>(r.regionCount()));
    ASSERT_EQ(r.enclosed_particle[i], r.region_of[i] >= 0 && r.enclosed[r.region_of[i]]) << i;
  }
}

template <int D>
void checkBubbleStats(const BubbleStats& b, const Particles<D>& p, const GasRegions& r, const Vec<D>& centre) {
  std::size_t count = 0;
  double pressure = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (r.region_of[i] == b.region) ++count, pressure += p.pressure[i];
  EXPECT_EQ(b.particles, count);
  EXPECT_NEAR(b.mean_pressure, pressure / count, 1e-12 * std::abs(pressure / count));
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(b.centroid[k], k < D ? centre[k] : 0.0, 1e-12) << "axis " << k;
  EXPECT_NEAR(b.size, count * std::pow(kL0, D), 1e-12 * count * std::pow(kL0, D));
}

template <int D>
void checkDiscInsideLiquid() {
  const Index<D> zero = Index<D>::Zero();
  const auto p = makeLattice<D>(Index<D>::Constant(-8), Index<D>::Constant(8),
                                [&](const Index<D>& k) { return inBall<D>(k, zero, 2.5) ? kGas : kLiquid; });
  const auto r = regionsOf<D>(p);
  expectConsistent<D>(p, r);
  ASSERT_EQ(r.regionCount(), 1u);
  EXPECT_TRUE(r.enclosed[0]);
  const auto stats = bubbleStatistics<D>(p, r, kL0);
  ASSERT_EQ(stats.size(), 1u);
  EXPECT_EQ(stats[0].region, 0);
  EXPECT_EQ(stats[0].particles, D == 2 ? 21u : 81u);  // lattice points with |k| <= 2.5
  checkBubbleStats<D>(stats[0], p, r, origin<D>());
}

// The same block topped by three gas rows with nothing above: the layer is a region of its own and open.
template <int D>
void checkOpenLayerAbove() {
  const Index<D> zero = Index<D>::Zero();
  Index<D> hi = Index<D>::Constant(8);
  hi[D - 1] = 11;
  const auto p = makeLattice<D>(Index<D>::Constant(-8), hi, [&](const Index<D>& k) {
    return k[D - 1] >= 9 || inBall<D>(k, zero, 2.5) ? kGas : kLiquid;
  });
  const auto r = regionsOf<D>(p);
  expectConsistent<D>(p, r);
  ASSERT_EQ(r.regionCount(), 2u);
  EXPECT_TRUE(r.enclosed[0]);   // the disc: its smallest index comes first
  EXPECT_FALSE(r.enclosed[1]);  // the layer
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!isGas(p.kind[i], p.phase[i])) continue;
    EXPECT_EQ(r.region_of[i], p.position[i][D - 1] > origin<D>()[D - 1] + 8.5 * kL0 ? 1 : 0);
  }
  const auto stats = bubbleStatistics<D>(p, r, kL0);
  ASSERT_EQ(stats.size(), 1u);
  EXPECT_EQ(stats[0].region, 0);
  checkBubbleStats<D>(stats[0], p, r, origin<D>());
}

// Floor: two dummy rows, one wall row (vertical index -3, -2, -1), liquid above. Three gas features spaced along
// axis 0: a pocket touching the wall, a particle two rows above the wall (the wall within the link radius) and a
// particle three rows above it (nothing but liquid within the link radius: a bubble).
template <int D>
void checkGasAtWall() {
  Index<D> lo = Index<D>::Constant(-5), hi = Index<D>::Constant(5);
  lo[0] = -14, hi[0] = 14, lo[D - 1] = -3, hi[D - 1] = 8;
  Index<D> pocket = Index<D>::Zero(), near = Index<D>::Zero(), far = Index<D>::Zero();
  pocket[0] = -8, pocket[D - 1] = 1;
  near[D - 1] = 1;
  far[0] = 8, far[D - 1] = 2;
  const auto p = makeLattice<D>(lo, hi, [&](const Index<D>& k) {
    if (k[D - 1] < -1) return Site{true, ParticleKind::Dummy, Phase::Liquid};
    if (k[D - 1] == -1) return Site{true, ParticleKind::Wall, Phase::Liquid};
    return inBall<D>(k, pocket, 1.5) || k == near || k == far ? kGas : kLiquid;
  });
  const auto r = regionsOf<D>(p);
  expectConsistent<D>(p, r);
  ASSERT_EQ(r.regionCount(), 3u);
  EXPECT_FALSE(r.enclosed[0]);  // pocket: its lowest row (vertical index 0) comes first
  EXPECT_FALSE(r.enclosed[1]);  // two rows above the wall
  EXPECT_TRUE(r.enclosed[2]);   // three rows above the wall
  const auto stats = bubbleStatistics<D>(p, r, kL0);
  ASSERT_EQ(stats.size(), 1u);
  EXPECT_EQ(stats[0].region, 2);
  EXPECT_EQ(stats[0].particles, 1u);
  checkBubbleStats<D>(stats[0], p, r, at<D>(far));
}

template <int D>
void checkSingleGasParticle() {
  const auto p = makeLattice<D>(Index<D>::Constant(-4), Index<D>::Constant(4),
                                [](const Index<D>& k) { return k.isZero() ? kGas : kLiquid; });
  const auto r = regionsOf<D>(p);
  expectConsistent<D>(p, r);
  ASSERT_EQ(r.regionCount(), 1u);
  EXPECT_TRUE(r.enclosed[0]);
  const auto stats = bubbleStatistics<D>(p, r, kL0);
  ASSERT_EQ(stats.size(), 1u);
  EXPECT_EQ(stats[0].particles, 1u);
  checkBubbleStats<D>(stats[0], p, r, origin<D>());
}

// Connected components and the enclosed rule straight from the definitions, O(N^2).
template <int D>
GasRegions bruteForce(const Particles<D>& p) {
  const std::size_t n = p.size();
  const int full = latticeNeighbourCount(D, kLink, kL0);
  auto close = [&](std::size_t i, std::size_t j) {
    return i != j && isActive(p.kind[j]) && (p.position[j] - p.position[i]).norm() < kLink;
  };
  GasRegions r;
  r.region_of.assign(n, -1);
  for (std::size_t s = 0; s < n; ++s) {
    if (!isGas(p.kind[s], p.phase[s]) || r.region_of[s] >= 0) continue;
    const auto id = static_cast<std::int32_t>(r.enclosed.size());
    r.enclosed.push_back(1);
    std::vector<std::size_t> stack{s};
    r.region_of[s] = id;
    while (!stack.empty()) {
      const auto i = stack.back();
      stack.pop_back();
      int count = 0;
      for (std::size_t j = 0; j < n; ++j) {
        if (!close(i, j)) continue;
        ++count;
        if (isGas(p.kind[j], p.phase[j])) {
          if (r.region_of[j] < 0) r.region_of[j] = id, stack.push_back(j);
        } else if (p.kind[j] != ParticleKind::Fluid) {
          r.enclosed[id] = 0;
        }
      }
      if (count < 0.8 * full) r.enclosed[id] = 0;
    }
  }
  return r;
}

// A tank (dummy floor, wall row) of liquid with random gas particles and an open top; some escaped particles.
// Sparser gas in 3D (32 neighbours instead of 12) so that isolated bubbles remain.
template <int D>
Particles<D> randomGas(int half, unsigned seed) {
  const unsigned gas_percent = D == 2 ? 20 : 5;
  std::mt19937 rng(seed);
  Index<D> lo = Index<D>::Constant(-half), hi = Index<D>::Constant(half);
  auto p = makeLattice<D>(lo, hi, [&](const Index<D>& k) {
    const unsigned roll = rng() % 100;
    if (k[D - 1] < -half + 2) return Site{true, ParticleKind::Dummy, Phase::Liquid};
    if (k[D - 1] == -half + 2) return Site{true, ParticleKind::Wall, Phase::Liquid};
    return roll < gas_percent ? kGas : kLiquid;
  });
  for (std::size_t i = 0; i < p.size(); ++i)
    if (rng() % 50 == 0) p.kind[i] = ParticleKind::Escaped;
  return p;
}

template <int D>
void checkAgainstBruteForce(int half) {
  const auto p = randomGas<D>(half, 7);
  const auto r = regionsOf<D>(p);
  expectConsistent<D>(p, r);
  const auto expected = bruteForce<D>(p);
  EXPECT_EQ(r.region_of, expected.region_of);
  EXPECT_EQ(r.enclosed, expected.enclosed);
  std::size_t enclosed = 0;
  for (char e : r.enclosed) enclosed += e;
  EXPECT_GT(enclosed, 5u);                        // not vacuous: bubbles ...
  EXPECT_GT(r.regionCount() - enclosed, 5u);      // ... and open regions
  EXPECT_EQ(bubbleStatistics<D>(p, r, kL0).size(), enclosed);
}

template <int D>
void checkThreadCountIndependence(int half) {
  const auto p = randomGas<D>(half, 11);
  const int before = omp_get_max_threads();
  std::vector<GasRegions> results;
  for (int threads : {1, 2, 3}) {
    omp_set_num_threads(threads);
    results.push_back(regionsOf<D>(p));
  }
  omp_set_num_threads(before);
  const auto stats = bubbleStatistics<D>(p, results[0], kL0);
  ASSERT_GT(results[0].regionCount(), 10u);
  for (std::size_t t = 1; t < results.size(); ++t) {
    EXPECT_EQ(results[t].region_of, results[0].region_of);
    EXPECT_EQ(results[t].enclosed, results[0].enclosed);
    EXPECT_EQ(results[t].enclosed_particle, results[0].enclosed_particle);
    const auto other = bubbleStatistics<D>(p, results[t], kL0);
    ASSERT_EQ(other.size(), stats.size());
    for (std::size_t b = 0; b < stats.size(); ++b) {
      EXPECT_EQ(other[b].mean_pressure, stats[b].mean_pressure);
      EXPECT_EQ(other[b].centroid, stats[b].centroid);
    }
  }
}

}  // namespace

TEST(EnclosedGas, LatticeNeighbourCounts) {
  EXPECT_EQ(latticeNeighbourCount(2, kLink, kL0), 12);
  EXPECT_EQ(latticeNeighbourCount(3, kLink, kL0), 32);
  EXPECT_EQ(latticeNeighbourCount(2, 1.5, 1.0), 8);
  EXPECT_THROW(latticeNeighbourCount(4, kLink, kL0), std::invalid_argument);
}

TEST(EnclosedGas, DiscInsideLiquidIsOneBubble2D) { checkDiscInsideLiquid<2>(); }
TEST(EnclosedGas, SphereInsideLiquidIsOneBubble3D) { checkDiscInsideLiquid<3>(); }
TEST(EnclosedGas, GasLayerWithNothingAboveIsOpen2D) { checkOpenLayerAbove<2>(); }
TEST(EnclosedGas, GasLayerWithNothingAboveIsOpen3D) { checkOpenLayerAbove<3>(); }
TEST(EnclosedGas, GasWithinLinkRadiusOfAWallIsOpen2D) { checkGasAtWall<2>(); }
TEST(EnclosedGas, GasWithinLinkRadiusOfAWallIsOpen3D) { checkGasAtWall<3>(); }
// A bubble that drifts onto a wall stays a bubble (the previous step's delta_gl exempts its particles from the wall
// rule, as from the neighbour count): the wall case above with the pocket enclosed at the last step. Gas that was
// open, the particle two rows above the wall, stays open. Before the twentieth session a bubble under the plunge
// point that came within re of the pool's floor became open gas, which the liquid does not see, and was thrown out at
// 120 m/s 14 ms later (docs/two-phase.md).
TEST(EnclosedGas, ABubbleThatDriftsOntoAWallStaysABubble) {
  const Index<2> pocket(-8, 1), near(0, 1), far(8, 2);
  const auto p = makeLattice<2>(Index<2>(-14, -3), Index<2>(14, 8), [&](const Index<2>& k) {
    if (k[1] < -1) return Site{true, ParticleKind::Dummy, Phase::Liquid};
    if (k[1] == -1) return Site{true, ParticleKind::Wall, Phase::Liquid};
    return inBall<2>(k, pocket, 1.5) || k == near || k == far ? kGas : kLiquid;
  });
  std::vector<char> was_enclosed(p.size(), 0);
  for (std::size_t i = 0; i < p.size(); ++i)
    was_enclosed[i] = isGas(p.kind[i], p.phase[i]) && p.position[i][0] < at<2>(Index<2>(-5, 0))[0];  // the pocket
  GasRegionOptions options;
  options.was_enclosed = &was_enclosed;
  GasRegions r;
  findGasRegions<2>(p, neighbours<2>(p), kLink, kL0, r, options);
  expectConsistent<2>(p, r);
  ASSERT_EQ(r.regionCount(), 3u);
  EXPECT_TRUE(r.enclosed[0]);   // the pocket, on the wall, a bubble at the last step
  EXPECT_FALSE(r.enclosed[1]);  // two rows above the wall, open at the last step
  EXPECT_TRUE(r.enclosed[2]);   // three rows above the wall
}

TEST(EnclosedGas, SingleGasParticleInLiquidIsABubble2D) { checkSingleGasParticle<2>(); }
TEST(EnclosedGas, SingleGasParticleInLiquidIsABubble3D) { checkSingleGasParticle<3>(); }

TEST(EnclosedGas, TwoBubblesGetIdsBySmallestIndex) {
  // b sits lower (smaller indices) though further along axis 0: it is region 0.
  const Index<2> a(-5, 5), b(5, -5);
  const auto p = makeLattice<2>(Index<2>::Constant(-10), Index<2>::Constant(10), [&](const Index<2>& k) {
    return inBall<2>(k, a, 1.5) || inBall<2>(k, b, 2.0) ? kGas : kLiquid;
  });
  const auto r = regionsOf<2>(p);
  expectConsistent<2>(p, r);
  ASSERT_EQ(r.regionCount(), 2u);
  EXPECT_TRUE(r.enclosed[0] && r.enclosed[1]);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (r.region_of[i] < 0) continue;
    EXPECT_EQ(r.region_of[i], p.position[i][1] < origin<2>()[1] ? 0 : 1);
  }
  const auto stats = bubbleStatistics<2>(p, r, kL0);
  ASSERT_EQ(stats.size(), 2u);
  EXPECT_EQ(stats[0].region, 0);
  EXPECT_EQ(stats[0].particles, 13u);  // |k| <= 2
  checkBubbleStats<2>(stats[0], p, r, at<2>(b));
  EXPECT_EQ(stats[1].region, 1);
  EXPECT_EQ(stats[1].particles, 9u);  // |k| <= 1.5
  checkBubbleStats<2>(stats[1], p, r, at<2>(a));
}

TEST(EnclosedGas, EscapedParticlesAreIgnored) {
  // Two gas particles 4 l0 apart in liquid, bridged by a chain of escaped gas particles. Escaped particles
  // neither link the two nor open them (they are not liquid), whether or not the list still holds them.
  auto p = makeLattice<2>(Index<2>::Constant(-8), Index<2>::Constant(8), [](const Index<2>& k) {
    return k == Index<2>(-2, 0) || k == Index<2>(2, 0) ? kGas : kLiquid;
  });
  const std::size_t first_chain = p.size();
  for (int x = -2; x <= 2; ++x) {
    p.add(origin<2>() + kL0 * Vec<2>(x, 0.5), Vec<2>::Zero(), ParticleKind::Fluid, Phase::Gas);
    p.pressure.back() = 1e9;
  }
  const NeighbourList stale = neighbours<2>(p);  // built while the chain was still active
  for (std::size_t i = first_chain; i < p.size(); ++i) p.kind[i] = ParticleKind::Escaped;
  for (const NeighbourList* nl : {&stale, static_cast<const NeighbourList*>(nullptr)}) {
    GasRegions r;
    findGasRegions<2>(p, nl ? *nl : neighbours<2>(p), kLink, kL0, r);
    expectConsistent<2>(p, r);
    ASSERT_EQ(r.regionCount(), 2u);
    EXPECT_TRUE(r.enclosed[0] && r.enclosed[1]);
    for (std::size_t i = first_chain; i < p.size(); ++i) EXPECT_EQ(r.region_of[i], -1);
    const auto stats = bubbleStatistics<2>(p, r, kL0);
    ASSERT_EQ(stats.size(), 2u);
    EXPECT_EQ(stats[0].particles + stats[1].particles, 2u);
    EXPECT_LT(stats[0].mean_pressure, 2000.0);
  }
}

TEST(EnclosedGas, LiquidOnlyHasNoRegions) {
  auto p = makeLattice<3>(Index<3>::Constant(-3), Index<3>::Constant(3), [](const Index<3>&) { return kLiquid; });
  p.kind[5] = ParticleKind::Escaped;
  p.phase[5] = Phase::Gas;  // an escaped gas particle is not gas
  const auto r = regionsOf<3>(p);
  expectConsistent<3>(p, r);
  EXPECT_EQ(r.regionCount(), 0u);
  EXPECT_TRUE(bubbleStatistics<3>(p, r, kL0).empty());
  Particles<2> none;
  const auto empty = regionsOf<2>(none);
  EXPECT_EQ(empty.regionCount(), 0u);
  EXPECT_TRUE(empty.region_of.empty());
}

TEST(EnclosedGas, MismatchedNeighbourListThrows) {
  const auto p = makeLattice<2>(Index<2>::Constant(-2), Index<2>::Constant(2), [](const Index<2>&) { return kGas; });
  GasRegions r;
  EXPECT_THROW(findGasRegions<2>(p, NeighbourList{}, kLink, kL0, r), std::invalid_argument);
}

TEST(EnclosedGas, RandomGasMatchesBruteForce2D) { checkAgainstBruteForce<2>(30); }
TEST(EnclosedGas, RandomGasMatchesBruteForce3D) { checkAgainstBruteForce<3>(9); }
TEST(EnclosedGas, ThreadCountIndependent2D) { checkThreadCountIndependence<2>(40); }
TEST(EnclosedGas, ThreadCountIndependent3D) { checkThreadCountIndependence<3>(12); }

// The join radius (numerics.gas_region_link): two gas particles in water with one water particle between them
// (2 l0 apart) are one region when joined at the number-density radius 2.1 l0 and two at 1.5 l0; the gas of a
// lattice bubble (neighbours at l0 and 1.41 l0) stays one region at 1.5 l0; every region is enclosed either way.
TEST(GasRegions, JoinRadiusSplitsGasSeparatedByOneWaterParticle) {
  const Index<2> lo(-5, -5), hi(5, 5);
  const auto p = makeLattice<2>(lo, hi, [](const Index<2>& k) {
    return (k == Index<2>(-1, 0) || k == Index<2>(1, 0)) ? kGas : kLiquid;
  });
  const auto nl = neighbours<2>(p);
  GasRegions wide, tight;
  findGasRegions<2>(p, nl, kLink, kL0, wide);
  findGasRegions<2>(p, nl, kLink, kL0, tight, {nullptr, 0, 1.5 * kL0});
  EXPECT_EQ(wide.regionCount(), 1u);
  EXPECT_EQ(tight.regionCount(), 2u);
  for (char e : tight.enclosed) EXPECT_TRUE(e);
  const auto bubble = makeLattice<2>(Index<2>(-8, -8), Index<2>(8, 8), [](const Index<2>& k) {
    return inBall<2>(k, Index<2>(0, 0), 3.0) ? kGas : kLiquid;
  });
  GasRegions one;
  findGasRegions<2>(bubble, neighbours<2>(bubble), kLink, kL0, one, {nullptr, 0, 1.5 * kL0});
  ASSERT_EQ(one.regionCount(), 1u);
  EXPECT_TRUE(one.enclosed[0]);
}

// Dispersed gas (numerics.dispersed_gas_fraction): a chain of single gas particles through the water, each one
// water particle from the next (2 l0 apart) and the top one 2 l0 under the air, joins the air above at the plain
// link and is open gas with it. Counted as dispersed (10 of its 12 neighbours are water), every particle of the
// chain is a region of its own, enclosed in the water, while the air (whose lowest row has 4 water neighbours
// of 12) stays one open region.
TEST(GasRegions, DispersedGasDoesNotJoinTheWatersAirToTheAirAbove) {
  const Index<2> lo(-6, -9), hi(6, 4);
  auto inChain = [](const Index<2>& k) { return k[0] == 0 && (k[1] == -1 || k[1] == -3 || k[1] == -5); };
  const auto p = makeLattice<2>(lo, hi, [&](const Index<2>& k) {
    return (k[1] >= 1 || inChain(k)) ? kGas : kLiquid;  // air from row 1 up; its top row borders open space
  });
  const auto nl = neighbours<2>(p);
  GasRegions plain, dispersed;
  findGasRegions<2>(p, nl, kLink, kL0, plain);
  GasRegionOptions options;
  options.dispersed_fraction = 0.5;
  findGasRegions<2>(p, nl, kLink, kL0, dispersed, options);
  const std::size_t top = p.size() - 1;  // the last lattice point: the air's top row
  const std::int32_t air_plain = plain.region_of[top], air_dispersed = dispersed.region_of[top];
  std::size_t chain = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!isGas(p.kind[i], p.phase[i])) continue;
    if (p.position[i][1] > origin<2>()[1]) {  // the air
      EXPECT_EQ(plain.region_of[i], air_plain);
      EXPECT_EQ(dispersed.region_of[i], air_dispersed) << "the air stays one region";
      continue;
    }
    ++chain;
    EXPECT_EQ(plain.region_of[i], air_plain) << "plain link: the chain belongs to the air";
    EXPECT_NE(dispersed.region_of[i], air_dispersed);
    EXPECT_TRUE(dispersed.enclosed_particle[i]) << "dispersed: the chain's gas is enclosed in the water";
  }
  EXPECT_EQ(chain, 3u);
  EXPECT_FALSE(plain.enclosed[air_plain]);
  EXPECT_FALSE(dispersed.enclosed[air_dispersed]);
  EXPECT_EQ(dispersed.regionCount(), 4u) << "the air and three regions of one particle";
  EXPECT_EQ(dispersed.dispersed, 3u) << "the guard's firings (diagnostics.csv dispersed_gas): the chain";
  EXPECT_EQ(plain.dispersed, 0u);
  // At fraction 0.95 (10 or 11 of 12 falls short) the chain is not dispersed and joins the air as before.
  options.dispersed_fraction = 0.95;
  GasRegions strict;
  findGasRegions<2>(p, nl, kLink, kL0, strict, options);
  EXPECT_EQ(strict.regionCount(), 1u);
}

// numerics.dispersed_gas_touch: air in a one-particle dip of the water's surface has 8 water neighbours of 12, so at
// dispersed_gas_fraction 0.5 it is dispersed and becomes a pocket of its own, enclosed in the water (the rule that
// carried channel-surface air into the waterfall's water, docs/waterfall.md). Touching the air above (1 l0 away), it
// joins the air's region with the touch rule. A dispersed particle between two separate pockets of air joins only
// the nearer one: the two stay two regions.
TEST(GasRegions, DispersedGasTouchingTheAirJoinsItAndNeverBridgesTwoRegions) {
  const Index<2> lo(-6, -6), hi(6, 4);
  auto dip = [](const Index<2>& k) { return k[0] == 0 && k[1] == 0; };
  const auto p = makeLattice<2>(lo, hi, [&](const Index<2>& k) { return (k[1] >= 1 || dip(k)) ? kGas : kLiquid; });
  const auto nl = neighbours<2>(p);
  std::size_t in_dip = p.size();
  for (std::size_t i = 0; i < p.size(); ++i)
    if ((p.position[i] - at<2>(Index<2>(0, 0))).norm() < 1e-9) in_dip = i;
  ASSERT_LT(in_dip, p.size());
  const std::size_t top = p.size() - 1;
  GasRegionOptions options;
  options.dispersed_fraction = 0.5;
  GasRegions apart, touching;
  findGasRegions<2>(p, nl, kLink, kL0, apart, options);
  EXPECT_NE(apart.region_of[in_dip], apart.region_of[top]);
  EXPECT_TRUE(apart.enclosed_particle[in_dip]) << "without the touch rule the dip's air is a pocket in the water";
  EXPECT_EQ(apart.dispersed, 1u);
  options.dispersed_touch = 1.5 * kL0;
  findGasRegions<2>(p, nl, kLink, kL0, touching, options);
  EXPECT_EQ(touching.region_of[in_dip], touching.region_of[top]);
  EXPECT_FALSE(touching.enclosed_particle[in_dip]) << "it is the open air it touches";
  EXPECT_EQ(touching.regionCount(), 1u);
  EXPECT_EQ(touching.dispersed, 0u) << "joined by the touch rule: not counted";

  // Two pockets of 4 x 6 air in the water, two columns apart, and one dispersed air particle between them that
  // touches both (1 l0 from the left one, 2 l0 from the right one; touch radius 2.1 l0, join radius 1.5 l0).
  auto pocket = [](const Index<2>& k) {
    return (k[1] >= 0 && k[1] <= 5) && ((k[0] >= -6 && k[0] <= -3) || (k[0] >= 0 && k[0] <= 3));
  };
  auto lone = [](const Index<2>& k) { return k[0] == -2 && k[1] == 2; };
  const auto q = makeLattice<2>(Index<2>(-10, -5), Index<2>(7, 10),
                                [&](const Index<2>& k) { return (pocket(k) || lone(k)) ? kGas : kLiquid; });
  GasRegionOptions join_wide;
  join_wide.join_radius = 1.5 * kL0;
  join_wide.dispersed_fraction = 0.5;
  join_wide.dispersed_touch = 2.1 * kL0;
  GasRegions two;
  findGasRegions<2>(q, neighbours<2>(q), kLink, kL0, two, join_wide);
  std::set<std::int32_t> pockets;
  std::int32_t lone_region = -1, left_region = -1;
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (!isGas(q.kind[i], q.phase[i])) continue;
    const Vec<2> d = (q.position[i] - origin<2>()) / kL0;
    if (std::abs(d[0] + 2.0) < 1e-9 && std::abs(d[1] - 2.0) < 1e-9) lone_region = two.region_of[i];
    else pockets.insert(two.region_of[i]);
    if (std::abs(d[0] + 3.0) < 1e-9 && std::abs(d[1] - 2.0) < 1e-9) left_region = two.region_of[i];
  }
  EXPECT_EQ(lone_region, left_region) << "the dispersed particle joins the nearer pocket";
}

// A closed gas domain (numerics.closed_pockets): water on a walled floor under a layer of air, with two pockets of
// air against the floor, of 18 particles each (above bubble_min_particles = 6). The right pocket holds a vent's gas
// (the atmosphere), the left none. By size ("small") both are open gas: they touch the wall. With the atmosphere
// ("unvented") the left is a pocket in the water, a bubble; the right reaches the ambient and stays open; the layer
// above (the largest region) stays open too.
TEST(GasRegions, AnUnventedPocketOnAWallIsABubbleOfAnySize) {
  const Index<2> left(-8, 1), right(8, 1);
  const auto p = makeLattice<2>(Index<2>(-14, -3), Index<2>(14, 12), [&](const Index<2>& k) {
    if (k[1] < -1) return Site{true, ParticleKind::Dummy, Phase::Liquid};
    if (k[1] == -1) return Site{true, ParticleKind::Wall, Phase::Liquid};
    return k[1] >= 8 || inBall<2>(k, left, 2.3) || inBall<2>(k, right, 2.3) ? kGas : kLiquid;
  });
  const auto nl = neighbours<2>(p);
  std::vector<int> vent_of(p.size(), -1);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (isGas(p.kind[i], p.phase[i]) && p.position[i][0] > at<2>(Index<2>(0, 0))[0] &&
        p.position[i][1] < at<2>(Index<2>(0, 5))[1])
      vent_of[i] = 0;  // the right pocket: a vent's gas
  GasRegionOptions by_size;
  by_size.closed_small_region = 6;
  GasRegionOptions unvented = by_size;
  unvented.vent_of = &vent_of;
  GasRegions small, vents;
  findGasRegions<2>(p, nl, kLink, kL0, small, by_size);
  findGasRegions<2>(p, nl, kLink, kL0, vents, unvented);
  auto regionAt = [&](const GasRegions& r, const Index<2>& k) {
    for (std::size_t i = 0; i < p.size(); ++i)
      if ((p.position[i] - at<2>(k)).norm() < 1e-9 * kL0) return r.region_of[i];
    return std::int32_t{-1};
  };
  ASSERT_EQ(small.regionCount(), 3u);
  ASSERT_EQ(vents.regionCount(), 3u);
  EXPECT_EQ(small.regionSizes()[regionAt(small, left)], 18u);
  EXPECT_FALSE(small.enclosed[regionAt(small, left)]) << "by size a pocket of 18 on the wall is open gas";
  EXPECT_FALSE(small.enclosed[regionAt(small, right)]);
  EXPECT_TRUE(vents.enclosed[regionAt(vents, left)]) << "no vent's gas: a pocket in the water";
  EXPECT_FALSE(vents.enclosed[regionAt(vents, right)]) << "it holds a vent's gas: the atmosphere";
  EXPECT_FALSE(vents.enclosed[regionAt(vents, Index<2>(0, 10))]) << "the layer of air above";
}

// The neighbour list carried over the particles an open boundary removed and made (NeighbourSearch::carryOver,
// neighbour_search.hpp): it holds every pair within the radius, as a new build does, each list in ascending order,
// with the near list filtered at the build positions; and it refuses what it cannot carry (a particle moved past
// half the skin, a reordering, a particle gone inactive), leaving the list as it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "mps/neighbour_search.hpp"

using namespace mistfall;

namespace {

constexpr double kRadius = 0.09, kSkin = 0.02;

template <int D>
Vec<D> randomPoint(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Vec<D> x;
  for (int k = 0; k < D; ++k) x[k] = u(rng);
  return x;
}

// 1200 random particles, a list built with a skin, then: every 7th removed, the others moved by less than half the
// skin, 40 made (appended, as Particles::add does).
template <int D>
struct Changed {
  std::mt19937_64 rng{7};
  Particles<D> p;
  NeighbourSearch<D> search{Vec<D>::Zero(), Vec<D>::Ones(), kRadius, kSkin};
  NeighbourList list;
  Changed() {
    for (int i = 0; i < 1200; ++i) p.add(randomPoint<D>(rng), Vec<D>::Zero(), ParticleKind::Fluid, Phase::Liquid);
    search.build(p.position, p.kind, p.id, list);
    std::vector<char> remove(p.size(), 0);
    for (std::size_t i = 0; i < p.size(); i += 7) remove[i] = 1;
    p.erase(remove);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (auto& x : p.position) {
      Vec<D> d;
      for (int k = 0; k < D; ++k) d[k] = u(rng);
      x += d.normalized() * (0.45 * kSkin * std::abs(u(rng)));
    }
    for (int i = 0; i < 40; ++i) p.add(randomPoint<D>(rng), Vec<D>::Zero(), ParticleKind::Fluid, Phase::Liquid);
  }
};

// Every pair within `radius` now is in the list, no index twice, each list ascending.
template <int D>
void expectCovers(const Particles<D>& p, const NeighbourList& list, double radius) {
  ASSERT_EQ(p.size(), list.particleCount());
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::vector<std::int32_t> l(list.indices.begin() + list.begin(i), list.indices.begin() + list.end(i));
    EXPECT_TRUE(std::adjacent_find(l.begin(), l.end(), std::greater_equal<>()) == l.end()) << "particle " << i;
    for (std::size_t j = 0; j < p.size(); ++j)
      if (j != i && (p.position[j] - p.position[i]).norm() < radius) {
        ++pairs;
        EXPECT_TRUE(std::binary_search(l.begin(), l.end(), static_cast<std::int32_t>(j))) << i << " misses " << j;
      }
  }
  EXPECT_GT(pairs, p.size() / 4);  // not vacuous
}

template <int D>
void checkCarryOver() {
  Changed<D> c;
  EXPECT_FALSE(c.search.covers(c.p.position, c.p.kind));
  const std::int64_t builds = c.search.builds();
  ASSERT_TRUE(c.search.carryOver(c.p.position, c.p.kind, c.p.id, c.list));
  EXPECT_EQ(builds + 1, c.search.builds());  // a new list for the solver's near list to be filtered from
  expectCovers(c.p, c.list, kRadius);
  // The near list, filtered at the build positions with reach r + skin, holds the pairs within r.
  NeighbourList near;
  filterNeighbours<D>(c.search.builtPositions(), c.list, 0.05 + kSkin, near);
  expectCovers(c.p, near, 0.05);
  // It covers the particles until one of them has moved half the skin from where it was listed.
  EXPECT_TRUE(c.search.covers(c.p.position, c.p.kind));
  c.p.position.back()[0] += 0.6 * kSkin;
  EXPECT_FALSE(c.search.covers(c.p.position, c.p.kind));
}

}  // namespace

TEST(NeighbourCarryOver, HoldsEveryPairANewBuildWould2D) { checkCarryOver<2>(); }
TEST(NeighbourCarryOver, HoldsEveryPairANewBuildWould3D) { checkCarryOver<3>(); }

TEST(NeighbourCarryOver, RefusesWhatItCannotCarry) {
  auto refuses = [](auto&& change) {
    Changed<2> c;
    change(c.p);
    const NeighbourList before = c.list;
    EXPECT_FALSE(c.search.carryOver(c.p.position, c.p.kind, c.p.id, c.list));
    EXPECT_EQ(before.indices, c.list.indices);
    EXPECT_EQ(before.offsets, c.list.offsets);
  };
  refuses([](Particles<2>& p) { p.position[3][1] += 0.6 * kSkin; });                   // a survivor moved too far
  refuses([](Particles<2>& p) { std::swap(p.id[3], p.id[4]); });                      // reordered
  refuses([](Particles<2>& p) { p.kind[5] = ParticleKind::Escaped; });                 // gone inactive
  refuses([](Particles<2>& p) { p.kind.back() = ParticleKind::Escaped; });             // made inactive
  refuses([](Particles<2>& p) { std::swap(p.id.front(), p.id.back()); });             // a new one among the old
}

TEST(NeighbourCarryOver, NeedsTheBuildsIds) {
  Changed<2> c;
  c.search.build(c.p.position, c.p.kind, c.list);  // no ids given: nothing to carry over from
  c.p.add(Vec<2>(0.5, 0.5), Vec<2>::Zero(), ParticleKind::Fluid, Phase::Liquid);
  EXPECT_FALSE(c.search.carryOver(c.p.position, c.p.kind, c.p.id, c.list));
}

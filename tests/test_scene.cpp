// Tests of the initial particle arrangement: lattice counts, water placement, wall/dummy classification.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <tuple>

#include "case/case_file.hpp"
#include "case/scene.hpp"

using namespace mistfall;

namespace {

std::string header2d(const std::string& domain_min, const std::string& domain_max, double l0) {
  return "[case]\nname = \"s\"\ndimension = 2\n[domain]\nmin = " + domain_min + "\nmax = " + domain_max +
         "\n[numerics]\nparticle_spacing = " + std::to_string(l0) + "\n[output]\nend_time = 1.0\n";
}

std::string region(const std::string& name, const std::string& material, const std::string& min,
                   const std::string& max, const std::string& extra = "") {
  return "[[region]]\nname = \"" + name + "\"\nmaterial = \"" + material + "\"\nmin = " + min + "\nmax = " + max +
         "\n" + extra;
}

// Lattice index of a position (exact for lattice points).
template <int D>
std::tuple<long, long, long> indexOf(const CaseConfig& c, const Vec<D>& x) {
  long i[3] = {0, 0, 0};
  for (int k = 0; k < D; ++k)
    i[k] = std::lround((x[k] - c.domain.min[k]) / c.numerics.particle_spacing - 0.5);
  return {i[0], i[1], i[2]};
}

template <int D>
void expectDistinctPositions(const CaseConfig& c, const Particles<D>& p) {
  std::set<std::tuple<long, long, long>> seen;
  for (const auto& x : p.position) EXPECT_TRUE(seen.insert(indexOf<D>(c, x)).second) << x.transpose();
}

}  // namespace

TEST(Scene, WaterBoxCount2DIsProductOfAxisCounts) {
  // l0 = 0.1 from 0: x points 0.15..0.55 in [0.12, 0.58) -> 5; y points 0.05..0.35 in [0, 0.4) -> 4.
  const CaseConfig c = parseCase(header2d("[0, 0]", "[1, 1]", 0.1) +
                                     region("w", "water", "[0.12, 0.0]", "[0.58, 0.4]", "velocity = [0.5, -0.25]\n"),
                                 "t");
  const auto p = buildParticles<2>(c);
  EXPECT_EQ(p.size(), 5u * 4u);
  EXPECT_EQ(countLatticePoints(c, c.regions[0].box), 5u * 4u);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(p.kind[i], ParticleKind::Fluid);
    EXPECT_EQ(p.phase[i], Phase::Liquid);
    EXPECT_DOUBLE_EQ(p.velocity[i].x(), 0.5);
    EXPECT_DOUBLE_EQ(p.velocity[i].y(), -0.25);
    EXPECT_DOUBLE_EQ(p.pressure[i], 0.0);
  }
}

TEST(Scene, BoxEdgesOnLatticeMultiplesAreRobust) {
  // Edges at domain.min + k l0 where k l0 is not exact in binary (l0 = 0.008, origin -0.032).
  const CaseConfig c = parseCase(header2d("[-0.032, -0.032]", "[0.232, 0.28]", 0.008) +
                                     region("w", "water", "[0.0, 0.0]", "[0.2, 0.2]") +
                                     region("v", "water", "[0.2, 0.104]", "[0.232, 0.28]"),
                                 "t");
  EXPECT_EQ(countLatticePoints(c, c.regions[0].box), 25u * 25u);
  EXPECT_EQ(countLatticePoints(c, c.regions[1].box), 4u * 22u);
  EXPECT_EQ(countLatticePoints(c, c.domain), 33u * 39u);
  EXPECT_EQ(buildParticles<2>(c).size(), 25u * 25u + 4u * 22u);
}

TEST(Scene, WaterBoxCount3DIsProductOfAxisCounts) {
  const std::string text =
      "[case]\nname = \"s3\"\ndimension = 3\n[domain]\nmin = [-0.1, 0, 0]\nmax = [1, 0.5, 0.7]\n"
      "[numerics]\nparticle_spacing = 0.05\n[output]\nend_time = 1\n"
      "[[region]]\nname = \"w\"\nmin = [0, 0.1, 0.2]\nmax = [0.3, 0.4, 0.6]\nvelocity = [0, 1, 2]\n";
  const CaseConfig c = parseCase(text, "t");
  const auto p = buildParticles<3>(c);
  EXPECT_EQ(p.size(), 6u * 6u * 8u);
  EXPECT_EQ(countLatticePoints(c, c.regions[0].box), 6u * 6u * 8u);
  EXPECT_EQ(p.count(ParticleKind::Fluid), p.size());
  EXPECT_DOUBLE_EQ(p.velocity[0].z(), 2.0);
  expectDistinctPositions(c, p);
}

TEST(Scene, BottomWallOfFourLayersHasOneWallAndThreeDummyLayers) {
  const CaseConfig c = parseCase(header2d("[0, 0]", "[1, 1]", 0.1) + region("water", "water", "[0, 0.4]", "[1, 0.8]") +
                                     region("floor", "wall", "[0, 0]", "[1, 0.4]"),
                                 "t");
  const auto p = buildParticles<2>(c);
  EXPECT_EQ(p.count(ParticleKind::Fluid), 40u);
  EXPECT_EQ(p.count(ParticleKind::Wall), 10u);
  EXPECT_EQ(p.count(ParticleKind::Dummy), 30u);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] == ParticleKind::Wall) EXPECT_NEAR(p.position[i].y(), 0.35, 1e-12);
    if (p.kind[i] == ParticleKind::Dummy) EXPECT_LT(p.position[i].y(), 0.3);
    if (isFixed(p.kind[i])) EXPECT_EQ(p.velocity[i], Vec<2>::Zero());
  }
}

TEST(Scene, BottomWall3DHasOneWallLayer) {
  const std::string text =
      "[case]\nname = \"s3\"\ndimension = 3\n[domain]\nmin = [0, 0, 0]\nmax = [0.5, 0.5, 0.5]\n"
      "[numerics]\nparticle_spacing = 0.1\n[output]\nend_time = 1\n"
      "[[region]]\nname = \"w\"\nmin = [0, 0, 0.3]\nmax = [0.5, 0.5, 0.4]\n"
      "[[region]]\nname = \"floor\"\nmaterial = \"wall\"\nmin = [0, 0, 0]\nmax = [0.5, 0.5, 0.3]\n";
  const auto p = buildParticles<3>(parseCase(text, "t"));
  EXPECT_EQ(p.count(ParticleKind::Fluid), 25u);
  EXPECT_EQ(p.count(ParticleKind::Wall), 25u);
  EXPECT_EQ(p.count(ParticleKind::Dummy), 50u);
}

TEST(Scene, HydrostaticTankClassification) {
  // 33 x 39 lattice; walls 4 thick on the left, right and bottom, 35 rows high.
  const CaseConfig c = loadCaseFile(std::string(MISTFALL_SOURCE_DIR) + "/cases/hydrostatic.toml");
  const auto p = buildParticles<2>(c);
  EXPECT_EQ(p.count(ParticleKind::Fluid), 625u);
  // Wall: bottom row 3 (cols 3..29) + inner columns above it (2 x 31) + the top row of each side wall (2 x 3).
  EXPECT_EQ(p.count(ParticleKind::Wall), 27u + 62u + 6u);
  EXPECT_EQ(p.count(ParticleKind::Wall) + p.count(ParticleKind::Dummy), 33u * 4u + 2u * 4u * 31u);
  expectDistinctPositions(c, p);
}

TEST(Scene, OrderWaterFirstThenWallsAndEveryWaterParticleInItsRegion) {
  const CaseConfig c = parseCase(header2d("[0, 0]", "[1, 1]", 0.1) + region("a", "water", "[0.2, 0.2]", "[0.5, 0.6]") +
                                     region("left", "wall", "[0, 0]", "[0.2, 1]") +
                                     region("b", "water", "[0.6, 0.2]", "[0.9, 0.5]", "velocity = [1, 0]\n") +
                                     region("floor", "wall", "[0, 0]", "[1, 0.2]"),
                                 "t");
  const auto p = buildParticles<2>(c);
  const std::size_t na = countLatticePoints(c, c.regions[0].box), nb = countLatticePoints(c, c.regions[2].box);
  ASSERT_EQ(na, 12u);
  ASSERT_EQ(nb, 9u);
  ASSERT_GT(p.size(), na + nb);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool water = i < na + nb;
    EXPECT_EQ(p.kind[i] == ParticleKind::Fluid, water) << i;
    if (!water) continue;
    const Box& b = c.regions[i < na ? 0 : 2].box;
    for (int k = 0; k < 2; ++k) {
      EXPECT_GE(p.position[i][k], b.min[k]);
      EXPECT_LT(p.position[i][k], b.max[k]);
    }
    EXPECT_DOUBLE_EQ(p.velocity[i].x(), i < na ? 0.0 : 1.0);
    if (i > 0 && i != na) {  // lexicographic within a region, axis 0 slowest
      const auto& x0 = p.position[i - 1];
      const auto& x1 = p.position[i];
      EXPECT_TRUE(x0.x() < x1.x() || (x0.x() == x1.x() && x0.y() < x1.y())) << i;
    }
  }
  // Overlapping wall regions are merged: the corner [0,0.2)x[0,0.2) appears once.
  EXPECT_EQ(p.size() - na - nb, 2u * 10u + 8u * 2u);
  expectDistinctPositions(c, p);
}

TEST(Scene, ShippedCasesHaveDistinctPositionsAndAreDeterministic) {
  const std::string dir = std::string(MISTFALL_SOURCE_DIR) + "/cases/";
  const CaseConfig d = loadCaseFile(dir + "dam_break.toml");
  const auto a = buildParticles<2>(d);
  const auto b = buildParticles<2>(d);
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.kind, b.kind);
  expectDistinctPositions(d, a);

  const CaseConfig d3 = loadCaseFile(dir + "dam_break_3d.toml");
  const auto p3 = buildParticles<3>(d3);
  expectDistinctPositions(d3, p3);
  // 46 x 16 x 33 lattice; solid = everything below z = 0 or outside the inner tank, up to z = 0.16.
  const std::size_t solid = 46u * 16u * 3u + (46u * 16u - 40u * 10u) * 27u;
  EXPECT_EQ(p3.count(ParticleKind::Wall) + p3.count(ParticleKind::Dummy), solid);
  for (std::size_t i = 0; i < p3.size(); ++i)
    if (p3.kind[i] == ParticleKind::Fluid) EXPECT_LT(p3.position[i].z(), 0.12);
}

TEST(Scene, DimensionMismatchThrows) {
  const CaseConfig c = parseCase(header2d("[0, 0]", "[1, 1]", 0.1) + region("w", "water", "[0, 0]", "[1, 1]"), "t");
  EXPECT_THROW(buildParticles<3>(c), std::invalid_argument);
}

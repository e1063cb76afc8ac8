// Tests of the initial particle arrangement: lattice counts, water placement, wall/dummy classification.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <set>
#include <string>
#include <tuple>
#include <vector>

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

namespace {

std::string circle(const std::string& name, const std::string& material, const std::string& center, double radius,
                   const std::string& extra = "") {
  return "[[region]]\nname = \"" + name + "\"\nmaterial = \"" + material + "\"\nshape = \"circle\"\ncenter = " +
         center + "\nradius = " + std::to_string(radius) + "\n" + extra;
}

template <int D>
std::size_t countPhase(const Particles<D>& p, Phase ph) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < p.size(); ++i) n += p.kind[i] == ParticleKind::Fluid && p.phase[i] == ph;
  return n;
}

// Lattice points of a 2D case whose distance from `c` is at most r (brute force over the whole domain).
std::size_t pointsInDisc(const CaseConfig& cfg, double cx, double cy, double r) {
  const double l0 = cfg.numerics.particle_spacing;
  std::size_t n = 0;
  for (std::int64_t i = 0; i < domainLatticeCount(cfg, 0); ++i)
    for (std::int64_t j = 0; j < domainLatticeCount(cfg, 1); ++j) {
      const double x = cfg.domain.min[0] + (i + 0.5) * l0 - cx, y = cfg.domain.min[1] + (j + 0.5) * l0 - cy;
      n += std::hypot(x, y) <= r * (1 + 1e-12);
    }
  return n;
}

}  // namespace

TEST(SceneGas, GasFillsDomainAroundWaterAndWalls) {
  // 10 x 10 lattice. "air" fills the domain and is declared first, so water and walls win over it.
  const CaseConfig c = parseCase(header2d("[0, 0]", "[1, 1]", 0.1) +
                                     region("air", "gas", "[0, 0]", "[1, 1]", "velocity = [0, 0.25]\n") +
                                     region("w", "water", "[0.3, 0.2]", "[0.7, 0.6]") +
                                     region("floor", "wall", "[0, 0]", "[1, 0.2]") +
                                     region("left", "wall", "[0, 0]", "[0.2, 1]"),
                                 "t");
  const auto p = buildParticles<2>(c);
  const std::size_t water = 4u * 4u, solid = 10u * 2u + 2u * 8u;
  const std::size_t gas = countLatticePoints(c, c.domain) - water - solid;
  ASSERT_EQ(gas, 48u);
  EXPECT_EQ(p.size(), 100u);
  EXPECT_EQ(countPhase(p, Phase::Liquid), water);
  EXPECT_EQ(countPhase(p, Phase::Gas), gas);
  EXPECT_EQ(p.count(ParticleKind::Wall) + p.count(ParticleKind::Dummy), solid);
  expectDistinctPositions(c, p);  // gas takes no water or wall point
  for (std::size_t i = 0; i < p.size(); ++i) {
    // Order: water, then gas, then solids.
    const bool is_water = i < water, is_gas = i >= water && i < water + gas;
    EXPECT_EQ(p.kind[i] == ParticleKind::Fluid && p.phase[i] == Phase::Liquid, is_water) << i;
    EXPECT_EQ(p.kind[i] == ParticleKind::Fluid && p.phase[i] == Phase::Gas, is_gas) << i;
    if (is_gas) {
      EXPECT_DOUBLE_EQ(p.velocity[i].y(), 0.25);
      const auto& x = p.position[i];
      EXPECT_FALSE(x.x() > 0.3 && x.x() < 0.7 && x.y() > 0.2 && x.y() < 0.6) << x.transpose();
      EXPECT_TRUE(x.x() > 0.2 && x.y() > 0.2) << x.transpose();
    }
    // The inner wall layer touches gas above y = 0.6 and beside the water: it is Wall, not Dummy.
    if (isFixed(p.kind[i])) {
      const auto& x = p.position[i];
      const bool inner =
          (std::abs(x.x() - 0.15) < 1e-9 && x.y() > 0.1) || (std::abs(x.y() - 0.15) < 1e-9 && x.x() > 0.1);
      EXPECT_EQ(p.kind[i] == ParticleKind::Wall, inner) << x.transpose();
    }
  }
  // A gas-only neighbour makes a wall point Wall: e.g. (0.15, 0.85) has only gas and wall around it.
  bool found = false;
  for (std::size_t i = 0; i < p.size(); ++i)
    if ((p.position[i] - Vec<2>(0.15, 0.85)).norm() < 1e-9) {
      found = true;
      EXPECT_EQ(p.kind[i], ParticleKind::Wall);
    }
  EXPECT_TRUE(found);
}

TEST(SceneGas, LaterRegionsWinBetweenWaterAndGas) {
  const CaseConfig c = parseCase(header2d("[0, 0]", "[1, 1]", 0.1) + region("w", "water", "[0, 0]", "[0.6, 0.6]") +
                                     region("g1", "gas", "[0.4, 0.4]", "[1, 1]", "velocity = [1, 0]\n") +
                                     region("g2", "gas", "[0.8, 0.8]", "[1, 1]", "velocity = [2, 0]\n") +
                                     region("w2", "water", "[0.6, 0.6]", "[0.8, 0.8]"),
                                 "t");
  EXPECT_EQ(regionParticleCounts(c), (std::vector<std::size_t>{36u - 4u, 36u - 4u - 4u, 4u, 4u}));
  const auto p = buildParticles<2>(c);
  EXPECT_EQ(p.size(), 32u + 28u + 4u + 4u);
  expectDistinctPositions(c, p);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& x = p.position[i];
    const bool in_w2 = x.x() > 0.6 && x.x() < 0.8 && x.y() > 0.6 && x.y() < 0.8;
    const bool in_g2 = x.x() > 0.8 && x.y() > 0.8;
    const bool in_g1 = !in_w2 && !in_g2 && x.x() > 0.4 && x.y() > 0.4;
    EXPECT_EQ(p.phase[i] == Phase::Gas, in_g1 || in_g2) << x.transpose();
    EXPECT_DOUBLE_EQ(p.velocity[i].x(), in_g2 ? 2.0 : in_g1 ? 1.0 : 0.0) << x.transpose();
    EXPECT_EQ(p.phase[i] == Phase::Liquid, i < 36u);  // water first: "w" (32 points) then "w2", then gas
  }
}

TEST(SceneGas, GasCircleInsideWater2D) {
  // Domain 5 x 5 m, l0 = 0.1: 50 x 50 lattice filled with water; a gas disc of R = 20 l0 declared after it.
  const double l0 = 0.1, r = 2.0;
  const std::string head = header2d("[0, 0]", "[5, 5]", l0) + region("tank", "water", "[0, 0]", "[5, 5]");
  for (const std::string centre : {"[2.55, 2.55]", "[2.5, 2.5]", "[2.525, 2.475]"}) {
    const CaseConfig c = parseCase(head + circle("bubble", "gas", centre, r, "velocity = [0, 0.5]\n"), "t");
    const double cx = c.regions[1].center[0], cy = c.regions[1].center[1];
    const auto p = buildParticles<2>(c);
    const std::size_t gas = countPhase(p, Phase::Gas);
    const double area_cells = std::numbers::pi * r * r / (l0 * l0);
    EXPECT_EQ(gas, pointsInDisc(c, cx, cy, r)) << centre;
    // Lattice-point count of a disc: error bounded by its perimeter in cells (Gauss circle problem).
    EXPECT_NEAR(static_cast<double>(gas), area_cells, 2.0 * std::numbers::pi * r / l0) << centre;
    if (centre == "[2.55, 2.55]") EXPECT_NEAR(static_cast<double>(gas), area_cells, 1.0);  // centred on a point
    EXPECT_EQ(p.size(), 2500u);
    EXPECT_EQ(countPhase(p, Phase::Liquid), 2500u - gas);
    expectDistinctPositions(c, p);  // the gas points are not water particles
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double d = std::hypot(p.position[i].x() - cx, p.position[i].y() - cy);
      EXPECT_EQ(p.phase[i] == Phase::Gas, d <= r + 1e-9) << p.position[i].transpose();
      EXPECT_EQ(p.phase[i] == Phase::Gas, i >= 2500u - gas);  // water first, then gas
      EXPECT_DOUBLE_EQ(p.velocity[i].y(), p.phase[i] == Phase::Gas ? 0.5 : 0.0);
    }
  }
}

TEST(SceneGas, GasSphereInsideWater3D) {
  // 20^3 lattice of water with a gas sphere of R = 6 l0 centred on a cell corner.
  const std::string text =
      "[case]\nname = \"s3\"\ndimension = 3\n[domain]\nmin = [0, 0, 0]\nmax = [2, 2, 2]\n"
      "[numerics]\nparticle_spacing = 0.1\n[output]\nend_time = 1\n"
      "[[region]]\nname = \"tank\"\nmin = [0, 0, 0]\nmax = [2, 2, 2]\n" +
      circle("bubble", "gas", "[1, 1, 1]", 0.6);
  const CaseConfig c = parseCase(text, "t");
  const auto p = buildParticles<3>(c);
  const std::size_t gas = countPhase(p, Phase::Gas);
  const double volume_cells = 4.0 / 3.0 * std::numbers::pi * 6.0 * 6.0 * 6.0;
  EXPECT_NEAR(static_cast<double>(gas), volume_cells, 0.05 * volume_cells);
  EXPECT_EQ(gas, countLatticePoints(c, c.regions[1]));
  EXPECT_EQ(p.size(), 8000u);
  EXPECT_EQ(countPhase(p, Phase::Liquid), 8000u - gas);
  expectDistinctPositions(c, p);
  for (std::size_t i = 0; i < p.size(); ++i)
    EXPECT_EQ(p.phase[i] == Phase::Gas, (p.position[i] - Vec<3>(1, 1, 1)).norm() <= 0.6 + 1e-9);
}

TEST(SceneGas, TankWithAirAboveWaterAndBubble) {
  // The documented example (docs/case-file.md): air fills the tank, water fills its lower part, a bubble
  // in the water; walls next to the air are Wall particles.
  const CaseConfig c = parseCase(header2d("[-0.04, -0.04]", "[0.44, 0.44]", 0.01) +
                                     region("air", "gas", "[0, 0]", "[0.4, 0.44]") +
                                     region("water", "water", "[0, 0]", "[0.4, 0.25]") +
                                     circle("bubble", "gas", "[0.2, 0.1]", 0.05) +
                                     region("floor", "wall", "[-0.04, -0.04]", "[0.44, 0]") +
                                     region("left", "wall", "[-0.04, -0.04]", "[0, 0.44]") +
                                     region("right", "wall", "[0.4, -0.04]", "[0.44, 0.44]"),
                                 "t");
  const auto counts = regionParticleCounts(c);
  EXPECT_EQ(counts[0], 40u * 19u);                                 // air above the water
  EXPECT_EQ(counts[1] + counts[2], 40u * 25u);                     // water and bubble share the lower part
  EXPECT_EQ(counts[2], countLatticePoints(c, c.regions[2]));       // the bubble keeps all its points
  const auto p = buildParticles<2>(c);
  EXPECT_EQ(countPhase(p, Phase::Gas), counts[0] + counts[2]);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& x = p.position[i];
    if (isFixed(p.kind[i]) && x.y() > 0.25 && (std::abs(x.x() + 0.005) < 1e-9 || std::abs(x.x() - 0.405) < 1e-9))
      EXPECT_EQ(p.kind[i], ParticleKind::Wall) << x.transpose();  // beside the air
  }
  expectDistinctPositions(c, p);
}

// Entrained gas below a bubble's resolution as points (mps/entrained_bubbles.hpp): the drag law's terminal rise
// against measured air bubbles in water, the points' slip through still water at that speed, their return to the
// air at the surface, the gas kept particle for particle, and the water's momentum from the points' reaction.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include "case/case_file.hpp"
#include "mps/entrained_bubbles.hpp"
#include "io/checkpoint.hpp"
#include "mps/reference_density.hpp"
#include "support/run_case.hpp"
#include "support/same_particles.hpp"
#include "support/pocket_tank.hpp"

using namespace mistfall;

namespace {

EntrainedBubbleModel airInWater(double diameter) {
  EntrainedBubbleModel m;
  m.diameter = diameter;
  return m;
}

using test_support::kPockets;

// The ten single gas particles of support/pocket_tank.hpp, moved as points of bubbles of `diameter`; `numerics`:
// more lines of [numerics] (the coupling).
std::string pointsCase(double diameter, const std::string& numerics = "") {
  return test_support::pocketTankCase("entrained_points",
                                      "entrained_bubble_diameter = " + std::to_string(diameter) + "\n" + numerics);
}

struct PointsRun : test_support::SolverRun<2> {
  explicit PointsRun(double diameter, const std::string& numerics = "")
      : SolverRun(pointsCase(diameter, numerics), "points.toml") {}
  std::size_t count(ParticleKind kind, Phase phase) const {
    const auto& p = state.particles;
    std::size_t c = 0;
    for (std::size_t i = 0; i < p.size(); ++i) c += p.kind[i] == kind && p.phase[i] == phase;
    return c;
  }
  std::size_t made = 0, released = 0;
  void stepTo(double t) {
    while (state.time < t - 1e-12) {
      const StepReport& r = solver->step(t);
      made += r.bubble_points_made;
      released += r.bubble_points_released;
    }
  }
};

}  // namespace

// Tomiyama et al.'s drag (slightly contaminated water) against air bubbles rising in tap water (Clift, Grace &
// Weber 1978, Fig. 7.3: about 0.23 m/s from 3 to 6 mm, 0.25 m/s at 1 cm); eq. (19) alone, a rigid sphere's drag,
// would give 0.44 m/s at 5 mm.
TEST(EntrainedBubbleDrag, TerminalRiseOfMillimetreBubbles) {
  struct Row {
    double diameter, measured;
  };
  for (const Row& row : {Row{0.003, 0.23}, Row{0.005, 0.23}, Row{0.010, 0.25}}) {
    const double u = airInWater(row.diameter).terminalSpeed();
    EXPECT_NEAR(u, row.measured, 0.1 * row.measured) << "d = " << row.diameter << " m";
    std::printf("terminal rise d = %.0f mm: %.4f m/s\n", 1e3 * row.diameter, u);
  }
  // The deformed-bubble branch in closed form: C_D = 8/3 Eo/(Eo + 4).
  const EntrainedBubbleModel m = airInWater(0.005);
  const double eo = m.eotvos(), cd = 8.0 / 3.0 * eo / (eo + 4.0);
  EXPECT_NEAR(m.terminalSpeed(), std::sqrt(4.0 / 3.0 * (1.0 - m.densityRatio()) * m.gravity * m.diameter / cd), 1e-9);
}

// Ten single gas particles in still water leave the lattice as points (the water keeps their volume: each stays as a
// water particle), slip up through the water at the drag law's terminal speed, and at the surface give their volume
// back (the nearest water particle becomes gas). Each phase keeps its particles: water particles less points, and gas
// particles plus points, are constant. The water's kinetic energy stays below the work the bubbles' buoyancy did on
// their way up, (rho_l - rho_g) |g| V times their rise, which is where its motion comes from. On both couplings: on
// the one equation a lone gas particle in the water otherwise carries its own pressure and momentum, at 1/830 of
// the water's density, and an unresolved one there rattled in its cage of water until the 5 mm waterfall diverged
// (docs/two-phase.md).
struct Coupling {
  const char* name;
  const char* numerics;
};

class EntrainedBubbleCoupling : public ::testing::TestWithParam<Coupling> {};

const Coupling kCouplings[] = {
    {"two_systems", ""},
    {"one_equation", "scheme = \"stabilised\"\ncoupling = \"one_equation\"\ncollision_distance = 0.8\n"},
};

INSTANTIATE_TEST_SUITE_P(EntrainedBubbles, EntrainedBubbleCoupling, ::testing::ValuesIn(kCouplings),
                         [](const auto& info) { return std::string(info.param.name); });

TEST_P(EntrainedBubbleCoupling, RiseThroughStillWaterAndRejoinTheAir) {
  const double d = 0.005, l0 = 0.005;
  PointsRun run(d, GetParam().numerics);
  const std::size_t gas0 = run.count(ParticleKind::Fluid, Phase::Gas);
  const std::size_t liquid0 = run.count(ParticleKind::Fluid, Phase::Liquid);
  const EntrainedBubbleModel model = airInWater(d);
  const double terminal = model.terminalSpeed();
  run.stepTo(0.001);
  ASSERT_EQ(run.count(ParticleKind::Point, Phase::Gas), static_cast<std::size_t>(kPockets));
  ASSERT_EQ(run.count(ParticleKind::Fluid, Phase::Liquid), liquid0 + kPockets);
  const auto& p = run.state.particles;
  // The slip: each point's vertical velocity less the water's around it (weights (1 - r/re)^2), from 0.05 s (after
  // the start, tau ~ 10 ms) to 0.12 s (before the first reach the surface).
  double slip = 0.0;
  int samples = 0;
  for (double t = 0.05; t <= 0.12 + 1e-9; t += 0.01) {
    run.stepTo(t);
    for (std::size_t b = 0; b < p.size(); ++b) {
      if (p.kind[b] != ParticleKind::Point) continue;
      double w = 0.0, uw = 0.0;
      for (std::size_t j = 0; j < p.size(); ++j) {
        if (p.kind[j] != ParticleKind::Fluid || p.phase[j] != Phase::Liquid) continue;
        const double r = (p.position[j] - p.position[b]).norm();
        if (r >= 2.1 * l0) continue;
        const double wj = (1.0 - r / (2.1 * l0)) * (1.0 - r / (2.1 * l0));
        w += wj, uw += wj * p.velocity[j][1];
      }
      slip += p.velocity[b][1] - uw / w;
      ++samples;
    }
  }
  ASSERT_EQ(samples, 8 * kPockets);
  slip /= samples;
  // Measured 0.2372 m/s, 2.4 % over the terminal 0.2316, with the point's last push added back to the water's
  // acceleration it reads (entrained_bubbles.hpp). Without that, 0.208 m/s (10 % under: the projection's answer to
  // the point's own force read as the water's acceleration); without the force returned, 0.2315.
  EXPECT_NEAR(slip, terminal, 0.05 * terminal) << "mean slip over 0.05-0.12 s";
  // The rise: the buoyancy's work on each point up to where it is released, then the water's kinetic energy.
  const double work_per_metre = (model.liquid_density - model.gas_density) * model.gravity * l0 * l0;
  double work = 0.0;
  while (run.state.time < 0.4 - 1e-12) {
    std::vector<std::pair<std::uint64_t, double>> height;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.kind[i] == ParticleKind::Point) height.emplace_back(p.id[i], p.position[i][1]);
    run.stepTo(run.state.time + 0.002);
    for (auto [id, y] : height)
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p.id[i] == id && p.kind[i] == ParticleKind::Point) work += work_per_metre * (p.position[i][1] - y);
  }
  EXPECT_EQ(run.count(ParticleKind::Point, Phase::Gas), 0u) << "points left in the water at 0.4 s";
  EXPECT_EQ(run.released, static_cast<std::size_t>(kPockets));
  EXPECT_EQ(run.count(ParticleKind::Fluid, Phase::Liquid), liquid0);
  EXPECT_EQ(run.count(ParticleKind::Fluid, Phase::Gas), gas0);
  double energy = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == ParticleKind::Fluid && p.phase[i] == Phase::Liquid)
      energy += 0.5 * model.liquid_density * l0 * l0 * p.velocity[i].squaredNorm();
  std::printf("slip %.4f m/s (terminal %.4f), buoyancy work %.4f J/m, water's kinetic energy at 0.4 s %.4f J/m\n", slip,
              terminal, work, energy);
  EXPECT_GT(work, 0.0);
  EXPECT_LT(energy, work);
}

// One step of a point in a patch of still water, the water's own acceleration nil: what the water gains is what eq.
// (18) takes from the point, so the water's momentum change plus the gas's own, rho_g V du_b, is the impulse of the
// buoyancy less the gas's weight, (rho_g - rho_l) V g dt, to round-off (the water particle's own weight, which the
// kept volume carries in the lattice, is the predict stage's).
TEST(EntrainedBubbles, TheWaterTakesTheForceThePointFeels) {
  const double l0 = 0.005, re = 2.1 * l0, dt = 5e-4;
  const EntrainedBubbleModel model = airInWater(0.005);
  const Vec<2> g(0.0, -model.gravity);
  Particles<2> p;
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j) p.add(Vec<2>(i * l0, j * l0), Vec<2>::Zero(), ParticleKind::Fluid, Phase::Liquid);
  p.add(Vec<2>(0.3 * l0, 0.2 * l0), Vec<2>(0.02, 0.05), ParticleKind::Point, Phase::Gas);
  const std::size_t b = p.size() - 1;
  const MpsConstants c = referenceConstants(2, l0, 2.1, 2.1);
  EntrainedBubbles<2> points(model, l0, re, c.n0, g);
  std::map<std::uint64_t, Vec<2>> forces;
  const std::vector<Vec<2>> start = p.velocity;
  const Vec<2> ub0 = p.velocity[b];
  const EntrainedBubbleCounts counts = points.advance(p, start, std::vector<char>(p.size(), 0), dt, forces);
  EXPECT_EQ(counts.released, 0u);
  Vec<2> water = Vec<2>::Zero();
  for (std::size_t j = 0; j < b; ++j) water += model.liquid_density * l0 * l0 * p.velocity[j];
  const Vec<2> total = water + model.gas_density * l0 * l0 * (p.velocity[b] - ub0);
  const Vec<2> expected = (model.gas_density - model.liquid_density) * l0 * l0 * g * dt;
  EXPECT_NEAR(total[0], expected[0], 1e-12);
  EXPECT_NEAR(total[1], expected[1], 1e-9 * std::abs(expected[1]));
  EXPECT_GT(p.velocity[b][1], ub0[1]);  // it starts to rise
}

// numerics.entrained_bubble_diameter: 0 (off) by default; not with entrained_gas_rise_speed, nor with the one
// equation; physics.surface_tension: water-air's by default, > 0.
TEST(EntrainedBubbles, CaseFileReadsTheKeys) {
  const auto config = [](const std::string& numerics, const std::string& physics = "") {
    std::string text = test_support::tankCase("keys", true, false, "", numerics);
    if (!physics.empty()) text.replace(text.find("[numerics]"), 0, "[physics]\n" + physics);
    return text;
  };
  const CaseConfig plain = parseCase(config(""), "keys.toml");
  EXPECT_EQ(plain.numerics.entrained_bubble_diameter, 0.0);
  EXPECT_EQ(plain.physics.surface_tension, 0.0728);
  const CaseConfig set = parseCase(config("entrained_bubble_diameter = 0.004\n", "surface_tension = 0.05\n"), "k.toml");
  EXPECT_EQ(set.numerics.entrained_bubble_diameter, 0.004);
  EXPECT_EQ(set.physics.surface_tension, 0.05);
  const auto error = [&](const std::string& numerics, const std::string& physics = "") {
    try {
      parseCase(config(numerics, physics), "keys.toml");
    } catch (const CaseError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error("entrained_bubble_diameter = 0.004\nentrained_gas_rise_speed = 0.2\n").find("allowed one of them"),
            std::string::npos);
  EXPECT_EQ(error("scheme = \"stabilised\"\ncoupling = \"one_equation\"\nentrained_bubble_diameter = 0.004\n"), "");
  EXPECT_NE(error("entrained_bubble_diameter = -0.004\n").find("numerics.entrained_bubble_diameter"), std::string::npos);
  EXPECT_NE(error("", "surface_tension = 0\n").find("physics.surface_tension"), std::string::npos);
}

// A run resumed from a checkpoint written while points rise (0.05 s) ends as the unbroken run does, bit for bit.
TEST(EntrainedBubbles, ResumeFromCheckpointIsBitIdentical) {
  PointsRun whole(0.005);
  whole.stepTo(0.05);
  whole.stepTo(0.1);
  PointsRun first(0.005);
  first.stepTo(0.05);
  ASSERT_EQ(first.count(ParticleKind::Point, Phase::Gas), static_cast<std::size_t>(kPockets));
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "mistfall_points_resume.ckpt";
  writeCheckpoint<2>(file, first.state);
  PointsRun second(0.005);
  second.state = readCheckpoint<2>(file);
  std::filesystem::remove(file);
  second.solver = std::make_unique<MpsSolver<2>>(second.config, second.state);
  second.stepTo(0.1);
  EXPECT_EQ(whole.state.step, second.state.step);
  test_support::expectSameParticles(whole.state.particles, second.state.particles);
}

// A point at a water surface is released: the water particle nearest to it becomes gas with the point's velocity,
// the rest of the water is untouched, and the point is listed for removal.
TEST(EntrainedBubbles, ReleaseAtTheSurfaceTurnsTheNearestWaterIntoGas) {
  const double l0 = 0.005, re = 2.1 * l0, dt = 5e-4;
  const EntrainedBubbleModel model = airInWater(0.005);
  Particles<2> p;
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 0; ++j)
      p.add(Vec<2>(i * l0, j * l0), Vec<2>(0.1 * std::sin(i + 2.0 * j), 0.05 * std::cos(3.0 * i - j)),
            ParticleKind::Fluid, Phase::Liquid);
  p.add(Vec<2>(0.2 * l0, 0.9 * l0), Vec<2>(0.01, 0.3), ParticleKind::Point, Phase::Gas);
  const std::size_t b = p.size() - 1;
  const std::vector<Vec<2>> before = p.velocity;
  const MpsConstants c = referenceConstants(2, l0, 2.1, 2.1);
  EntrainedBubbles<2> points(model, l0, re, c.n0, Vec<2>(0.0, -9.81));
  std::map<std::uint64_t, Vec<2>> forces;
  const EntrainedBubbleCounts counts = points.advance(p, p.velocity, std::vector<char>(p.size(), 0), dt, forces);
  ASSERT_EQ(counts.released, 1u);
  ASSERT_EQ(counts.released_ids.size(), 1u);
  EXPECT_EQ(counts.released_ids[0], p.id[b]);
  std::size_t gas = 0;
  for (std::size_t j = 0; j < b; ++j) {
    if (p.phase[j] == Phase::Gas) {
      ++gas;
      EXPECT_EQ(p.velocity[j], Vec<2>(0.01, 0.3));
      EXPECT_NEAR((p.position[j] - Vec<2>(0.0, 0.0)).norm(), 0.0, 1e-12);  // the top row's particle under it
    } else {
      EXPECT_EQ(p.velocity[j], before[j]) << "water particle " << j;
    }
  }
  EXPECT_EQ(gas, 1u);
}

// On the one equation only gas regions below a bubble's resolution (fewer than bubble_min_particles) become points;
// the rest keep their particles in the lattice. With bubble_min_particles = 1 every region counts as resolved, so
// none of the pocket tank's ten single gas particles may leave (with the default 6 all ten do, above).
TEST(EntrainedBubbles, OneEquationMovesOnlyGasBelowABubblesResolution) {
  PointsRun run(0.005, "scheme = \"stabilised\"\ncoupling = \"one_equation\"\ncollision_distance = 0.8\n"
                       "bubble_min_particles = 1\n");
  run.stepTo(0.005);
  EXPECT_EQ(run.made, 0u);
  EXPECT_EQ(run.count(ParticleKind::Point, Phase::Gas), 0u);
}

// Points inside an air pocket wider than re (under a plunging jet) give their volume back at the pocket's edge: each
// turns the water particle nearest to it into gas, however far, so three points that drifted within 0.1 mm of each
// other make three gas particles a lattice spacing apart. Searching only the cells within re, all three became gas
// particles at their own places (`unpaired`), 0.1 mm apart: on cases/waterfall.toml such a cluster blew the
// pocket's gas up to 770 m/s the next step.
TEST(EntrainedBubbles, PointsInAnAirPocketGiveTheirVolumeBackAtItsEdge) {
  const double l0 = 0.005, re = 2.1 * l0, dt = 5e-4, hole = 7.0 * l0;
  const EntrainedBubbleModel model = airInWater(0.005);
  Particles<2> p;
  for (int i = -12; i <= 12; ++i)
    for (int j = -12; j <= 12; ++j) {
      const Vec<2> x(i * l0, j * l0);
      p.add(x, Vec<2>::Zero(), ParticleKind::Fluid, x.norm() < hole ? Phase::Gas : Phase::Liquid);
    }
  const std::size_t first = p.size();
  for (int k = 0; k < 3; ++k)
    p.add(Vec<2>(1.2 * l0 + 1e-4 * k, -0.7 * l0), Vec<2>(0.0, 0.2), ParticleKind::Point, Phase::Gas);
  const MpsConstants c = referenceConstants(2, l0, 2.1, 2.1);
  EntrainedBubbles<2> points(model, l0, re, c.n0, Vec<2>(0.0, -9.81));
  std::map<std::uint64_t, Vec<2>> forces;
  const std::vector<Phase> phase_before = p.phase;
  const EntrainedBubbleCounts counts = points.advance(p, p.velocity, std::vector<char>(p.size(), 0), dt, forces);
  EXPECT_EQ(counts.released, 3u);
  EXPECT_EQ(counts.unpaired, 0u);
  EXPECT_EQ(counts.released_ids.size(), 3u);
  std::vector<Vec<2>> made;
  for (std::size_t j = 0; j < first; ++j)
    if (phase_before[j] == Phase::Liquid && p.phase[j] == Phase::Gas) made.push_back(p.position[j]);
  ASSERT_EQ(made.size(), 3u);
  for (std::size_t a = 0; a < made.size(); ++a) {
    EXPECT_GE(made[a].norm(), hole) << "gas " << a << " is not at the pocket's edge";
    EXPECT_LT(made[a].norm(), hole + 1.5 * l0);
    for (std::size_t b = a + 1; b < made.size(); ++b) EXPECT_GE((made[a] - made[b]).norm(), l0 - 1e-12);
  }
  for (std::size_t k = first; k < p.size(); ++k) EXPECT_EQ(p.kind[k], ParticleKind::Point);  // removed by the solver
}

// Points that meet coalesce (entrained_bubbles.hpp): twenty points at one place deep in still water (the stack that
// blew up cases/waterfall.toml at 5.388 s) keep one point; the other nineteen give their gas back to the lattice, each
// to its own water particle, the nearest first, so the gas is a cluster the lattice resolves. A point 2 l0 away is
// left alone, and a gas particle within l0/2 of the kept point stays in the lattice, while one away from every
// point leaves it.
TEST(EntrainedBubbles, PointsThatMeetCoalesceIntoTheLattice) {
  const double l0 = 0.005, re = 2.1 * l0, dt = 5e-4;
  const EntrainedBubbleModel model = airInWater(0.005);
  Particles<2> p;
  for (int i = -10; i <= 10; ++i)
    for (int j = -10; j <= 10; ++j) p.add(Vec<2>(i * l0, j * l0), Vec<2>::Zero(), ParticleKind::Fluid, Phase::Liquid);
  const std::size_t near_gas = 10 * 21 + 10, far_gas = 3 * 21 + 3;  // (0, 0) and (-7 l0, -7 l0)
  p.phase[near_gas] = p.phase[far_gas] = Phase::Gas;
  std::vector<char> candidate(p.size(), 0);
  candidate[near_gas] = candidate[far_gas] = 1;
  const std::size_t first = p.size();
  const Vec<2> stack(0.3 * l0, 0.2 * l0), apart(0.3 * l0 + 2.0 * l0, 0.2 * l0);
  for (int k = 0; k < 20; ++k) p.add(stack, Vec<2>(0.0, 0.1), ParticleKind::Point, Phase::Gas);
  p.add(apart, Vec<2>(0.0, 0.1), ParticleKind::Point, Phase::Gas);
  candidate.resize(p.size(), 0);
  const std::vector<Phase> phase_before = p.phase;
  const MpsConstants c = referenceConstants(2, l0, 2.1, 2.1);
  EntrainedBubbles<2> points(model, l0, re, c.n0, Vec<2>(0.0, -9.81));
  std::map<std::uint64_t, Vec<2>> forces;
  const EntrainedBubbleCounts counts = points.advance(p, p.velocity, candidate, dt, forces);
  EXPECT_EQ(counts.coalesced, 19u);
  EXPECT_EQ(counts.released, 0u);  // none reached the surface
  EXPECT_EQ(counts.unpaired, 0u);
  ASSERT_EQ(counts.released_ids.size(), 19u);
  for (std::size_t k = 0; k < counts.released_ids.size(); ++k)
    EXPECT_EQ(counts.released_ids[k], p.id[first + 1 + k]) << "the first point of the stack is the one kept";
  std::vector<double> made;  // distances of the water turned into gas from the stack
  for (std::size_t j = 0; j < first; ++j)
    if (phase_before[j] == Phase::Liquid && p.phase[j] == Phase::Gas) made.push_back((p.position[j] - stack).norm());
  ASSERT_EQ(made.size(), 19u);
  for (double r : made) EXPECT_LT(r, 3.0 * l0) << "gas given back far from the stack";
  // the nearest water first: nothing left as water is nearer to the stack than the farthest gas made
  const double farthest = *std::max_element(made.begin(), made.end());
  for (std::size_t j = 0; j < first; ++j)
    if (p.phase[j] == Phase::Liquid) EXPECT_GE((p.position[j] - stack).norm(), farthest - 1e-12);
  EXPECT_EQ(counts.made, 1u);  // the far gas particle left the lattice, the one next to the kept point did not
  EXPECT_EQ(p.phase[near_gas], Phase::Gas);
  EXPECT_EQ(p.phase[far_gas], Phase::Liquid);
  EXPECT_EQ(p.kind.back(), ParticleKind::Point);
  EXPECT_EQ(p.position.back(), p.position[far_gas]);
}

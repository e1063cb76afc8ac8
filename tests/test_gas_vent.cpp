// Gas vents (src/mps/gas_vent.hpp): a vent's columns move with the air in front of them, gas leaves past the outer
// face and enters there one lattice layer at a time, air entering from the domain joins its column's line; air
// flowing through a duct between two vents slows by the dynamic pressure of the air it draws in (Bernoulli) and every
// gas particle is accounted for; water filling a tank pushes its air out of a vent at the ambient pressure, where the
// sealed tank's air is compressed; the case-file checks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "case/case_file.hpp"
#include "io/checkpoint.hpp"
#include "case/scene.hpp"
#include "mps/gas_vent.hpp"
#include "mps/solver.hpp"
#include "support/air_column.hpp"
#include "support/same_particles.hpp"
#include "support/case_text.hpp"
#include "support/scratch.hpp"

using namespace mistfall;
using test_support::errorOf;

namespace {

// A vertical duct of air 10 cm wide and 30 cm high between side walls, l0 = 1 cm, with a vent across its bottom
// (outward -y) and one across its top (outward +y); the air starts at `speed` upward. A puddle in a cup beside it
// (the case needs water) takes no part. `numerics`: keys added to [numerics].
std::string ductCase(double speed, const std::string& numerics = "") {
  return test_support::airColumnCase(numerics, speed, test_support::ductVents());
}

// A lid from x = 0 to `end` over y 0.3-0.34, cut by a vent (outward +y) between `vent_from` and `vent_to`.
std::string ventedLid(const std::string& vent_from, const std::string& vent_to, const std::string& end) {
  return R"(
[[region]]
name = "lid_left"
material = "wall"
min = [0.0, 0.3]
max = [)" + vent_from + R"(, 0.34]
[[region]]
name = "lid_right"
material = "wall"
min = [)" + vent_to + R"(, 0.3]
max = [)" + end + R"(, 0.34]
[[vent]]
name = "top"
min = [)" + vent_from + R"(, 0.3]
max = [)" + vent_to + R"(, 0.34]
direction = [0, 1]
)";
}

// A tank 30 x 30 cm, l0 = 1 cm: 10 cm of water under air, fed by an inflow buffer at its foot (q = 0.005 m^2/s,
// U = 0.1 m/s; `discharge` 0: none); the lid either sealed or with a vent in its middle third. The two-systems
// coupling with the waterfall's gas keys, or the one equation.
std::string tankCase(bool vented, bool one_equation = false, double discharge = 0.005) {
  const std::string numerics = one_equation ? R"(scheme = "stabilised"
coupling = "one_equation"
collision_distance = 0.8
)"
                                            : R"(gas_correction_limit = 0.2
surface_neighbour_fraction = 0.85
entrained_gas_rise_speed = 0.23
dispersed_gas_fraction = 0.5
dispersed_gas_touch = 1.5
)";
  std::string lid = vented ? ventedLid("0.1", "0.2", "0.3")
                           : R"(
[[region]]
name = "lid"
material = "wall"
min = [0.0, 0.3]
max = [0.3, 0.34]
)";
  return R"(
[case]
name = "tank"
dimension = 2
[domain]
min = [-0.04, -0.04]
max = [0.34, 0.34]
[physics.gas]
sound_speed = 340.0
[numerics]
particle_spacing = 0.01
dt_max = 5e-4
pressure_source = "mixed"
source_relaxation = 0.01
gas_domain = "closed"
)" + numerics + R"(
[output]
end_time = 1.0
[[region]]
name = "air"
material = "gas"
min = [0.0, 0.0]
max = [0.3, 0.3]
[[region]]
name = "water"
material = "water"
min = [0.0, 0.0]
max = [0.3, 0.1]
[[region]]
name = "floor"
material = "wall"
min = [-0.04, -0.04]
max = [0.34, 0.0]
[[region]]
name = "left"
material = "wall"
min = [-0.04, 0.0]
max = [0.0, 0.34]
[[region]]
name = "right"
material = "wall"
min = [0.3, 0.0]
max = [0.34, 0.34]
)" + (discharge > 0.0 ? R"([[inflow]]
name = "feed"
min = [0.0, 0.0]
max = [0.04, 0.05]
direction = [1, 0]
discharge = )" + std::to_string(discharge) + "\n"
                                     : std::string()) +
         lid;
}

struct VentRun {
  CaseConfig config;
  SimulationState<2> state;
  std::unique_ptr<MpsSolver<2>> solver;
  explicit VentRun(const std::string& text) : config(parseCase(text, "vent.toml")) {
    state.particles = buildParticles<2>(config);
    solver = std::make_unique<MpsSolver<2>>(config, state);
  }
  void advanceTo(double t) {
    while (state.time < t - 1e-12) solver->step(t);
  }
  std::int64_t gas() const { return static_cast<std::int64_t>(state.particles.count(ParticleKind::Fluid, Phase::Gas)); }
  // The mean over the gas outside the vents of its pressure above the ambient rho_g g.x [Pa].
  double meanGasPressureAboveAmbient() const {
    const auto& p = state.particles;
    const std::vector<int> vent = ventOf<2>(p, config);
    const Vec<2> g(0.0, -9.81);
    double sum = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.kind[i] == ParticleKind::Fluid && p.phase[i] == Phase::Gas && vent[i] < 0 && p.position[i][1] < 0.3)
        sum += p.pressure[i] - ambientPressure<2>(p.position[i], 1.2, g), ++n;
    return sum / n;
  }
};

// The particles of the duct case at set-up, and the vents' record of them (no motion yet).
struct Exchange {
  CaseConfig config = parseCase(ductCase(0.0), "duct.toml");
  Particles<2> p = buildParticles<2>(config);
  std::vector<int> vent = ventOf<2>(p, config);
  std::vector<Vec<2>> start = p.position;
};

// The air in front of the top vent's first column (x = 0.005) moving out at 0.3 m/s, and two air particles of the
// domain (at (0.045, 0.255) and (0.055, 0.255)) for a test to place: their indices (the particle count if missing).
std::pair<std::size_t, std::size_t> columnOutAndTwoAirParticles(Exchange& e) {
  std::size_t a = e.p.size(), b = e.p.size();
  for (std::size_t i = 0; i < e.p.size(); ++i) {
    if (e.vent[i] >= 0 || e.p.phase[i] != Phase::Gas) continue;
    if (std::abs(e.p.position[i][0] - 0.005) < 1e-9 && e.p.position[i][1] > 0.28)
      e.p.velocity[i] = Vec<2>(0.0, 0.3);
    if ((e.p.position[i] - Vec<2>(0.045, 0.255)).norm() < 1e-9) a = i;
    if ((e.p.position[i] - Vec<2>(0.055, 0.255)).norm() < 1e-9) b = i;
  }
  return {a, b};
}

}  // namespace

TEST(GasVent, SetUpFillsTheVentBoxesWithGasAtRest) {
  Exchange e;
  int in_vents = 0;
  for (std::size_t i = 0; i < e.p.size(); ++i)
    if (e.vent[i] >= 0) {
      ++in_vents;
      EXPECT_EQ(Phase::Gas, e.p.phase[i]);
      EXPECT_EQ(0.0, e.p.velocity[i].norm());
    }
  EXPECT_EQ(2 * 10 * 4, in_vents);  // two boxes of 10 columns, 4 layers deep
}

TEST(GasVent, ColumnsFollowTheAirInFrontAndTheOuterFaceCreatesALayerWhenOneFits) {
  Exchange e;
  // The air in front of the top vent's first column (x = 0.005) moves down at 0.3 m/s, at an angle.
  for (std::size_t i = 0; i < e.p.size(); ++i)
    if (e.vent[i] < 0 && e.p.phase[i] == Phase::Gas && std::abs(e.p.position[i][0] - 0.005) < 1e-9 &&
        e.p.position[i][1] > 0.28)
      e.p.velocity[i] = Vec<2>(0.1, -0.3);
  const std::size_t before = e.p.size();
  // 0.02 s: the column moves 6 mm inward (its layers at y = 0.299 .. 0.329), so a layer fits at y = 0.339.
  const VentExchange x = exchangeVentGas<2>(e.p, e.config, e.vent, e.start, 0.02, 1.2, Vec<2>(0.0, -9.81));
  EXPECT_EQ(1, x.gas_in);
  EXPECT_EQ(0, x.gas_out);
  ASSERT_EQ(before + 1, e.p.size());
  EXPECT_NEAR(0.005, e.p.position.back()[0], 1e-12);
  EXPECT_NEAR(0.339, e.p.position.back()[1], 1e-12);
  EXPECT_NEAR(-0.3, e.p.velocity.back()[1], 1e-12);  // the column's normal velocity; none across it
  EXPECT_EQ(0.0, e.p.velocity.back()[0]);
  EXPECT_NEAR(1.2 * -9.81 * 0.339, e.p.pressure.back(), 1e-12);  // the ambient pressure there
  int moved = 0, still = 0;
  for (std::size_t i = 0; i < before; ++i) {
    if (e.vent[i] != 1) continue;
    const bool first = std::abs(e.p.position[i][0] - 0.005) < 1e-9;
    const double shift = e.p.position[i][1] - e.start[i][1];
    (first ? moved : still) += 1;
    EXPECT_NEAR(first ? -0.006 : 0.0, shift, 1e-12);
  }
  EXPECT_EQ(4, moved);
  EXPECT_EQ(36, still);
}

// Air entering a vent joins its column on the column's line across the vent, where it would not lie within l0/2 of
// the column's gas: in 0.02 s the top vent's first column (x = 0.005) moves 6 mm out with the air in front of it
// (its layers at y = 0.311 .. 0.341; the last passes the outer face and leaves). Air that entered the box in the step
// at (0.0083, 0.3035) is put on the column's line, x = 0.005, at the same height and the column's velocity; air that
// entered beside it at (0.0021, 0.3012), 0.23 l0 below it once on the line, leaves through the vent (counted).
TEST(GasVent, AirEnteringAVentJoinsItsColumnsLineOrLeavesWhereItWouldCrowdIt) {
  Exchange e;
  const auto [a, b] = columnOutAndTwoAirParticles(e);
  ASSERT_LT(a, e.p.size());
  ASSERT_LT(b, e.p.size());
  e.p.position[a] = Vec<2>(0.0083, 0.3035);
  e.p.velocity[a] = Vec<2>(0.2, 0.4);
  e.p.position[b] = Vec<2>(0.0021, 0.3012);
  const std::uint64_t id_a = e.p.id[a], id_b = e.p.id[b];
  const std::size_t before = e.p.size();
  const VentExchange x = exchangeVentGas<2>(e.p, e.config, e.vent, e.start, 0.02, 1.2, Vec<2>(0.0, -9.81));
  EXPECT_EQ(2, x.gas_out);
  EXPECT_EQ(1, x.gas_crowded_out);
  EXPECT_EQ(2, x.gas_out_by_vent[1]);  // both by the top vent (the case's second)
  EXPECT_EQ(0, x.gas_out_by_vent[0]);
  EXPECT_EQ(before - 2 + static_cast<std::size_t>(x.gas_in), e.p.size());
  int found_a = 0, found_b = 0;
  for (std::size_t i = 0; i < e.p.size(); ++i) {
    found_b += e.p.id[i] == id_b;
    if (e.p.id[i] != id_a) continue;
    ++found_a;
    EXPECT_NEAR(0.005, e.p.position[i][0], 1e-12);
    EXPECT_NEAR(0.3035, e.p.position[i][1], 1e-12);
    EXPECT_EQ(0.0, e.p.velocity[i][0]);
    EXPECT_NEAR(0.3, e.p.velocity[i][1], 1e-12);
  }
  EXPECT_EQ(1, found_a);
  EXPECT_EQ(0, found_b);
}

// numerics.vent_crowding_at_mouth: as above, the top vent's first column (x = 0.005) moves out at 0.3 m/s, and air
// at (0.0083, 0.3015) enters the box (inner face y = 0.30). Air of the domain sits just out of the box in that
// column, at (0.0052, 0.2990), 0.25 l0 below where the entering air lands on the column's line. Without the key the
// entering air joins the column there (the pair of the 5 mm waterfall's roof vent, docs/waterfall.md); with it, it
// leaves crowded.
TEST(GasVent, AirEnteringAVentNextToAirJustOutOfItsMouthLeavesWithTheKey) {
  for (const bool key : {false, true}) {
    SCOPED_TRACE(key ? "vent_crowding_at_mouth = true" : "without the key");
    Exchange e;
    if (key) e.config.numerics.vent_crowding_at_mouth = true;
    const auto [a, b] = columnOutAndTwoAirParticles(e);
    ASSERT_LT(a, e.p.size());
    ASSERT_LT(b, e.p.size());
    e.p.position[a] = Vec<2>(0.0083, 0.3015);  // entering
    e.p.position[b] = Vec<2>(0.0052, 0.2990);  // just out of the mouth
    e.p.velocity[b] = Vec<2>(0.0, 0.3);
    const std::uint64_t id_a = e.p.id[a];
    const VentExchange x = exchangeVentGas<2>(e.p, e.config, e.vent, e.start, 0.02, 1.2, Vec<2>(0.0, -9.81));
    EXPECT_EQ(key ? 1 : 0, x.gas_crowded_out);
    int found = 0;
    for (std::size_t i = 0; i < e.p.size(); ++i) {
      if (e.p.id[i] != id_a) continue;
      ++found;
      EXPECT_NEAR(0.005, e.p.position[i][0], 1e-12);  // on the column's line, 0.25 l0 from the air below it
      EXPECT_NEAR(0.3015, e.p.position[i][1], 1e-12);
    }
    EXPECT_EQ(key ? 0 : 1, found);
  }
}

TEST(GasVent, GasPastTheOuterFaceLeaves) {
  Exchange e;
  // The air below the bottom vent's columns at x = 0.005 and 0.015 moves down at 0.4 m/s: in 0.02 s those two
  // columns move 8 mm outward and their outermost layers (y = -0.035) pass the outer face y = -0.04.
  for (std::size_t i = 0; i < e.p.size(); ++i)
    if (e.vent[i] < 0 && e.p.phase[i] == Phase::Gas && e.p.position[i][0] < 0.02 && e.p.position[i][1] < 0.02)
      e.p.velocity[i] = Vec<2>(0.0, -0.4);
  const std::size_t before = e.p.size();
  const VentExchange x = exchangeVentGas<2>(e.p, e.config, e.vent, e.start, 0.02, 1.2, Vec<2>(0.0, -9.81));
  EXPECT_EQ(2, x.gas_out);
  EXPECT_EQ(0, x.gas_in);
  EXPECT_EQ(0, x.liquid_out);
  EXPECT_EQ(before - 2, e.p.size());
}

// A vent's gas is moved by its column at the end of the step (exchangeVentGas), so neither the gas correction nor
// the particle shifting moves it and no guard counts it: on waterfall_small a quarter of gas_correction_limit's
// firings over 0-3 s were crowded vent gas whose cut correction the vent then replaced, and on the one equation 675 of
// shift_limit's 689 cuts over its first 0.4 s were vent gas (docs/two-phase.md). Both couplings, one row each.
// After a first step, pushes the vent gas at (x_a, y) and (x_b, y) to 0.02 l0 apart, moving at 0.2 m/s along y, and
// takes one more step of at most 1 s; the air's start-up
// drift moves the vent's columns by less than `drift` [m] in that step.
void crowdVentGasAndStep(const std::string& text, double y, double x_a, double x_b, double drift) {
  VentRun r(text);
  auto& p = r.state.particles;
  r.solver->step(1.0);  // a first step: the surface normals the shifting needs come from the last pressure
  std::size_t a = p.size(), b = p.size();
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != ParticleKind::Fluid || std::abs(p.position[i][1] - y) > 1e-4) continue;
    if (std::abs(p.position[i][0] - x_a) < 1e-9) a = i;
    if (std::abs(p.position[i][0] - x_b) < 1e-9) b = i;
  }
  ASSERT_LT(a, p.size());
  ASSERT_LT(b, p.size());
  const Vec<2> along = p.position[b] - p.position[a];
  p.position[b] = p.position[a] + 0.02 * along;
  p.velocity[a] = p.velocity[b] = Vec<2>(0.0, 0.2);  // the shifting scales with the speed (particle_shifting.hpp)
  const Vec<2> start_b = p.position[b];
  const std::uint64_t id_b = p.id[b];
  const StepReport report = r.solver->step(1.0);
  EXPECT_EQ(0u, report.gas_correction_cuts);
  EXPECT_EQ(0u, report.shift_cuts);
  // The column moves only along the vent's axis (y), with the still air in front of it: the crowded particle keeps
  // its place across the vent, and moves along it by no more than the air's start-up drift allows.
  int found = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.id[i] == id_b) {
      ++found;
      EXPECT_EQ(start_b[0], p.position[i][0]);
      EXPECT_NEAR(start_b[1], p.position[i][1], drift);
    }
  EXPECT_EQ(1, found);
}

// A vent's gas is moved by its column at the end of the step (exchangeVentGas), so neither the gas correction nor
// the particle shifting moves it and no guard counts it: on waterfall_small a quarter of gas_correction_limit's
// firings over 0-3 s were crowded vent gas whose cut correction the vent then replaced, and on the one equation 675 of
// shift_limit's 689 cuts over its first 0.4 s were vent gas (docs/two-phase.md). The two-systems row crowds the duct's
// bottom vent's outermost layer (more than re from the duct's air), the one equation's the tank's lid vent's.
TEST(GasVent, CrowdedVentGasIsMovedByItsColumnAndNoGuardCountsIt) {
  {
    SCOPED_TRACE("two systems");
    crowdVentGasAndStep(ductCase(0.0, "gas_correction_limit = 0.2\n"), -0.035, 0.045, 0.055, 1e-5);
  }
  {
    SCOPED_TRACE("one equation");
    std::string text = tankCase(true, true, 0.0);
    text.replace(text.find("collision_distance = 0.8"), 24, "collision_distance = 0.8\nshift_limit = 0.2");
    crowdVentGasAndStep(text, 0.335, 0.145, 0.155, 1e-5);
  }
}

// A vent prescribes its gas's place across the vent and its velocity (gas_vent.hpp), so air that meets a vent's gas
// in the collision model takes the whole reversal, as at a wall (solver_collisions.cpp). Traced on the 5 mm waterfall
// (docs/waterfall.md, thirty-fourth session): with the reversal shared by mass, the vent reset its particle's half at
// the end of every step, the air beside it kept approaching (0.42, 0.29, 0.27 l0) and the gas rows threw it out at
// 100 m/s. Here: the duct's air particle under the top vent's middle column, moved to 0.65 l0 below the column's first
// layer and sent up at 1 m/s; with no restitution its approach is gone after the collision (shared: +0.5 m/s left).
TEST(GasVent, AirMeetingAVentsGasTakesTheWholeReversal) {
  VentRun run(ductCase(0.0, "collision_distance = 0.8\ncollision_restitution = 0.0\n"));
  auto& p = run.state.particles;
  auto at = [&](double x, double y) {
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.kind[i] == ParticleKind::Fluid && (p.position[i] - Vec<2>(x, y)).norm() < 1e-9) return i;
    return p.size();
  };
  const std::size_t below = at(0.045, 0.295), first_layer = at(0.045, 0.305);
  ASSERT_LT(below, p.size());
  ASSERT_LT(first_layer, p.size());
  p.position[below][1] = 0.2985;
  p.velocity[below] = Vec<2>(0.0, 1.0);
  const auto path = test_support::freshDir("vent_collision") / "trace.csv";
  run.solver->traceParticle(p.id[below], 0.0, path.string());
  run.solver->step(1.0);
  const double uy = test_support::traceValue(path, "collision", "self", 12);  // column 12: uy
  ASSERT_TRUE(std::isfinite(uy)) << "no collision row for the particle in " << path;
  EXPECT_LT(uy, 0.01);    // the vent's gas at rest but for one step of gravity: nothing left of the approach
  EXPECT_GT(uy, -0.01);   // and no restitution
}

// The same duct with its top closed by a lid but for a vent over its middle 4 cm: the air turns round the lid's
// edges into the vent.
std::string nozzleCase(const std::string& numerics) {
  return test_support::airColumnCase(numerics, 0.2, R"(
[[vent]]
name = "bottom"
min = [0.0, -0.04]
max = [0.1, 0.0]
direction = [0, -1]
)" + ventedLid("0.03", "0.07", "0.1"));
}

// Air started at u0 = 0.2 m/s up a duct between two openings to the still ambient, with nothing to drive it. The air
// entering at the bottom is drawn from rest (the vent's total-pressure inflow: p = p_a - rho u^2/2) and the air
// leaving at the top keeps its speed (static p_a: the exit loss), so the duct's air, L = 0.31 m between the vents'
// first layers, decelerates as du/dt = -u^2/(2L): u(t) = u0 / (1 + u0 t / (2L)), 0.182 m/s at 0.3 s. With the static
// ambient on entry too (`inflow = "static"`, the first version) nothing slows it and it keeps 0.2 m/s. Measured
// 0.177 and 0.193 m/s. The stabilised gas operators: the paper's let still air drift (0.047 m/s in 0.3 s,
// test_gas_operators.cpp), and with them the duct's air reached 0.228 m/s by 0.3 s.
TEST(GasVent, AirFlowingThroughADuctBetweenTwoVentsSlowsByItsEntryAndIsAccountedFor) {
  struct Row {
    const char* inflow;
    double expected;  // mean speed at 0.3 s [m/s]
  };
  const double u0 = 0.2, length = 0.31, t = 0.3;
  for (const Row& row : {Row{"total_pressure", u0 / (1.0 + u0 * t / (2.0 * length))}, Row{"static", u0}}) {
    SCOPED_TRACE(row.inflow);
    std::string text = ductCase(u0, "gas_operators = \"stabilised\"\n");
    for (std::size_t at = text.find("direction = [0, "); at != std::string::npos;
         at = text.find("direction = [0, ", at + 1))
      text.insert(text.find('\n', at) + 1, std::string("inflow = \"") + row.inflow + "\"\n");
    VentRun r(text);
    const std::int64_t gas0 = r.gas();
    r.advanceTo(t);
    // In through the bottom and out through the top at u w / l0^2 = 0.2 * 0.1 / 1e-4 = 200 particles a second.
    EXPECT_NEAR(60.0, static_cast<double>(r.state.vented_in), 6.0);
    EXPECT_NEAR(60.0, static_cast<double>(r.state.vented_out), 6.0);
    EXPECT_EQ(gas0, r.gas() - r.state.vented_in + r.state.vented_out);  // every gas particle accounted for
    EXPECT_NEAR(static_cast<double>(gas0), static_cast<double>(r.gas()), 0.02 * static_cast<double>(gas0));
    const auto& p = r.state.particles;
    double sum = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.kind[i] == ParticleKind::Fluid && p.phase[i] == Phase::Gas && p.position[i][0] < 0.1 &&
          p.position[i][1] > 0.02 && p.position[i][1] < 0.28)
        sum += p.velocity[i][1], ++n;
    EXPECT_NEAR(row.expected, sum / n, 0.008);
    std::printf("duct air at %.1f s, inflow = \"%s\": %.4f m/s (expected %.4f)\n", t, row.inflow, sum / n, row.expected);
    EXPECT_EQ(0u, p.count(ParticleKind::Escaped));
  }
}

// numerics.vent_outlet = "zero_gradient": a vent's gas holds the ambient pressure and takes no part in the
// divergence of the gas in front of it (its velocity is that gas's own, extrapolated with zero normal gradient).
// With the columns' velocities in that divergence ("buffer"), each column feeds on the air it draws: at the edges
// of a vent narrower than its duct the air's mean speed rises to 0.3-0.65 m/s within 0.5 s (a 0.2 m/s flow), and
// the fed tank of docs/two-phase.md came apart at its vent's edges.
TEST(GasVent, AirTurningIntoAVentNarrowerThanItsDuctStaysCalm) {
  VentRun r(nozzleCase("gas_operators = \"stabilised\"\nvent_outlet = \"zero_gradient\"\n"));
  double sum = 0.0;
  int frames = 0;
  for (int k = 1; k <= 10; ++k) {
    r.advanceTo(0.05 * k);
    const auto& p = r.state.particles;
    double speed = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.kind[i] == ParticleKind::Fluid && p.phase[i] == Phase::Gas && p.position[i][0] < 0.1)
        speed += p.velocity[i].norm(), ++n;
    sum += speed / n, ++frames;
  }
  EXPECT_LT(sum / frames, 0.2);  // measured 0.09 (0.55 with "buffer")
  EXPECT_EQ(0u, r.state.particles.count(ParticleKind::Escaped));
}

TEST(GasVent, WaterFillingATankPushesItsAirOutOfTheVentAtTheAmbientPressure) {
  VentRun sealed(tankCase(false));
  VentRun vented(tankCase(true));
  const std::int64_t gas0 = vented.gas();
  sealed.advanceTo(0.2);
  vented.advanceTo(0.2);
  // Both took in the same water: 10 particles, 0.001 m^2.
  EXPECT_EQ(10, vented.state.created);
  EXPECT_EQ(10, sealed.state.created);
  // The sealed air is compressed; the vented air stays at the ambient pressure.
  EXPECT_GT(sealed.meanGasPressureAboveAmbient(), 15.0);
  EXPECT_LT(std::abs(vented.meanGasPressureAboveAmbient()), 5.0);  // measured -1.4 Pa; sealed 47 Pa
  // The air went out of the vent, and every gas particle is accounted for.
  EXPECT_GT(vented.state.vented_out - vented.state.vented_in, 5);
  EXPECT_EQ(gas0, vented.gas() - vented.state.vented_in + vented.state.vented_out);
  EXPECT_EQ(0u, vented.state.particles.count(ParticleKind::Escaped));
}

// The one equation (numerics.coupling = "one_equation"): its closed air's pressure rises faster than the air's
// stiffness gives (docs/two-phase.md); under a vented lid the air stays at the ambient pressure, the air pushed out
// is about the water taken in, and still water under a vented lid stays at rest.
TEST(GasVent, TheOneEquationsAirUnderAVentedLidStaysAtTheAmbientPressure) {
  VentRun sealed(tankCase(false, true));
  VentRun vented(tankCase(true, true));
  const std::int64_t gas0 = vented.gas();
  sealed.advanceTo(0.2);
  vented.advanceTo(0.2);
  EXPECT_EQ(10, vented.state.created);
  EXPECT_GT(sealed.meanGasPressureAboveAmbient(), 1000.0);  // measured 3.1 kPa
  EXPECT_LT(std::abs(vented.meanGasPressureAboveAmbient()), 1.0);  // measured 0.08 Pa
  EXPECT_EQ(gas0, vented.gas() - vented.state.vented_in + vented.state.vented_out);
  EXPECT_NEAR(10.0, static_cast<double>(vented.state.vented_out - vented.state.vented_in), 5.0);  // measured 10
  EXPECT_EQ(0u, vented.state.particles.count(ParticleKind::Escaped));

  VentRun still(tankCase(true, true, 0.0));
  still.advanceTo(0.5);
  double fastest = 0.0;
  const auto& p = still.state.particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == ParticleKind::Fluid) fastest = std::max(fastest, p.velocity[i].norm());
  EXPECT_LT(fastest, 1e-3);  // measured 9e-6 m/s
  EXPECT_EQ(0, still.state.vented_in + still.state.vented_out);
}

TEST(GasVent, CaseFileChecksTheVent) {
  const std::string duct = ductCase(0.0);
  // A vent box inside a wall region.
  std::string text = duct;
  text.replace(text.find("min = [0.0, 0.3]\nmax = [0.1, 0.34]"), 34, "min = [0.1, 0.3]\nmax = [0.14, 0.34]");
  EXPECT_HAS(errorOf(text), "vent[1] overlaps wall region \"right\"");
  // Not a unit coordinate vector.
  text = duct;
  text.replace(text.find("direction = [0, 1]"), 18, "direction = [0.7, 0.7]");
  EXPECT_HAS(errorOf(text), "vent[1].direction is not a unit coordinate vector");
  // An unknown key.
  text = duct;
  text.replace(text.find("direction = [0, 1]"), 18, "direction = [0, 1]\npressure = 0.0");
  EXPECT_HAS(errorOf(text), "vent[1]");
  EXPECT_HAS(errorOf(text), "pressure");
  // No gas.
  text = duct;
  text.replace(text.find("material = \"gas\""), 16, "material = \"water\"");
  EXPECT_HAS(errorOf(text), "this case has no gas region");
  // numerics.vent_outlet: "buffer" by default, "zero_gradient", nothing else.
  EXPECT_FALSE(parseCase(duct, "duct.toml").numerics.vent_zero_gradient);
  EXPECT_TRUE(parseCase(ductCase(0.0, "vent_outlet = \"zero_gradient\"\n"), "duct.toml").numerics.vent_zero_gradient);
  const std::string bad = errorOf(ductCase(0.0, "vent_outlet = \"open\"\n"));
  EXPECT_HAS(bad, "numerics.vent_outlet");
  EXPECT_HAS(bad, "zero_gradient");
  // Each vent choice: its default on both vents; the other value, set on the top vent only; a bad value named with
  // the allowed ones.
  auto checkChoice = [&](const std::string& key, auto member, auto default_value, const std::string& other,
                         auto other_value, const std::string& allowed) {
    SCOPED_TRACE(key);
    auto withKey = [&](const std::string& value) {
      std::string t = duct;
      t.replace(t.find("direction = [0, 1]"), 18, "direction = [0, 1]\n" + key + " = \"" + value + "\"");
      return t;
    };
    EXPECT_EQ(default_value, parseCase(duct, "duct.toml").vents[1].*member);
    EXPECT_EQ(other_value, parseCase(withKey(other), "duct.toml").vents[1].*member);
    EXPECT_EQ(default_value, parseCase(withKey(other), "duct.toml").vents[0].*member);
    EXPECT_HAS(errorOf(withKey("open")), "vent[1]." + key);
    EXPECT_HAS(errorOf(withKey("open")), allowed);
  };
  checkChoice("inflow", &Vent::inflow, Vent::Inflow::TotalPressure, "static", Vent::Inflow::Static, "total_pressure");
  checkChoice("liquid_exit", &Vent::liquid_exit, Vent::LiquidExit::OuterFace, "inner_face",
              Vent::LiquidExit::InnerFace, "inner_face");
}

// A vented run resumed from a checkpoint goes on as the unbroken run did, particle for particle (the vents keep
// nothing between steps but their particles and the counts in the state).
TEST(GasVent, AVentedRunResumesBitIdentically) {
  VentRun whole(tankCase(true));
  whole.advanceTo(0.05);  // an output time of both runs
  whole.advanceTo(0.1);
  VentRun first(tankCase(true));
  first.advanceTo(0.05);
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "mistfall_vent_resume.ckpt";
  writeCheckpoint<2>(file, first.state);
  VentRun second(tankCase(true));
  second.state = readCheckpoint<2>(file);
  std::filesystem::remove(file);
  second.solver = std::make_unique<MpsSolver<2>>(second.config, second.state);
  second.advanceTo(0.1);
  EXPECT_GT(whole.state.vented_out, 0);
  EXPECT_EQ(whole.state.step, second.state.step);
  EXPECT_EQ(whole.state.vented_in, second.state.vented_in);
  EXPECT_EQ(whole.state.vented_out, second.state.vented_out);
  test_support::expectSameParticles(whole.state.particles, second.state.particles);
}

// Water that splashed into a vent and leaves it across the outer face just beside the box's edge (outside every
// column) left through the vent: it is removed and counted as liquid_out, not left beyond the domain to be counted as
// escaped (waterfall_small, cavity vent, 4.32 s: 0.2 l0 below the vent's lower edge).
TEST(GasVent, WaterLeavingByTheOuterFaceBesideTheEdgeLeaves) {
  Exchange e;
  std::size_t k = e.p.size();
  for (std::size_t i = 0; i < e.p.size(); ++i)
    if (e.vent[i] == 0 && std::abs(e.p.position[i][0] - 0.005) < 1e-9 && std::abs(e.p.position[i][1] + 0.035) < 1e-9)
      k = i;
  ASSERT_LT(k, e.p.size());
  e.p.phase[k] = Phase::Liquid;
  e.p.position[k] = Vec<2>(-0.002, -0.041);  // past the outer face y = -0.04, left of the first column
  const std::size_t before = e.p.size();
  const VentExchange x = exchangeVentGas<2>(e.p, e.config, e.vent, e.start, 0.02, 1.2, Vec<2>(0.0, -9.81));
  EXPECT_EQ(1, x.liquid_out);
  EXPECT_EQ(0, x.gas_out);
  EXPECT_EQ(before - 1 + static_cast<std::size_t>(x.gas_in), e.p.size());
  for (std::size_t i = 0; i < e.p.size(); ++i) EXPECT_GE(e.p.position[i][1], -0.04) << "particle " << i;
}

// numerics.vent_liquid_stop: the top vent's first column (x = 0.005, layers from y = 0.305) is drawn inward at 0.3 m/s
// by the air in front of it, 6 mm in 0.02 s, onto a droplet at (0.005, 0.296) under its mouth. Without the key its
// first particle ends 0.3 l0 from the droplet (the pair the waterfall's roof vent made, docs/waterfall.md); with it
// the column is held where it was and counted, and the other columns are driven as before.
TEST(GasVent, AColumnDrawnOntoLiquidAtItsMouthIsHeldWithTheKey) {
  for (const bool stop : {false, true}) {
    SCOPED_TRACE(stop ? "vent_liquid_stop = true" : "without the key");
    const CaseConfig config = parseCase(ductCase(0.0, stop ? "vent_liquid_stop = true\n" : ""), "duct.toml");
    Particles<2> p = buildParticles<2>(config);
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.phase[i] == Phase::Gas && std::abs(p.position[i][0] - 0.005) < 1e-9 && p.position[i][1] > 0.28 &&
          p.position[i][1] < 0.3)
        p.velocity[i] = Vec<2>(0.0, -0.3);
    p.add(Vec<2>(0.005, 0.296), Vec<2>::Zero(), ParticleKind::Fluid, Phase::Liquid);
    const std::size_t droplet = p.size() - 1;
    const std::vector<int> vent = ventOf<2>(p, config);
    const std::vector<Vec<2>> start = p.position;
    const VentExchange x = exchangeVentGas<2>(p, config, vent, start, 0.02, 1.2, Vec<2>(0.0, -9.81));
    EXPECT_EQ(stop ? 1 : 0, x.liquid_stops);
    double nearest = 1.0;
    int moved = 0;
    for (std::size_t i = 0; i < start.size(); ++i) {
      if (vent[i] != 1) continue;
      if (std::abs(p.position[i][1] - start[i][1]) > 1e-12) ++moved;
      nearest = std::min(nearest, (p.position[i] - p.position[droplet]).norm());
    }
    EXPECT_EQ(stop ? 0 : 4, moved);
    if (stop)
      EXPECT_GE(nearest, 0.5 * 0.01);  // no closer than the collision distance (0.5 l0, the case's default)
    else
      EXPECT_NEAR(0.003, nearest, 1e-12);
  }
}

// A vent's liquid_exit: spray at (0.005, 0.302), inside the top vent's box 2 mm above its inner face (y = 0.3), and a
// droplet at (0.045, 0.296) under its mouth. With "outer_face" (the default) both stay, liquid in the box is not
// driven and the columns keep their gas; with "inner_face" the one in the box leaves, counted as liquid out, and the
// one under the mouth stays. No gas is removed either way.
TEST(GasVent, LiquidInAVentsBoxLeavesAtTheInnerFaceWithTheKey) {
  for (const bool inner : {false, true}) {
    SCOPED_TRACE(inner ? "liquid_exit = \"inner_face\"" : "the default");
    std::string text = ductCase(0.0);
    if (inner) text.replace(text.find("direction = [0, 1]"), 18, "direction = [0, 1]\nliquid_exit = \"inner_face\"");
    const CaseConfig config = parseCase(text, "duct.toml");
    Particles<2> p = buildParticles<2>(config);
    p.add(Vec<2>(0.005, 0.302), Vec<2>(0.0, 0.5), ParticleKind::Fluid, Phase::Liquid);
    p.add(Vec<2>(0.045, 0.296), Vec<2>::Zero(), ParticleKind::Fluid, Phase::Liquid);
    const std::uint64_t in_box = p.id[p.size() - 2], at_mouth = p.id[p.size() - 1];
    const std::vector<int> vent = ventOf<2>(p, config);
    const std::vector<Vec<2>> start = p.position;
    const std::size_t before = p.size();
    const VentExchange x = exchangeVentGas<2>(p, config, vent, start, 0.002, 1.2, Vec<2>(0.0, -9.81));
    EXPECT_EQ(inner ? 1 : 0, x.liquid_out);
    EXPECT_EQ((std::vector<std::int64_t>{0, inner ? 1 : 0}), x.liquid_out_by_vent);  // the top vent's, for vents.csv
    EXPECT_EQ(0, x.gas_out);
    EXPECT_EQ(before - x.liquid_out + x.gas_in, p.size());
    int found_in_box = 0, found_at_mouth = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      found_in_box += p.id[i] == in_box;
      found_at_mouth += p.id[i] == at_mouth;
    }
    EXPECT_EQ(inner ? 0 : 1, found_in_box);
    EXPECT_EQ(1, found_at_mouth);
  }
}

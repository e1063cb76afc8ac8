// Tests of the case-file reader for the gas phase ([physics.gas], material = "gas", overlap resolution) and
// circle-shaped regions.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "case/scene.hpp"
#include "support/case_text.hpp"

using namespace mistfall;
using test_support::errorOf;
using test_support::Parts;

TEST(CaseFileGas, PhaseDefaultsAndLookup) {
  const CaseConfig c = parseCase(Parts{}.text(), "t.toml");
  EXPECT_DOUBLE_EQ(c.physics.gas.density, 1.2);
  EXPECT_DOUBLE_EQ(c.physics.gas.kinematic_viscosity, 1.5e-5);
  EXPECT_DOUBLE_EQ(c.physics.gas.sound_speed, 340.0);
  EXPECT_DOUBLE_EQ(PhysicsConfig{}.gas.sound_speed, 340.0);
  EXPECT_TRUE(std::isinf(PhysicsConfig{}.liquid.sound_speed));  // the liquid defaults are unchanged
  EXPECT_EQ(&phaseProperties(c.physics, static_cast<int>(Phase::Liquid)), &c.physics.liquid);
  EXPECT_EQ(&phaseProperties(c.physics, static_cast<int>(Phase::Gas)), &c.physics.gas);
  EXPECT_THROW(phaseProperties(c.physics, 2), std::out_of_range);
}

TEST(CaseFileGas, ReadsGasTable) {
  Parts p;
  p.physics = "[physics.liquid]\ndensity = 998\n[physics.gas]\ndensity = 1.25\nkinematic_viscosity = 1.6e-5\n"
              "sound_speed = \"inf\"\n";
  CaseConfig c = parseCase(p.text(), "t.toml");
  EXPECT_DOUBLE_EQ(c.physics.liquid.density, 998.0);
  EXPECT_DOUBLE_EQ(c.physics.gas.density, 1.25);
  EXPECT_DOUBLE_EQ(c.physics.gas.kinematic_viscosity, 1.6e-5);
  EXPECT_TRUE(std::isinf(c.physics.gas.sound_speed));

  p.physics = "[physics.gas]\nsound_speed = 100\n";
  c = parseCase(p.text(), "t.toml");
  EXPECT_DOUBLE_EQ(c.physics.gas.sound_speed, 100.0);
  EXPECT_DOUBLE_EQ(c.physics.gas.density, 1.2);  // untouched keys keep the gas defaults
}

TEST(CaseFileGas, GasTableErrors) {
  struct Bad {
    std::string line, path, allowed;
  };
  const Bad cases[] = {
      {"density = 0", "physics.gas.density = 0", "(0, 100000]"},
      {"density = 2e5", "physics.gas.density = 200000", "(0, 100000]"},
      {"kinematic_viscosity = -1e-5", "physics.gas.kinematic_viscosity = -1e-5", "[0, 1]"},
      {"kinematic_viscosity = 2", "physics.gas.kinematic_viscosity = 2", "[0, 1]"},
      {"sound_speed = 0", "physics.gas.sound_speed = 0", "a number > 0 or the string \"inf\""},
      {"sound_speed = \"fast\"", "physics.gas.sound_speed = \"fast\"", "a number > 0 or the string \"inf\""},
  };
  for (const Bad& b : cases) {
    Parts p;
    p.physics = "[physics.gas]\n" + b.line + "\n";
    const std::string msg = errorOf(p.text());
    EXPECT_HAS(msg, "cases/x.toml: " + b.path);
    EXPECT_HAS(msg, "allowed " + b.allowed);
  }
  Parts p;
  p.physics = "[physics.gas]\ndensty = 1.2\n";
  std::string msg = errorOf(p.text());
  EXPECT_HAS(msg, "unknown key physics.gas.densty; did you mean 'density'?");
  p.physics = "[physics]\ngas = 1.2\n";
  EXPECT_HAS(errorOf(p.text()), "physics.gas = 1.2 has the wrong type");
  p.physics = "[physics.air]\ndensity = 1.2\n";
  msg = errorOf(p.text());
  EXPECT_HAS(msg, "unknown key physics.air");
  EXPECT_HAS(msg, "gravity, liquid, gas");
}

namespace {
std::string gasRegion(const std::string& name, const std::string& min, const std::string& max,
                      const std::string& extra = "") {
  return "[[region]]\nname = \"" + name + "\"\nmaterial = \"gas\"\nmin = " + min + "\nmax = " + max + "\n" + extra;
}
}  // namespace

TEST(CaseFileGas, GasRegionsMayOverlapAnything) {
  // Gas declared first over the whole domain, then water and a wall inside it; gas regions overlapping each
  // other; a velocity on gas.
  Parts p;
  p.regions = gasRegion("air", "[0, 0]", "[1, 1]", "velocity = [0.5, 0]\n") + p.regions +
              "[[region]]\nname = \"floor\"\nmaterial = \"wall\"\nmin = [0.5, 0]\nmax = [1, 0.2]\n" +
              gasRegion("jet", "[0.6, 0.6]", "[0.9, 0.9]");
  const CaseConfig c = parseCase(p.text(), "t.toml");
  ASSERT_EQ(c.regions.size(), 4u);
  EXPECT_EQ(c.regions[0].material, Material::Gas);
  EXPECT_EQ(c.regions[0].initial_velocity, (std::array<double, 3>{0.5, 0.0, 0.0}));
  EXPECT_EQ(c.regions[3].material, Material::Gas);
  EXPECT_EQ(regionParticleCounts(c), (std::vector<std::size_t>{100u - 25u - 10u - 9u, 25u, 10u, 9u}));

  // Water after gas overrides the gas; gas after water overrides the water.
  p = Parts{};
  p.regions += gasRegion("bubble", "[0.2, 0.2]", "[0.4, 0.4]");
  EXPECT_EQ(regionParticleCounts(parseCase(p.text(), "t.toml")), (std::vector<std::size_t>{21u, 4u}));
}

TEST(CaseFileGas, RegionLeftWithoutPointsNamesIt) {
  Parts p;  // the gas lies entirely inside the later water region
  p.regions = gasRegion("air", "[0.1, 0.1]", "[0.3, 0.3]") + p.regions;
  std::string msg = errorOf(p.text());
  EXPECT_HAS(msg, "cases/x.toml: region[0] (\"air\") contains no lattice point not taken by a wall region or by a "
                  "later water or gas region (material = \"gas\")");

  p = Parts{};  // gas inside a wall, declared after it: walls always win
  p.regions += "[[region]]\nname = \"block\"\nmaterial = \"wall\"\nmin = [0.5, 0]\nmax = [1, 1]\n" +
               gasRegion("air", "[0.6, 0.6]", "[0.9, 0.9]");
  EXPECT_HAS(errorOf(p.text()), "region[2] (\"air\") contains no lattice point not taken by a wall region");

  p = Parts{};  // a later gas region swallows the whole water region
  p.regions += gasRegion("air", "[0, 0]", "[1, 1]");
  msg = errorOf(p.text());
  EXPECT_HAS(msg, "region[0] (\"w\") contains no lattice point");
  EXPECT_HAS(msg, "(material = \"water\")");

  p = Parts{};  // a gas region that is empty of lattice points to begin with gets the empty-region error
  p.regions += gasRegion("thin", "[0.6, 0.36]", "[1.0, 0.44]");
  EXPECT_HAS(errorOf(p.text()), "region[1] (\"thin\") is empty");
}

TEST(CaseFileGas, WaterStillMustNotOverlapWaterOrWall) {
  Parts p;
  p.regions = gasRegion("air", "[0, 0]", "[1, 1]") + p.regions +
              "[[region]]\nname = \"w2\"\nmin = [0.4, 0.4]\nmax = [0.8, 0.8]\n";
  std::string msg = errorOf(p.text());
  EXPECT_HAS(msg, "region[2] (\"w2\") overlaps region[1] (\"w\") (water and water)");
  EXPECT_HAS(msg, "gas regions may overlap any region");
  p = Parts{};
  p.regions += "[[region]]\nname = \"walls\"\nmaterial = \"wall\"\nmin = [0.4, 0.4]\nmax = [0.8, 0.8]\n";
  EXPECT_HAS(errorOf(p.text()), "region[1] (\"walls\") overlaps region[0] (\"w\") (wall and water)");
}

TEST(CaseFileGas, VelocityNotAllowedOnWall) {
  Parts p;
  p.regions += "[[region]]\nname = \"s\"\nmaterial = \"wall\"\nmin = [0.5, 0.5]\nmax = [1.0, 1.0]\n"
               "velocity = [1.0, 0.0]\n";
  EXPECT_HAS(errorOf(p.text()), "allowed only in water and gas regions");
  p.regions = Parts{}.regions + "[[region]]\nname = \"g\"\nmaterial = \"plasma\"\nmin = [0.5, 0.5]\nmax = [1, 1]\n";
  EXPECT_HAS(errorOf(p.text()),
             "region[1].material = \"plasma\" is not allowed; allowed \"water\" or \"wall\" or \"gas\"");
}

namespace {
std::string circle(const std::string& name, const std::string& material, const std::string& center,
                   const std::string& radius, const std::string& extra = "") {
  return "[[region]]\nname = \"" + name + "\"\nmaterial = \"" + material + "\"\nshape = \"circle\"\ncenter = " +
         center + "\nradius = " + radius + "\n" + extra;
}
}  // namespace

TEST(CaseFileCircle, ReadsCircleAndSphere) {
  Parts p;
  p.regions = "[[region]]\nname = \"w\"\nshape = \"box\"\nmin = [0, 0]\nmax = [1, 0.5]\n" +
              circle("bubble", "gas", "[0.5, 0.25]", "0.2", "velocity = [0, 1]\n");
  const CaseConfig c = parseCase(p.text(), "t.toml");
  EXPECT_EQ(c.regions[0].shape, RegionShape::Box);
  const Region& b = c.regions[1];
  EXPECT_EQ(b.shape, RegionShape::Circle);
  EXPECT_EQ(b.center, (std::array<double, 3>{0.5, 0.25, 0.0}));
  EXPECT_DOUBLE_EQ(b.radius, 0.2);
  EXPECT_DOUBLE_EQ(b.box.min[0], 0.3);  // bounding box
  EXPECT_DOUBLE_EQ(b.box.max[1], 0.45);
  EXPECT_EQ(b.initial_velocity, (std::array<double, 3>{0.0, 1.0, 0.0}));

  Parts q;
  q.header = "name = \"t3\"\ndimension = 3\n";
  q.domain = "min = [0, 0, 0]\nmax = [1, 1, 1]\n";
  q.regions = circle("drop", "water", "[0.5, 0.5, 0.5]", "0.5");
  const CaseConfig c3 = parseCase(q.text(), "t.toml");
  // A sphere of radius 5 l0 centred on a cell corner holds 552 lattice points (4/3 pi 5^3 = 523.6).
  EXPECT_EQ(countLatticePoints(c3, c3.regions[0]), 552u);
}

TEST(CaseFileCircle, Errors) {
  const std::string water = Parts{}.regions;
  struct Bad {
    std::string regions, expected;
  };
  const Bad cases[] = {
      {water + circle("c", "gas", "[0.5, 0.5]", "0"), "region[1].radius = 0 is out of range; allowed (0, inf)"},
      {water + circle("c", "gas", "[0.5, 0.5]", "-0.1"), "region[1].radius = -0.1 is out of range"},
      {water + circle("c", "gas", "[0.5, 0.5]", "\"big\""), "region[1].radius = \"big\" has the wrong type"},
      {water + circle("c", "gas", "[0.5, 0.5]", "0.75"),
       "region[1].radius = 0.75 takes the circle outside the domain on axis 0: center[0] -/+ radius = [-0.25, 1.25]"},
      {water + circle("c", "gas", "[0.5, 0.8]", "0.3"),
       "region[1].radius = 0.3 takes the circle outside the domain on axis 1"},
      {water + circle("c", "gas", "[1.5, 0.5]", "0.1"),
       "region[1].center[0] = 1.5 lies outside the domain; allowed [0, 1] (domain.min[0] to domain.max[0])"},
      {water + circle("c", "gas", "[0.5, 0.5]", "0.1", "min = [0.4, 0.4]\n"),
       "region[1].min = [0.4, 0.4] is not allowed with shape = \"circle\"; allowed center and radius"},
      {water + circle("c", "gas", "[0.5, 0.5]", "0.1", "max = [0.6, 0.6]\n"),
       "region[1].max = [0.6, 0.6] is not allowed with shape = \"circle\""},
      {water + "[[region]]\nname = \"c\"\nmaterial = \"gas\"\nmin = [0.5, 0.5]\nmax = [1, 1]\nradius = 0.1\n",
       "region[1].radius = 0.1 is not allowed with shape = \"box\"; allowed min and max"},
      {water + "[[region]]\nname = \"c\"\nshape = \"box\"\ncenter = [0.5, 0.5]\nmin = [0.5, 0.5]\nmax = [1, 1]\n",
       "region[1].center = [0.5, 0.5] is not allowed with shape = \"box\""},
      {water + "[[region]]\nname = \"c\"\nshape = \"circle\"\nradius = 0.1\n", "missing required key region[1].center"},
      {water + "[[region]]\nname = \"c\"\nshape = \"circle\"\ncenter = [0.5, 0.5]\n",
       "missing required key region[1].radius; allowed a number in (0, inf)"},
      {water + "[[region]]\nname = \"c\"\nshape = \"circle\"\ncenter = [0.5, 0.5, 0.5]\nradius = 0.1\n",
       "region[1].center = [0.5, 0.5, 0.5] has 3 elements"},
      {water + "[[region]]\nname = \"c\"\nshape = \"square\"\nmin = [0.5, 0.5]\nmax = [1, 1]\n",
       "region[1].shape = \"square\" is not allowed; allowed \"box\" or \"circle\""},
      // Between lattice points (0.65 and 0.75 on both axes): the circle holds none.
      {water + circle("c", "gas", "[0.7, 0.7]", "0.02"),
       "region[1] (\"c\") is empty: region[1].center = [0.7, 0.7], region[1].radius = 0.02 contains no lattice point"},
      {water + circle("c", "wall", "[0.6, 0.6]", "0.2"), "region[1] (\"c\") overlaps region[0] (\"w\")"},
      {water + circle("c", "water", "[0.75, 0.75]", "0.2") + circle("d", "water", "[0.75, 0.35]", "0.25"),
       "region[2] (\"d\") overlaps region[1] (\"c\")"},
  };
  for (const Bad& b : cases) {
    Parts p;
    p.regions = b.regions;
    EXPECT_HAS(errorOf(p.text()), b.expected);
  }
  // Touching is no overlap: a water circle touching the water box and a wall circle.
  Parts p;
  p.regions = water + circle("c", "wall", "[0.75, 0.75]", "0.25") + circle("d", "water", "[0.75, 0.25]", "0.25");
  EXPECT_NO_THROW(parseCase(p.text(), "t.toml"));
}

// The stabilised scheme takes gas under either coupling (docs/two-phase.md; before the twentieth session the two
// systems refused it).
TEST(CaseFileGas, StabilisedSchemeTakesGasUnderEitherCoupling) {
  for (const char* coupling : {"two_systems", "one_equation"}) {
    Parts p;
    p.numerics += std::string("scheme = \"stabilised\"\npressure_source = \"mixed\"\ncoupling = \"") + coupling + "\"\n";
    p.regions += "[[region]]\nname = \"air\"\nmaterial = \"gas\"\nmin = [0.0, 0.5]\nmax = [0.5, 1.0]\n";
    const CaseConfig c = parseCase(p.text(), "t.toml");
    EXPECT_EQ(c.numerics.scheme, Scheme::Stabilised) << coupling;
  }
}

// The bubble's gas motion and the regularisation of its rows (docs/two-phase.md): defaults, values, errors.
TEST(CaseFileGas, BubbleGasKeys) {
  const CaseConfig d = parseCase(Parts{}.text(), "t.toml");
  EXPECT_EQ(d.numerics.bubble_gas_motion, NumericsConfig::BubbleGasMotion::FollowLiquid);
  EXPECT_DOUBLE_EQ(d.numerics.bubble_regularisation, 10.0);
  EXPECT_FALSE(d.numerics.gas_pressure_memory_open);
  EXPECT_FALSE(d.numerics.gas_pressure_memory_bubbles);
  EXPECT_TRUE(d.numerics.bubble_start_at_water_pressure);
  EXPECT_FALSE(d.numerics.bubble_divergence_whole);
  EXPECT_FALSE(d.numerics.gas_collision_after_correction);
  EXPECT_FALSE(d.numerics.liquid_collision_after_correction);
  Parts p;
  p.numerics += "bubble_gas_motion = \"own_pressure\"\nbubble_regularisation = 0\ngas_pressure_memory = true\n"
                "gas_collision_after_correction = true\nliquid_collision_after_correction = true\n";
  const CaseConfig c = parseCase(p.text(), "t.toml");
  EXPECT_EQ(c.numerics.bubble_gas_motion, NumericsConfig::BubbleGasMotion::OwnPressure);
  EXPECT_DOUBLE_EQ(c.numerics.bubble_regularisation, 0.0);
  EXPECT_TRUE(c.numerics.gas_pressure_memory_open);
  EXPECT_TRUE(c.numerics.gas_pressure_memory_bubbles);
  EXPECT_TRUE(c.numerics.gas_collision_after_correction);
  EXPECT_TRUE(c.numerics.liquid_collision_after_correction);
  p = Parts{};
  p.numerics += "gas_pressure_memory = \"bubbles\"\n";  // the bubbles' rows only
  const CaseConfig b = parseCase(p.text(), "t.toml");
  EXPECT_FALSE(b.numerics.gas_pressure_memory_open);
  EXPECT_TRUE(b.numerics.gas_pressure_memory_bubbles);
  p = Parts{};
  p.numerics += "gas_pressure_memory = \"open_gas\"\n";  // the open gas's rows only
  const CaseConfig o = parseCase(p.text(), "t.toml");
  EXPECT_TRUE(o.numerics.gas_pressure_memory_open);
  EXPECT_FALSE(o.numerics.gas_pressure_memory_bubbles);
  p = Parts{};
  p.numerics += "gas_pressure_memory = \"open\"\n";
  EXPECT_HAS(errorOf(p.text()), "allowed \"bubbles\" or \"open_gas\"");
  p = Parts{};
  p.numerics += "gas_pressure_memory = 1\n";
  EXPECT_HAS(errorOf(p.text()), "true, false, \"bubbles\" or \"open_gas\"");
  p = Parts{};
  p.numerics += "bubble_initial_pressure = \"zero\"\n";
  EXPECT_FALSE(parseCase(p.text(), "t.toml").numerics.bubble_start_at_water_pressure);
  p = Parts{};
  p.numerics += "bubble_initial_pressure = \"hydrostatic\"\n";
  EXPECT_HAS(errorOf(p.text()), "allowed \"zero\" or \"water\"");
  p = Parts{};
  p.numerics += "bubble_divergence = \"whole_bubble\"\n";
  EXPECT_TRUE(parseCase(p.text(), "t.toml").numerics.bubble_divergence_whole);
  p = Parts{};
  p.numerics += "bubble_divergence = \"whole\"\n";
  EXPECT_HAS(errorOf(p.text()), "allowed \"interface\" or \"whole_bubble\"");
  p = Parts{};
  p.numerics += "bubble_gas_motion = \"float\"\n";
  EXPECT_HAS(errorOf(p.text()), "allowed \"follow_liquid\" or \"own_pressure\"");
  p = Parts{};
  p.numerics += "bubble_regularisation = -1\n";
  EXPECT_HAS(errorOf(p.text()), "numerics.bubble_regularisation = -1 is out of range");
}

// numerics.bubble_surface_tension and surface_tension_fit_radius (solver_liquid.cpp, interface_curvature.hpp):
// defaults, values, errors.
TEST(CaseFileGas, BubbleSurfaceTensionKeys) {
  const CaseConfig d = parseCase(Parts{}.text(), "t.toml");
  EXPECT_FALSE(d.numerics.bubble_surface_tension);
  EXPECT_DOUBLE_EQ(d.numerics.surface_tension_fit_radius, 5.0);
  Parts p;
  p.numerics += "bubble_surface_tension = \"jump\"\nsurface_tension_fit_radius = 4\n";
  const CaseConfig c = parseCase(p.text(), "t.toml");
  EXPECT_TRUE(c.numerics.bubble_surface_tension);
  EXPECT_DOUBLE_EQ(c.numerics.surface_tension_fit_radius, 4.0);
  p = Parts{};
  p.numerics += "bubble_surface_tension = \"csf\"\n";
  EXPECT_HAS(errorOf(p.text()), "allowed \"none\" or \"jump\"");
  p = Parts{};
  p.numerics += "surface_tension_fit_radius = 1.5\n";
  EXPECT_HAS(errorOf(p.text()), "numerics.surface_tension_fit_radius = 1.5 is out of range");
  p = Parts{};
  p.numerics += "bubble_surface_tension = \"jump\"\nscheme = \"stabilised\"\npressure_source = \"mixed\"\n"
                "coupling = \"one_equation\"\n";
  EXPECT_HAS(errorOf(p.text()), "bubble_surface_tension = \"jump\" needs numerics.coupling = \"two_systems\"");
  p = Parts{};
  p.numerics += "bubble_surface_tension = \"jump\"\nscheme = \"stabilised\"\npressure_source = \"mixed\"\n";
  EXPECT_HAS(errorOf(p.text()), "bubble_surface_tension = \"jump\" is built on numerics.scheme = \"paper\"");
}

// numerics.thin_row_pressure (solver_liquid_stabilised.cpp): "surface" by default; "liquid" on the stabilised
// scheme's two systems only.
TEST(CaseFileGas, ThinRowPressureKey) {
  EXPECT_FALSE(parseCase(Parts{}.text(), "t.toml").numerics.thin_rows_hold_liquid);
  Parts p;
  p.numerics += "thin_row_pressure = \"liquid\"\nscheme = \"stabilised\"\npressure_source = \"mixed\"\n";
  EXPECT_TRUE(parseCase(p.text(), "t.toml").numerics.thin_rows_hold_liquid);
  p = Parts{};
  p.numerics += "thin_row_pressure = \"walls\"\n";
  EXPECT_HAS(errorOf(p.text()), "allowed \"surface\" or \"liquid\"");
  p = Parts{};
  p.numerics += "thin_row_pressure = \"liquid\"\n";  // the paper's scheme has no thin rows
  EXPECT_HAS(errorOf(p.text()), "thin_row_pressure = \"liquid\" needs numerics.scheme = \"stabilised\"");
  p = Parts{};
  p.numerics += "thin_row_pressure = \"liquid\"\nscheme = \"stabilised\"\npressure_source = \"mixed\"\n"
                "coupling = \"one_equation\"\n";
  EXPECT_HAS(errorOf(p.text()), "thin_row_pressure = \"liquid\" needs numerics.scheme = \"stabilised\"");
}

// numerics.closed_pockets (enclosed_gas.hpp): "small" by default; "unvented" needs a closed gas domain and a vent.
TEST(CaseFileGas, ClosedPocketsKey) {
  EXPECT_EQ(parseCase(Parts{}.text(), "t.toml").numerics.closed_pockets, NumericsConfig::ClosedPockets::Small);
  const std::string air = "[[region]]\nname = \"air\"\nmaterial = \"gas\"\nmin = [0.0, 0.5]\nmax = [1.0, 1.0]\n";
  const std::string vent = "[[vent]]\nname = \"top\"\nmin = [0.4, 1.0]\nmax = [0.6, 1.1]\ndirection = [0, 1]\n";
  Parts p;
  p.domain = "min = [0.0, 0.0]\nmax = [1.0, 1.1]\n";
  p.physics = "[physics.gas]\nsound_speed = 340.0\n";
  p.numerics += "gas_domain = \"closed\"\nclosed_pockets = \"unvented\"\n";
  p.regions += air + vent;
  EXPECT_EQ(parseCase(p.text(), "t.toml").numerics.closed_pockets, NumericsConfig::ClosedPockets::Unvented);
  Parts no_vent = p;
  no_vent.regions = Parts{}.regions + air;
  EXPECT_HAS(errorOf(no_vent.text()), "this case has no [[vent]]");
  Parts open = p;
  open.numerics = Parts{}.numerics + "closed_pockets = \"unvented\"\n";
  EXPECT_HAS(errorOf(open.text()), "allowed with numerics.gas_domain = \"closed\"");
  Parts wrong;
  wrong.numerics += "closed_pockets = \"all\"\n";
  EXPECT_HAS(errorOf(wrong.text()), "allowed \"small\" or \"unvented\"");
}

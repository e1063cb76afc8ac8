// Tests of the case-file reader: shipped cases, defaults, and one test per class of error message.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <string>

#include "case/case_file.hpp"
#include "case/scene.hpp"
#include "support/case_text.hpp"

using namespace mistfall;

using test_support::errorOf;
using test_support::Parts;

namespace {

std::string source(const std::string& rel) { return std::string(MISTFALL_SOURCE_DIR) + "/" + rel; }

}  // namespace

TEST(CaseFile, ShippedCasesParse) {
  const CaseConfig h = loadCaseFile(source("cases/hydrostatic.toml"));
  EXPECT_EQ(h.name, "hydrostatic");
  EXPECT_EQ(h.dimension, 2);
  EXPECT_EQ(buildParticles<2>(h).count(ParticleKind::Fluid), 25u * 25u);

  const CaseConfig d = loadCaseFile(source("cases/dam_break.toml"));
  EXPECT_EQ(d.name, "dam_break");
  EXPECT_DOUBLE_EQ(d.numerics.particle_spacing, 0.004);
  EXPECT_DOUBLE_EQ(d.output.end_time, 0.4);
  const auto pd = buildParticles<2>(d);
  EXPECT_EQ(pd.count(ParticleKind::Fluid), 25u * 50u);
  EXPECT_GT(pd.count(ParticleKind::Wall), 0u);
  EXPECT_GT(pd.count(ParticleKind::Dummy), 0u);

  // The waterfall: q = 0.016 m^2/s through a 5 cm deep buffer (U = 0.32 m/s), drop 0.435 - 0.15 = 0.285 m.
  for (const char* name : {"cases/waterfall.toml", "cases/waterfall_small.toml"}) {
    const CaseConfig w = loadCaseFile(source(name));
    ASSERT_EQ(1u, w.inflows.size()) << name;
    EXPECT_DOUBLE_EQ(0.016, w.inflows[0].discharge);
    EXPECT_NEAR(0.32, w.inflows[0].speed, 1e-12);
    EXPECT_EQ(1u, w.outflows.size());
    EXPECT_GT(buildParticles<2>(w).count(ParticleKind::Inflow), 0u);
    if (std::string(name) == "cases/waterfall_small.toml") EXPECT_EQ(2u, w.vents.size());  // cavity and roof
  }
  EXPECT_DOUBLE_EQ(8.5, loadCaseFile(source("cases/waterfall.toml")).output.end_time);

  const CaseConfig d3 = loadCaseFile(source("cases/dam_break_3d.toml"));
  EXPECT_EQ(d3.dimension, 3);
  const auto p3 = buildParticles<3>(d3);
  EXPECT_EQ(p3.count(ParticleKind::Fluid), 10u * 10u * 20u);
  EXPECT_GT(p3.count(ParticleKind::Dummy), p3.count(ParticleKind::Wall) / 2);
}

TEST(CaseFile, DefaultsApplied) {
  const CaseConfig c = parseCase(Parts{}.text(), "t.toml");
  const NumericsConfig def;
  EXPECT_EQ(c.name, "t");
  EXPECT_DOUBLE_EQ(c.numerics.particle_spacing, 0.1);
  EXPECT_DOUBLE_EQ(c.numerics.radius_number_density, def.radius_number_density);
  EXPECT_DOUBLE_EQ(c.numerics.radius_laplacian, def.radius_laplacian);
  EXPECT_DOUBLE_EQ(c.numerics.courant, def.courant);
  EXPECT_DOUBLE_EQ(c.numerics.dt_max, def.dt_max);
  EXPECT_DOUBLE_EQ(c.numerics.dt_min, def.dt_min);
  EXPECT_DOUBLE_EQ(c.numerics.surface_threshold, def.surface_threshold);
  EXPECT_DOUBLE_EQ(c.numerics.collision_distance, def.collision_distance);
  EXPECT_DOUBLE_EQ(c.numerics.collision_restitution, def.collision_restitution);
  EXPECT_EQ(c.numerics.pressure_solver, PressureSolverKind::HypreAmg);
  EXPECT_DOUBLE_EQ(c.numerics.solver_tolerance, def.solver_tolerance);
  EXPECT_EQ(c.numerics.solver_max_iterations, def.solver_max_iterations);
  EXPECT_DOUBLE_EQ(c.numerics.max_escaped_fraction, def.max_escaped_fraction);
  EXPECT_DOUBLE_EQ(c.physics.liquid.density, 1000.0);
  EXPECT_DOUBLE_EQ(c.physics.liquid.kinematic_viscosity, 1.0e-6);
  EXPECT_TRUE(std::isinf(c.physics.liquid.sound_speed));
  EXPECT_EQ(c.physics.gravity, (std::array<double, 3>{0.0, -9.81, 0.0}));
  EXPECT_DOUBLE_EQ(c.output.interval, 0.01);
  ASSERT_EQ(c.regions.size(), 1u);
  EXPECT_EQ(c.regions[0].material, Material::Water);
  EXPECT_EQ(c.regions[0].initial_velocity, (std::array<double, 3>{0.0, 0.0, 0.0}));
}

TEST(CaseFile, Gravity3DDefaultPointsAlongMinusZ) {
  Parts p;
  p.header = "name = \"t3\"\ndimension = 3\n";
  p.domain = "min = [0, 0, 0]\nmax = [1, 1, 1]\n";
  p.regions = "[[region]]\nname = \"w\"\nmin = [0, 0, 0]\nmax = [0.5, 0.5, 0.5]\n";
  const CaseConfig c = parseCase(p.text(), "t.toml");
  EXPECT_EQ(c.physics.gravity, (std::array<double, 3>{0.0, 0.0, -9.81}));
  EXPECT_EQ(buildParticles<3>(c).size(), 125u);
}

TEST(CaseFile, ReadsEveryKey) {
  Parts p;
  p.physics = "[physics]\ngravity = [1, -5]\n[physics.liquid]\ndensity = 998\nkinematic_viscosity = 0.0\n"
              "sound_speed = 15.0\n";
  p.numerics = "particle_spacing = 0.1\nradius_number_density = 2.5\nradius_laplacian = 4\ncourant = 0.1\n"
               "dt_max = 0.01\ndt_min = 1e-6\nsurface_threshold = 0.9\ncollision_distance = 0.0\n"
               "collision_restitution = 1\npressure_solver = \"iccg\"\nsolver_tolerance = 1e-3\n"
               "solver_max_iterations = 50\nmax_escaped_fraction = 1\n";
  p.output = "end_time = 2\ninterval = 2\n";
  p.regions += "velocity = [0.5, -1]\n[[region]]\nname = \"box\"\nmaterial = \"wall\"\nmin = [0.5, 0]\nmax = [1, 1]\n";
  const CaseConfig c = parseCase(p.text(), "t.toml");
  EXPECT_EQ(c.physics.gravity, (std::array<double, 3>{1.0, -5.0, 0.0}));
  EXPECT_DOUBLE_EQ(c.physics.liquid.density, 998.0);
  EXPECT_DOUBLE_EQ(c.physics.liquid.kinematic_viscosity, 0.0);
  EXPECT_DOUBLE_EQ(c.physics.liquid.sound_speed, 15.0);
  EXPECT_DOUBLE_EQ(c.numerics.radius_laplacian, 4.0);
  EXPECT_DOUBLE_EQ(c.numerics.dt_min, 1e-6);
  EXPECT_DOUBLE_EQ(c.numerics.collision_distance, 0.0);
  EXPECT_EQ(c.numerics.pressure_solver, PressureSolverKind::EigenIccg);
  EXPECT_EQ(c.numerics.solver_max_iterations, 50);
  EXPECT_DOUBLE_EQ(c.output.interval, 2.0);
  ASSERT_EQ(c.regions.size(), 2u);
  EXPECT_EQ(c.regions[0].initial_velocity, (std::array<double, 3>{0.5, -1.0, 0.0}));
  EXPECT_EQ(c.regions[1].material, Material::Wall);
  EXPECT_EQ(c.regions[1].name, "box");
}

TEST(CaseFile, PressureSourceKeys) {
  // Defaults: the paper's standard source, gamma = 0.01.
  const CaseConfig d = parseCase(Parts{}.text(), "t.toml");
  EXPECT_EQ(d.numerics.pressure_source, PressureSource::Standard);
  EXPECT_DOUBLE_EQ(d.numerics.source_relaxation, 0.01);
  EXPECT_EQ(NumericsConfig{}.pressure_source, PressureSource::Standard);
  EXPECT_DOUBLE_EQ(NumericsConfig{}.source_relaxation, 0.01);

  Parts p;
  p.numerics += "pressure_source = \"mixed\"\nsource_relaxation = 0.05\n";
  CaseConfig c = parseCase(p.text(), "t.toml");
  EXPECT_EQ(c.numerics.pressure_source, PressureSource::Mixed);
  EXPECT_DOUBLE_EQ(c.numerics.source_relaxation, 0.05);
  EXPECT_FALSE(c.numerics.source_relaxation_per_time);  // "step", the default
  p.numerics += "source_relaxation_basis = \"time\"\n";
  EXPECT_TRUE(parseCase(p.text(), "t.toml").numerics.source_relaxation_per_time);

  p = Parts{};
  p.numerics += "pressure_source = \"standard\"\nsource_relaxation = 1\n";  // upper bound is closed
  c = parseCase(p.text(), "t.toml");
  EXPECT_EQ(c.numerics.pressure_source, PressureSource::Standard);
  EXPECT_DOUBLE_EQ(c.numerics.source_relaxation, 1.0);

  p = Parts{};
  p.numerics += "pressure_source = \"fast\"\n";
  std::string msg = errorOf(p.text());
  EXPECT_HAS(msg, "cases/x.toml: numerics.pressure_source = \"fast\" is not allowed");
  EXPECT_HAS(msg, "allowed \"standard\" or \"mixed\"");

  p = Parts{};
  p.numerics += "pressure_source = \"mixed\"\nsource_relaxation = 0\n";  // the pure divergence source
  EXPECT_DOUBLE_EQ(parseCase(p.text(), "t.toml").numerics.source_relaxation, 0.0);
  for (const std::string v : {"-0.1", "2"}) {
    p = Parts{};
    p.numerics += "source_relaxation = " + v + "\n";
    msg = errorOf(p.text());
    EXPECT_EQ(msg, "cases/x.toml: numerics.source_relaxation = " + v + " is out of range; allowed [0, 1]");
  }
}

TEST(CaseFile, SchemeKeys) {
  EXPECT_EQ(parseCase(Parts{}.text(), "t.toml").numerics.scheme, Scheme::Paper);  // the default
  Parts p;
  p.numerics += "scheme = \"stabilised\"\npressure_source = \"mixed\"\nliquid_support_fraction = 0.25\n"
                "gradient_correction_min_determinant = 0.5\n";
  const CaseConfig c = parseCase(p.text(), "t.toml");
  EXPECT_EQ(c.numerics.scheme, Scheme::Stabilised);
  EXPECT_DOUBLE_EQ(c.numerics.liquid_support_fraction, 0.25);
  EXPECT_DOUBLE_EQ(c.numerics.gradient_correction_min_determinant, 0.5);
  // The stabilised walls act through the divergence source, which only the mixed source has.
  p = Parts{};
  p.numerics += "scheme = \"stabilised\"\n";
  EXPECT_HAS(errorOf(p.text()), "numerics.scheme = \"stabilised\" needs numerics.pressure_source = \"mixed\"");
  p = Parts{};
  p.numerics += "scheme = \"fast\"\n";
  EXPECT_HAS(errorOf(p.text()), "allowed \"paper\" or \"stabilised\"");
  p = Parts{};
  p.numerics += "scheme = \"stabilised\"\npressure_source = \"mixed\"\nliquid_support_fraction = 1\n";
  EXPECT_HAS(errorOf(p.text()), "numerics.liquid_support_fraction = 1 is out of range; allowed [0, 1)");
}

TEST(CaseFile, SyntaxErrorNamesFileLineAndColumn) {
  const std::string msg = errorOf("[case]\nname = \"t\"\ndimension = = 2\n");
  EXPECT_HAS(msg, "cases/x.toml");
  EXPECT_HAS(msg, "syntax error");
  EXPECT_HAS(msg, "line 3");
  EXPECT_HAS(msg, "column");
}

TEST(CaseFile, UnknownKeySuggestsClosest) {
  Parts p;
  p.numerics += "courrant = 0.1\n";
  std::string msg = errorOf(p.text());
  EXPECT_HAS(msg, "cases/x.toml: unknown key numerics.courrant");
  EXPECT_HAS(msg, "did you mean 'courant'");

  p = Parts{};
  p.regions = "[[regions]]\nname = \"w\"\nmin = [0.0, 0.0]\nmax = [0.5, 0.5]\n";
  msg = errorOf(p.text());
  EXPECT_HAS(msg, "unknown key regions");
  EXPECT_HAS(msg, "did you mean 'region'");

  p = Parts{};
  p.regions += "veloctiy = [0, 0]\n";
  msg = errorOf(p.text());
  EXPECT_HAS(msg, "unknown key region[0].veloctiy");
  EXPECT_HAS(msg, "did you mean 'velocity'");

  p = Parts{};
  p.physics = "[physics.liquid]\ncolour = \"blue\"\n";
  msg = errorOf(p.text());
  EXPECT_HAS(msg, "unknown key physics.liquid.colour");
  EXPECT_EQ(msg.find("did you mean"), std::string::npos) << msg;
  EXPECT_HAS(msg, "density");  // lists the valid keys
}

TEST(CaseFile, WrongType) {
  Parts p;
  p.numerics += "courant = \"fast\"\n";
  std::string msg = errorOf(p.text());
  EXPECT_HAS(msg, "numerics.courant = \"fast\" has the wrong type (string)");
  EXPECT_HAS(msg, "(0, 1]");

  p = Parts{};
  p.header = "name = 5\ndimension = 2\n";
  msg = errorOf(p.text());
  EXPECT_HAS(msg, "case.name = 5 has the wrong type (integer)");
  EXPECT_HAS(msg, "non-empty string");

  p = Parts{};
  p.numerics += "solver_max_iterations = 10.5\n";
  msg = errorOf(p.text());
  EXPECT_HAS(msg, "numerics.solver_max_iterations");
  EXPECT_HAS(msg, "[1, 100000]");

  p = Parts{};
  p.domain = "min = [0.0, \"a\"]\nmax = [1.0, 1.0]\n";
  msg = errorOf(p.text());
  EXPECT_HAS(msg, "domain.min[1] = \"a\" has the wrong type");

  p = Parts{};
  p.regions = "[region]\nname = \"w\"\n";
  msg = errorOf(p.text());
  EXPECT_HAS(msg, "region = ");
  EXPECT_HAS(msg, "[[region]]");
}

TEST(CaseFile, WrongArrayLength) {
  Parts p;
  p.domain = "min = [0.0, 0.0, 0.0]\nmax = [1.0, 1.0]\n";
  std::string msg = errorOf(p.text());
  EXPECT_HAS(msg, "domain.min = [0, 0, 0] has 3 elements");
  EXPECT_HAS(msg, "exactly 2 numbers");

  p = Parts{};
  p.physics = "[physics]\ngravity = [0.0, 0.0, -9.81]\n";
  msg = errorOf(p.text());
  EXPECT_HAS(msg, "physics.gravity");
  EXPECT_HAS(msg, "exactly 2 numbers");
}

TEST(CaseFile, OutOfRange) {
  Parts p;
  p.numerics += "courant = 1.5\n";
  EXPECT_EQ(errorOf(p.text()), "cases/x.toml: numerics.courant = 1.5 is out of range; allowed (0, 1]");

  struct Bad {
    std::string Parts::*section;
    std::string line, path, allowed;
  };
  const Bad cases[] = {
      {&Parts::numerics, "particle_spacing = 0", "numerics.particle_spacing = 0", "(0, 10]"},
      {&Parts::numerics, "radius_number_density = 1", "numerics.radius_number_density = 1", "[1.5, 5]"},
      {&Parts::numerics, "radius_laplacian = 5.5", "numerics.radius_laplacian = 5.5", "[1.5, 5]"},
      {&Parts::numerics, "dt_max = 2", "numerics.dt_max = 2", "(0, 1]"},
      {&Parts::numerics, "dt_min = 0.01", "numerics.dt_min = 0.01", "(0, numerics.dt_max = 0.001)"},
      {&Parts::numerics, "surface_threshold = 1", "numerics.surface_threshold = 1", "(0, 1)"},
      {&Parts::numerics, "collision_distance = 1", "numerics.collision_distance = 1", "[0, 1)"},
      {&Parts::numerics, "collision_restitution = -0.1", "numerics.collision_restitution = -0.1", "[0, 1]"},
      {&Parts::numerics, "solver_tolerance = 0.1", "numerics.solver_tolerance = 0.1", "(0, 0.01]"},
      {&Parts::numerics, "solver_max_iterations = 0", "numerics.solver_max_iterations = 0", "[1, 100000]"},
      {&Parts::numerics, "max_escaped_fraction = 0", "numerics.max_escaped_fraction = 0", "(0, 1]"},
      {&Parts::numerics, "pressure_solver = \"cg\"", "numerics.pressure_solver = \"cg\"", "\"iccg\" or \"amg\""},
      {&Parts::output, "interval = 2", "output.interval = 2", "(0, output.end_time = 1]"},
      {&Parts::physics, "[physics.liquid]\ndensity = 0", "physics.liquid.density = 0", "(0, 100000]"},
      {&Parts::physics, "[physics.liquid]\nkinematic_viscosity = 2", "physics.liquid.kinematic_viscosity = 2",
       "[0, 1]"},
      {&Parts::physics, "[physics.liquid]\nsound_speed = -1", "physics.liquid.sound_speed = -1",
       "a number > 0 or the string \"inf\""},
      {&Parts::physics, "[physics.liquid]\nsound_speed = \"fast\"", "physics.liquid.sound_speed = \"fast\"",
       "a number > 0 or the string \"inf\""},
      {&Parts::header, "dimension = 4", "case.dimension = 4", "2 or 3"},
      {&Parts::regions, "material = \"steel\"", "region[0].material = \"steel\"", "\"water\" or \"wall\""},
      {&Parts::domain, "", "domain.max[0] = 0", "> domain.min[0] = 0"},
  };
  for (const Bad& b : cases) {
    Parts q;
    if (b.section == &Parts::header) q.header = "name = \"t\"\n";
    if (b.line.rfind("particle_spacing", 0) == 0) q.numerics = "";
    if (b.section == &Parts::domain) q.domain = "min = [0.0, 0.0]\nmax = [0.0, 1.0]\n";
    q.*b.section += b.line + "\n";
    const std::string msg = errorOf(q.text());
    EXPECT_HAS(msg, b.path);
    EXPECT_HAS(msg, "allowed " + b.allowed);
  }
}

TEST(CaseFile, MissingRequiredKey) {
  Parts p;
  p.header = "dimension = 2\n";
  EXPECT_HAS(errorOf(p.text()), "missing required key case.name; allowed a non-empty string");
  p = Parts{};
  p.header = "name = \"t\"\n";
  EXPECT_HAS(errorOf(p.text()), "missing required key case.dimension; allowed 2 or 3");
  p = Parts{};
  p.domain = "max = [1.0, 1.0]\n";
  EXPECT_HAS(errorOf(p.text()), "missing required key domain.min; allowed an array of exactly 2 numbers");
  p = Parts{};
  p.numerics = "courant = 0.1\n";
  EXPECT_HAS(errorOf(p.text()), "missing required key numerics.particle_spacing; allowed a number in (0, 10]");
  p = Parts{};
  p.output = "interval = 0.1\n";
  EXPECT_HAS(errorOf(p.text()), "missing required key output.end_time");
  p = Parts{};
  p.regions = "[[region]]\nname = \"w\"\nmax = [0.5, 0.5]\n";
  EXPECT_HAS(errorOf(p.text()), "missing required key region[0].min");
  p = Parts{};
  p.regions = "[[region]]\nmin = [0.0, 0.0]\nmax = [0.5, 0.5]\n";
  EXPECT_HAS(errorOf(p.text()), "missing required key region[0].name");
  p = Parts{};
  p.regions = "";
  const std::string msg = errorOf(p.text());
  EXPECT_HAS(msg, "missing required key region");
  EXPECT_HAS(msg, "[[region]]");
}

TEST(CaseFile, DuplicateRegionName) {
  Parts p;
  p.regions += "[[region]]\nname = \"w\"\nmaterial = \"wall\"\nmin = [0.5, 0.0]\nmax = [1.0, 1.0]\n";
  const std::string msg = errorOf(p.text());
  EXPECT_HAS(msg, "region[1].name = \"w\" duplicates region[0].name");
  EXPECT_HAS(msg, "unique");
}

TEST(CaseFile, RegionOutsideDomain) {
  Parts p;
  p.regions = "[[region]]\nname = \"w\"\nmin = [0.0, 0.0]\nmax = [0.5, 1.5]\n";
  const std::string msg = errorOf(p.text());
  EXPECT_HAS(msg, "region[0].max[1] = 1.5 lies outside the domain");
  EXPECT_HAS(msg, "allowed [0, 1]");
}

TEST(CaseFile, RegionMaxNotAboveMin) {
  Parts p;
  p.regions = "[[region]]\nname = \"w\"\nmin = [0.0, 0.5]\nmax = [0.5, 0.5]\n";
  const std::string msg = errorOf(p.text());
  EXPECT_HAS(msg, "region[0].max[1] = 0.5 is not greater than region[0].min[1] = 0.5");
  EXPECT_HAS(msg, "allowed region[0].max > region[0].min");
}

TEST(CaseFile, EmptyRegion) {
  Parts p;  // lattice x = 0.05, 0.15, ...: none in [0.36, 0.44)
  p.regions += "[[region]]\nname = \"thin\"\nmaterial = \"wall\"\nmin = [0.6, 0.36]\nmax = [1.0, 0.44]\n";
  const std::string msg = errorOf(p.text());
  EXPECT_HAS(msg, "region[1] (\"thin\") is empty");
  EXPECT_HAS(msg, "no lattice point");
  EXPECT_HAS(msg, "allowed a box holding at least one point");
}

TEST(CaseFile, WaterOverlapNamesBoth) {
  Parts p;
  p.regions += "[[region]]\nname = \"tank\"\nmaterial = \"wall\"\nmin = [0.4, 0.0]\nmax = [1.0, 1.0]\n";
  std::string msg = errorOf(p.text());
  EXPECT_HAS(msg, "region[1] (\"tank\") overlaps region[0] (\"w\")");
  EXPECT_HAS(msg, "allowed");

  p = Parts{};
  p.regions += "[[region]]\nname = \"w2\"\nmin = [0.3, 0.3]\nmax = [0.7, 0.7]\n";
  msg = errorOf(p.text());
  EXPECT_HAS(msg, "region[1] (\"w2\") overlaps region[0] (\"w\")");

  // Touching boxes and overlapping walls are fine.
  p = Parts{};
  p.regions += "[[region]]\nname = \"a\"\nmaterial = \"wall\"\nmin = [0.5, 0.0]\nmax = [1.0, 0.6]\n"
               "[[region]]\nname = \"b\"\nmaterial = \"wall\"\nmin = [0.5, 0.0]\nmax = [0.8, 1.0]\n";
  EXPECT_NO_THROW(parseCase(p.text(), "t.toml"));
}

TEST(CaseFile, NoWaterRegion) {
  Parts p;
  p.regions = "[[region]]\nname = \"w\"\nmaterial = \"wall\"\nmin = [0.0, 0.0]\nmax = [0.5, 0.5]\n";
  const std::string msg = errorOf(p.text());
  EXPECT_HAS(msg, "region: no region has material = \"water\"");
  EXPECT_HAS(msg, "allowed at least one");
}

TEST(CaseFile, VelocityOnlyForWater) {
  Parts p;
  p.regions += "[[region]]\nname = \"s\"\nmaterial = \"wall\"\nmin = [0.5, 0.5]\nmax = [1.0, 1.0]\n"
               "velocity = [1.0, 0.0]\n";
  EXPECT_HAS(errorOf(p.text()), "region[1].velocity = [1, 0] is not allowed for material = \"wall\"");
}

TEST(CaseFile, MissingFileAndNoFilesCreated) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "mistfall_case_file_test_missing";
  EXPECT_FALSE(fs::exists(dir));
  const fs::path missing = dir / "nothing.toml";
  try {
    loadCaseFile(missing);
    ADD_FAILURE() << "no CaseError";
  } catch (const CaseError& e) {
    EXPECT_HAS(std::string(e.what()), missing.string());
    EXPECT_HAS(std::string(e.what()), "does not exist");
  }
  EXPECT_FALSE(fs::exists(dir));

  std::set<fs::path> before, after;
  for (const auto& e : fs::directory_iterator(fs::current_path())) before.insert(e.path());
  parseCase(Parts{}.text(), "t.toml");
  loadCaseFile(source("cases/dam_break.toml"));
  for (const auto& e : fs::directory_iterator(fs::current_path())) after.insert(e.path());
  EXPECT_EQ(before, after);
}

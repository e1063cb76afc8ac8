// Tests of what a case file must satisfy before a run directory is touched: names that become file names
// (case.name) are names, the size of a case is estimated from its regions' volumes and a case that cannot fit
// in memory is refused at once, and the fingerprint a checkpoint carries tells the edits that change the
// simulation from the harmless ones.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "case/case_file.hpp"
#include "case/case_fingerprint.hpp"
#include "case/case_size.hpp"
#include "case/scene.hpp"
#include "support/case_text.hpp"
#include "support/dam_break_case.hpp"

using namespace mistfall;

using test_support::errorOf;
using test_support::Parts;

namespace {

// ---------------------------------------------------------------------------------------------------------
// Names

struct BadName {
  const char* toml;  // the value as written in the case file
  const char* why;
};

TEST(CaseNames, NamesThatAreNotFileNamesAreRefusedNamingTheKey) {
  const BadName bad[] = {
      {R"("../../../X")", "contains a path separator"}, {R"("a/b")", "contains a path separator"},
      {R"("a\\b")", "contains a path separator"},       {R"("..")", "contains '..'"},
      {R"("x..y")", "contains '..'"},                   {R"(".")", "is '.'"},
      {R"("")", "is empty"},                            {R"("two\nlines")", "contains a control character"},
      {R"("tab\there")", "contains a control character"}};
  for (const BadName& b : bad) {
    SCOPED_TRACE(b.toml);
    Parts p;
    p.header = std::string("name = ") + b.toml + "\ndimension = 2\n";
    const std::string msg = errorOf(p.text());
    EXPECT_HAS(msg, "case.name = ");
    EXPECT_HAS(msg, b.why);
    EXPECT_HAS(msg, "usable as a file name");
  }
  Parts p;
  p.header = "name = \"" + std::string(201, 'a') + "\"\ndimension = 2\n";
  EXPECT_HAS(errorOf(p.text()), "is 201 bytes long");
}

TEST(CaseNames, OrdinaryNamesAreKept) {
  for (const char* name : {"dam_break", "Waterfall 5 mm", "run-2.b", "été"}) {
    Parts p;
    p.header = std::string("name = \"") + name + "\"\ndimension = 2\n";
    EXPECT_EQ(name, parseCase(p.text(), "t.toml").name);
  }
}

// ---------------------------------------------------------------------------------------------------------
// Size

// Fluid from the regions' volumes is exact for boxes that do not overlap; walls are counted per region.
TEST(CaseSize, EstimateMatchesTheLatticeOfTheDamBreak) {
  const CaseConfig c = parseCase(test_support::damBreakCase(), "t.toml");
  const CaseSize s = estimateCaseSize(c);
  const Particles<2> p = buildParticles<2>(c);
  EXPECT_EQ(s.fluid, static_cast<double>(p.count(ParticleKind::Fluid)));
  const double solid = static_cast<double>(p.count(ParticleKind::Wall) + p.count(ParticleKind::Dummy));
  EXPECT_GE(s.solid, solid);
  EXPECT_LE(s.solid, 1.2 * solid);  // the corners of the walls, counted twice
  EXPECT_GT(s.bytes, 64e6);
}

TEST(CaseSize, ACircleCountsItsArea) {
  Parts p;
  p.numerics = "particle_spacing = 0.01\n";
  p.regions = "[[region]]\nname = \"drop\"\nshape = \"circle\"\ncenter = [0.5, 0.5]\nradius = 0.2\n";
  const CaseConfig c = parseCase(p.text(), "t.toml");
  const double lattice = static_cast<double>(buildParticles<2>(c).size());
  EXPECT_NEAR(estimateCaseSize(c).fluid, lattice, 0.02 * lattice);
}

TEST(CaseSize, AvailableMemoryIsKnownOnLinux) {
  const auto m = availableMemory();
  ASSERT_TRUE(m.has_value());
  EXPECT_GT(*m, 1e6);
}

// The issue's probe: l0 = 1e-6 spent 5 minutes in region validation, then died of std::bad_alloc. Now it is
// refused at once, naming the count, the estimate and what is available.
TEST(CaseSize, ACaseThatCannotFitIsRefusedAtOnce) {
  Parts p;
  p.numerics = "particle_spacing = 1e-6\n";
  const auto start = std::chrono::steady_clock::now();
  std::string msg;
  try {
    parseCase(p.text(), "cases/huge.toml");
    ADD_FAILURE() << "no ResourceError";
  } catch (const ResourceError& e) {
    msg = e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  EXPECT_HAS(msg, "cases/huge.toml: the case needs about 2.5e11 particles");
  EXPECT_HAS(msg, "numerics.particle_spacing = 1e-6");
  EXPECT_HAS(msg, "TB of memory");
  EXPECT_HAS(msg, "is available (MemAvailable");
}

TEST(CaseSize, BytesAreWrittenForPeople) {
  EXPECT_EQ("512 bytes", formatBytes(512));
  EXPECT_EQ("1.5 kB", formatBytes(1500));
  EXPECT_EQ("820 MB", formatBytes(820e6));
  EXPECT_EQ("106 TB", formatBytes(1.06e14));
}

// ---------------------------------------------------------------------------------------------------------
// Fingerprint

TEST(CaseFingerprint, SameValuesWrittenDifferentlyAreTheSame) {
  const std::string a = caseFingerprint(Parts{}.text(), "a.toml");
  Parts p;
  p.numerics = "particle_spacing = 0.10\n";
  p.output = "end_time = 1\n";
  EXPECT_EQ(a, caseFingerprint(p.text(), "b.toml"));
  EXPECT_TRUE(compareFingerprints(a, caseFingerprint(p.text(), "b.toml")).empty());
}

struct Edit {
  const char* label;
  std::string Parts::*section;
  const char* from;  // text in the section, replaced by `to` ("" from: `to` appended)
  const char* to;
  const char* key;   // the key reported changed
  bool harmless;
};

TEST(CaseFingerprint, EachEditIsNamedAndClassified) {
  const Edit edits[] = {
      {"end_time", &Parts::output, "end_time = 1.0", "end_time = 3.0", "output.end_time", true},
      {"name", &Parts::header, "name = \"t\"", "name = \"u\"", "case.name", true},
      {"region name", &Parts::regions, "name = \"w\"", "name = \"v\"", "region[0].name", true},
      {"classify", &Parts::output, "", "[classify]\nsurface_gradient = 0.5\n", "classify.surface_gradient", true},
      {"texture", &Parts::output, "", "[texture]\nseed = 7\n", "texture.seed", true},
      {"render", &Parts::output, "", "[render]\nimage_width = 320\n", "render.image_width", true},
      {"dt_min", &Parts::numerics, "", "dt_min = 1e-9\n", "numerics.dt_min", true},
      {"escaped", &Parts::numerics, "", "max_escaped_fraction = 0.5\n", "numerics.max_escaped_fraction", true},
      {"l0", &Parts::numerics, "0.1", "0.05", "numerics.particle_spacing", false},
      {"density", &Parts::physics, "", "[physics.liquid]\ndensity = 998.0\n", "physics.liquid.density", false},
      {"courant", &Parts::numerics, "", "courant = 0.1\n", "numerics.courant", false},
      {"interval", &Parts::output, "", "interval = 0.05\n", "output.interval", false},
      {"field grid", &Parts::output, "", "field_spacing = 0.1\n", "output.field_spacing", false},
      {"domain", &Parts::domain, "max = [1.0, 1.0]", "max = [1.0, 2.0]", "domain.max", false},
      {"region", &Parts::regions, "max = [0.5, 0.5]", "max = [0.5, 0.6]", "region[0].max", false},
      {"dimension", &Parts::header, "dimension = 2", "dimension = 3", "case.dimension", false},
      {"a key numerics does not know yet", &Parts::numerics, "", "future_key = 1\n", "numerics.future_key", false},
  };
  const std::string before = caseFingerprint(Parts{}.text(), "a.toml");
  for (const Edit& e : edits) {
    SCOPED_TRACE(e.label);
    Parts p;
    std::string& section = p.*(e.section);
    if (*e.from) {
      const auto at = section.find(e.from);
      ASSERT_NE(at, std::string::npos);
      section.replace(at, std::string(e.from).size(), e.to);
    } else {
      section += e.to;
    }
    const auto changes = compareFingerprints(before, caseFingerprint(p.text(), "b.toml"));
    ASSERT_EQ(1u, changes.size());
    EXPECT_EQ(e.key, changes[0].key);
    EXPECT_EQ(e.harmless, changes[0].harmless);
    EXPECT_EQ(e.harmless, !changesTheSimulation(e.key));
  }
}

TEST(CaseFingerprint, ADescriptionGivesBothValues) {
  Parts p;
  p.numerics = "particle_spacing = 0.05\n";
  const auto changes = compareFingerprints(caseFingerprint(Parts{}.text(), "a"), caseFingerprint(p.text(), "b"));
  ASSERT_EQ(1u, changes.size());
  EXPECT_EQ("numerics.particle_spacing = 0.1 in the checkpoint, 0.05 in case.toml", describe(changes[0]));
}

}  // namespace

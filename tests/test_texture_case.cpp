// The [texture] table of a case file: defaults, every key read, and errors that name the key, the value and the
// allowed range (unknown keys get a suggestion).
#include <gtest/gtest.h>

#include "support/case_text.hpp"

using namespace mistfall;
using test_support::errorOf;
using test_support::Parts;

namespace {

std::string withTexture(const std::string& lines) { return Parts{}.text() + "[texture]\n" + lines; }

}  // namespace

TEST(TextureCase, DefaultsWithoutTheTable) {
  const CaseConfig c = parseCase(Parts{}.text(), "cases/x.toml");
  EXPECT_EQ(c.texture.seed, 1);
  EXPECT_EQ(c.texture.fine_diameter, 7.5e-5);
  EXPECT_EQ(c.texture.representatives_per_source, 500);
  EXPECT_EQ(c.texture.representative_ratio, 1.0 / 250);
  EXPECT_EQ(c.texture.source_diameter, 0.1);  // numerics.particle_spacing
  EXPECT_EQ(c.texture.added_mass, 0.5);
  EXPECT_EQ(c.texture.fluctuation, FluctuationModel::Redrawn);
}

TEST(TextureCase, ReadsEveryKey) {
  const CaseConfig c = parseCase(withTexture("seed = 42\nfine_diameter = 1e-4\nrepresentatives_per_source = 100\n"
                                             "representative_ratio = 0.01\nsource_diameter = 0.004\n"
                                             "source_lifetime = 0.2\nadded_mass = 0.0\nwidth = 0.3\n"
                                             "fluctuation = \"langevin\"\nlangevin_time_scale = 0.3\n"
                                             "time_step = 5e-4\nmatch_radius = 2.0\nbirth_grace = 0.1\n"),
                                 "cases/x.toml");
  const TextureConfig& t = c.texture;
  EXPECT_EQ(t.seed, 42);
  EXPECT_EQ(t.fine_diameter, 1e-4);
  EXPECT_EQ(t.representatives_per_source, 100);
  EXPECT_EQ(t.representative_ratio, 0.01);
  EXPECT_EQ(t.source_diameter, 0.004);
  EXPECT_EQ(t.source_lifetime, 0.2);
  EXPECT_EQ(t.added_mass, 0.0);
  EXPECT_EQ(t.width, 0.3);
  EXPECT_EQ(t.fluctuation, FluctuationModel::Langevin);
  EXPECT_EQ(t.langevin_time_scale, 0.3);
  EXPECT_EQ(t.time_step, 5e-4);
  EXPECT_EQ(t.match_radius, 2.0);
  EXPECT_EQ(t.birth_grace, 0.1);
}

TEST(TextureCase, BadKeysNameKeyValueAndRange) {
  struct Bad {
    std::string line, message;
  };
  const Bad cases[] = {
      {"seed = -1", "texture.seed = -1 is out of range; allowed [0, 2147483647]"},
      {"fine_diameter = 0", "texture.fine_diameter = 0 is out of range; allowed (0, 0.01]"},
      {"representatives_per_source = 0",
       "texture.representatives_per_source = 0 is out of range; allowed [1, 1000000]"},
      {"representative_ratio = 2", "texture.representative_ratio = 2 is out of range; allowed (0, 1]"},
      {"source_diameter = 1e-5", "texture.source_diameter = 1e-5 is out of range; allowed (7.5e-5, 1]"},
      {"source_lifetime = 0", "texture.source_lifetime = 0 is out of range; allowed (0, 1000]"},
      {"added_mass = -0.5", "texture.added_mass = -0.5 is out of range; allowed [0, 10]"},
      {"width = 0", "texture.width = 0 is out of range; allowed (0, 1000]"},
      {"time_step = 0.5", "texture.time_step = 0.5 is out of range; allowed (0, output.interval = 0.01]"},
      {"match_radius = 0", "texture.match_radius = 0 is out of range; allowed (0, 10]"},
      {"birth_grace = -1", "texture.birth_grace = -1 is out of range; allowed [0, 10]"},
  };
  for (const Bad& b : cases) EXPECT_EQ(errorOf(withTexture(b.line + "\n")), "cases/x.toml: " + b.message) << b.line;

  std::string msg = errorOf(withTexture("fluctuation = \"white\"\n"));
  EXPECT_HAS(msg, "texture.fluctuation = \"white\"");
  EXPECT_HAS(msg, "\"redrawn\" or \"langevin\"");

  msg = errorOf(withTexture("fine_diametre = 1e-4\n"));
  EXPECT_HAS(msg, "unknown key texture.fine_diametre");
  EXPECT_HAS(msg, "did you mean 'fine_diameter'");

  msg = errorOf(withTexture("width = \"wide\"\n"));
  EXPECT_HAS(msg, "texture.width = \"wide\" has the wrong type (string)");
}

// texture.inline: off by default; on, it needs the flow grids (output.field_spacing > 0); a boolean.
TEST(TextureCase, InlineNeedsFlowGrids) {
  EXPECT_FALSE(parseCase(Parts{}.text(), "cases/x.toml").texture.run_inline);
  Parts grids;
  grids.output = "end_time = 1.0\nfield_spacing = 0.05\n";
  EXPECT_TRUE(parseCase(grids.text() + "[texture]\ninline = true\n", "cases/x.toml").texture.run_inline);
  EXPECT_FALSE(parseCase(grids.text() + "[texture]\ninline = false\n", "cases/x.toml").texture.run_inline);

  EXPECT_EQ(errorOf(withTexture("inline = true\n")),
            "cases/x.toml: texture.inline = true needs the flow grids, but output.field_spacing = 0 writes none; "
            "allowed output.field_spacing > 0 (or texture.inline = false)");
  EXPECT_HAS(errorOf(withTexture("inline = 1\n")),
             "texture.inline = 1 has the wrong type (integer); allowed true or false");
  EXPECT_HAS(errorOf(withTexture("inlined = true\n")), "did you mean 'inline'");
}

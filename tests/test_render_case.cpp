// The [render] table of a case file: defaults that frame the domain, explicit values, and errors naming the key.
#include <gtest/gtest.h>

#include "support/case_text.hpp"

using namespace mistfall;
using test_support::errorOf;
using test_support::Parts;

TEST(RenderCase, DefaultsFrameTheDomainFromTheFront) {
  const CaseConfig c = parseCase(Parts{}.text(), "x.toml");  // 2D, domain [0,1]^2, l0 = 0.1
  const RenderConfig& r = c.render;
  EXPECT_EQ(r.image_width, 640);
  EXPECT_EQ(r.image_height, 480);
  EXPECT_DOUBLE_EQ(r.extrusion_width, c.texture.width);
  EXPECT_DOUBLE_EQ(r.mist_radius, 0.025);
  EXPECT_DOUBLE_EQ(r.camera_look_at[0], 0.5);
  EXPECT_DOUBLE_EQ(r.camera_look_at[1], 0.5);
  EXPECT_DOUBLE_EQ(r.camera_look_at[2], 0.0);
  EXPECT_GT(r.camera_location[2], 1.0);  // 2D: in front, on +z, looking back at the x-y plane
  EXPECT_GT(r.camera_location[1], 0.5);  // a little from above
  EXPECT_GT(r.light_location[1], 1.0);
}

TEST(RenderCase, ExplicitValuesAreKept) {
  Parts p;
  p.output += "[render]\ncamera_location = [1.0, 2.0, 3.0]\ncamera_look_at = [0.0, 0.5, 0.0]\ncamera_angle = 30\n"
              "image_width = 320\nimage_height = 200\npreview_width = 64\npreview_height = 48\n"
              "extrusion_width = 0.2\nframe_rate = 10\n";
  const RenderConfig r = parseCase(p.text(), "x.toml").render;
  EXPECT_DOUBLE_EQ(r.camera_location[2], 3.0);
  EXPECT_DOUBLE_EQ(r.camera_look_at[1], 0.5);
  EXPECT_DOUBLE_EQ(r.camera_angle, 30.0);
  EXPECT_EQ(r.image_width, 320);
  EXPECT_EQ(r.preview_height, 48);
  EXPECT_DOUBLE_EQ(r.extrusion_width, 0.2);
  EXPECT_DOUBLE_EQ(r.frame_rate, 10.0);
}

TEST(RenderCase, BadValuesNameTheKeyAndTheRange) {
  auto with = [](const std::string& table) {
    Parts p;
    p.output += "[render]\n" + table;
    return errorOf(p.text());
  };
  EXPECT_HAS(with("camera_angle = 180\n"), "render.camera_angle");
  EXPECT_HAS(with("image_width = 8\n"), "[16, 8192]");
  EXPECT_HAS(with("extrusion_width = 0\n"), "render.extrusion_width");
  EXPECT_HAS(with("camera_location = [1.0, 2.0]\n"), "render.camera_location");
  EXPECT_HAS(with("camera_location = [0.5, 0.5, 0.0]\n"), "render.camera_look_at");
  EXPECT_HAS(with("colour = 1\n"), "render.colour");
}

TEST(RenderCase, StyleVolumesAndFramesHaveDefaultsAndChecks) {
  Parts p;
  const CaseConfig c = parseCase(p.text(), "x.toml");
  EXPECT_EQ(c.render.style, RenderStyle::Natural);
  EXPECT_DOUBLE_EQ(c.render.frame_interval, c.output.interval);
  EXPECT_DOUBLE_EQ(c.render.mist_voxel, c.numerics.particle_spacing);
  EXPECT_DOUBLE_EQ(c.render.sheet_variation, 0.3 * c.numerics.particle_spacing);
  EXPECT_TRUE(c.render.mist);
  EXPECT_TRUE(c.render.white_water);
  EXPECT_TRUE(c.render.hidden_regions.empty());
  EXPECT_DOUBLE_EQ(c.render.bank_width, 0.5);  // half the domain's larger extent
  p.output += "[render]\nstyle = \"lab\"\nframe_interval = 0.1\nmist = false\nsheet_variation = 0\n";
  const RenderConfig r = parseCase(p.text(), "x.toml").render;
  EXPECT_EQ(r.style, RenderStyle::Lab);
  EXPECT_DOUBLE_EQ(r.frame_interval, 0.1);
  EXPECT_FALSE(r.mist);
  auto with = [](const std::string& table) {
    Parts q;
    q.output += "[render]\n" + table;
    return errorOf(q.text());
  };
  EXPECT_HAS(with("style = \"photo\"\n"), "render.style");
  EXPECT_HAS(with("hiden_regions = []\n"), "did you mean 'hidden_regions'");
  EXPECT_HAS(with("mist_voxl = 0.01\n"), "did you mean 'mist_voxel'");
  EXPECT_HAS(with("hidden_regions = [\"lid\"]\n"), "not a wall region");
  EXPECT_HAS(with("hidden_regions = \"lid\"\n"), "render.hidden_regions");
  EXPECT_HAS(with("frame_interval = 0\n"), "render.frame_interval");
}

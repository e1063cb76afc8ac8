// The optional [texture] table of a case file: the parameters of the sub-particle-scale texture stage
// (`mistfall texture`, src/texture; every key, default and range in docs/case-file.md).
#include "case/case_config.hpp"
#include "case/toml_reader.hpp"

namespace mistfall::detail {

void readTexture(const Reader& rd, const toml::table& root, CaseConfig& c) {
  const std::string p = "texture";
  TextureConfig& x = c.texture;
  x.source_diameter = c.numerics.particle_spacing;
  if (!root.get(p)) return;
  const toml::table& t = rd.table(root, "", p);
  rd.checkKeys(t, p,
               {"seed", "fine_diameter", "representatives_per_source", "representative_ratio", "source_diameter",
                "source_lifetime", "added_mass", "width", "fluctuation", "langevin_time_scale", "time_step",
                "match_radius", "birth_grace", "inline", "file_interval", "vtp"});
  rd.integer(t, p, "seed", 0, 2147483647, "[0, 2147483647]", x.seed);
  rd.number(t, p, "fine_diameter", {0.0, 1e-2, true, false}, x.fine_diameter);
  rd.integer(t, p, "representatives_per_source", 1, 1000000, "[1, 1000000]", x.representatives_per_source);
  rd.number(t, p, "representative_ratio", {0.0, 1.0, true, false}, x.representative_ratio);
  rd.number(t, p, "source_diameter", {x.fine_diameter, 1.0, true, false},
            x.source_diameter);
  rd.number(t, p, "source_lifetime", {0.0, 1e3, true, false}, x.source_lifetime);
  rd.number(t, p, "added_mass", {0.0, 10.0, false, false}, x.added_mass);
  rd.number(t, p, "width", {0.0, 1e3, true, false}, x.width);
  if (int s = rd.choice(t, p, "fluctuation", {"redrawn", "langevin"}); s >= 0)
    x.fluctuation = s == 0 ? FluctuationModel::Redrawn : FluctuationModel::Langevin;
  rd.number(t, p, "langevin_time_scale", {0.0, 100.0, true, false}, x.langevin_time_scale);
  rd.number(t, p, "time_step", {0.0, c.output.interval, true, false, "output.interval"}, x.time_step);
  rd.number(t, p, "match_radius", {0.0, 10.0, true, false}, x.match_radius);
  rd.number(t, p, "birth_grace", {0.0, 10.0, false, false}, x.birth_grace);
  rd.boolean(t, p, "inline", x.run_inline);
  rd.number(t, p, "file_interval", {0.0, c.output.end_time, false, false, "output.end_time"}, x.file_interval);
  rd.boolean(t, p, "vtp", x.write_vtp);
  if (x.run_inline && !(c.output.field_spacing > 0.0))
    rd.fail("texture.inline = true needs the flow grids, but output.field_spacing = 0 writes none; allowed "
            "output.field_spacing > 0 (or texture.inline = false)");
}

}  // namespace mistfall::detail

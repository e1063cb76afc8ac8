// mistfall command line: `mistfall simulate CASE.toml --out DIR` and friends. `mistfall --help` lists them.
#include <CLI/CLI.hpp>

#include <iostream>

#include "cli/simulate.hpp"
#include "cli/texture_command.hpp"

int main(int argc, char** argv) {
  CLI::App app{"mistfall — physically based waterfall animation from a gas-liquid two-phase MPS simulation"};
  app.set_version_flag("--version", std::string("mistfall ") + MISTFALL_VERSION);
  app.require_subcommand(1);

  mistfall::SimulateOptions sim;
  std::filesystem::path resume_dir;
  auto* simulate = app.add_subcommand(
      "simulate", "Run the MPS simulation of a case: frames (VTK .vtp + .pvd), diagnostics.csv, checkpoints");
  simulate->add_option("case", sim.case_file, "Case file (TOML); see docs/case-file.md")->check(CLI::ExistingFile);
  simulate->add_option("--out,-o", sim.out_dir, "Run directory to write (created; must be new or empty)");
  simulate->add_option("--until", sim.until, "Stop at this simulated time [s] (default: output.end_time)");
  simulate->add_option("--threads,-j", sim.threads, "OpenMP threads (default: all cores)")->check(CLI::Range(1, 4096));
  simulate->add_flag("--ascii", sim.ascii, "Write ASCII VTK files instead of binary");
  simulate->add_option("--resume", resume_dir, "Continue the run in this directory from its last checkpoint")
      ->check(CLI::ExistingDirectory);
  simulate->add_flag("--overwrite", sim.overwrite, "Replace the contents of an existing run directory");
  simulate->add_flag("--plain-progress", sim.force_plain_progress, "Log progress lines instead of a progress bar");

  mistfall::TextureOptions tex;
  auto* texture = app.add_subcommand(
      "texture",
      "Sub-particle-scale texture of a classified run: droplet/bubble sources shedding mist and micro-bubbles, "
      "moved by eq. (18) through the saved flow fields; writes RUN_DIR/texture/ (.bin, .vtp, .pvd, texture.csv)");
  texture->add_option("run_dir", tex.run_dir,
                      "Run directory of `mistfall simulate` (with output.field_spacing > 0), classified by "
                      "`mistfall classify`; parameters from the [texture] table of its case.toml")
      ->required()
      ->check(CLI::ExistingDirectory);
  texture->add_option("--threads,-j", tex.threads, "OpenMP threads (default: all cores); results do not depend on N")
      ->check(CLI::Range(1, 4096));
  texture->add_flag("--ascii", tex.ascii, "Write ASCII VTK files instead of binary");
  texture->add_flag("--overwrite", tex.overwrite, "Replace an existing RUN_DIR/texture");
  texture->add_flag("--plain-progress", tex.force_plain_progress, "Log progress lines instead of a progress bar");

  // Command-line errors are bad input: exit code 1 like every other input error (CLI11 would use 100+).
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 1;
  }

  if (simulate->parsed()) {
    if (!resume_dir.empty()) {
      if (!sim.case_file.empty()) {
        std::cerr << "mistfall: give either a case file or --resume DIR, not both (a run directory holds its case)\n";
        return 1;
      }
      sim.resume = true;
      sim.out_dir = resume_dir;
    } else if (sim.case_file.empty() || sim.out_dir.empty()) {
      std::cerr << "mistfall simulate: need CASE.toml and --out DIR (or --resume DIR); see --help\n";
      return 1;
    }
    return mistfall::runSimulate(sim);
  }
  if (texture->parsed()) return mistfall::runTexture(tex);
  return 0;
}

// mistfall command line: `mistfall simulate CASE.toml --out DIR`, `mistfall classify RUN_DIR`, `mistfall texture
// RUN_DIR`, `mistfall render RUN_DIR`, `mistfall run CASE.toml --out DIR` (all four). `mistfall --help` lists them.
#include <CLI/CLI.hpp>

#include <iostream>

#include "cli/classify.hpp"
#include "cli/exit_codes.hpp"
#include "cli/openmp_runtime.hpp"
#include "cli/render_command.hpp"
#include "cli/run_command.hpp"
#include "cli/simulate.hpp"
#include "cli/texture_command.hpp"
#include "io/data_files.hpp"

int main(int argc, char** argv) {
  mistfall::useShortOpenMpSpin(argv);
  CLI::App app{"mistfall — physically based waterfall animation from a gas-liquid two-phase MPS simulation"};
  app.set_version_flag("--version", std::string("mistfall ") + MISTFALL_VERSION);
  app.require_subcommand(1);

  mistfall::SimulateOptions sim;
  std::filesystem::path resume_dir;
  auto* simulate = app.add_subcommand(
      "simulate", "Run the MPS simulation of a case: frames (VTK .vtp + .pvd), diagnostics.csv, checkpoints");
  simulate->add_option("case", sim.case_file, "Case file (TOML); see docs/case-file.md")->check(CLI::ExistingFile);
  simulate->add_option("--out,-o", sim.out_dir, "Run directory to write (created; must be new or empty)");
  simulate->add_option("--until", sim.until, "Stop at this simulated time [s], at most output.end_time (default: it)");
  simulate->add_option("--threads,-j", sim.threads, "OpenMP threads (default: all cores)")->check(CLI::Range(1, 4096));
  simulate->add_flag("--ascii", sim.ascii, "Write ASCII VTK files instead of binary");
  auto* resume = simulate->add_option("--resume", resume_dir,
                                      "Continue the run in this directory from its last checkpoint")
                     ->check(CLI::ExistingDirectory);
  simulate->add_flag("--overwrite", sim.overwrite, "Replace the contents of an existing run directory");
  simulate->add_flag("--plain-progress", sim.force_plain_progress, "Log progress lines instead of a progress bar");
  auto* trace = simulate->add_option("--trace", sim.trace_id,
                                     "Developers: write particle ID and its neighbours within l0 after every stage "
                                     "of each step to RUN_DIR/traces/trace_ID.csv (src/mps/particle_trace.hpp)");
  simulate->add_option("--trace-from", sim.trace_from, "With --trace: from the step that starts at this time [s]")
      ->needs(trace)
      ->check(CLI::NonNegativeNumber);
  simulate->add_flag("--accept-case-change", sim.accept_case_change,
                     "Developers, with --resume: go on although case.toml changed in what it simulates (a what-if "
                     "from a copy of a run's checkpoint); the changes are listed and recorded in "
                     "RUN_DIR/case_changes.txt (output.interval cannot change: the frames are numbered by it)")
      ->needs(resume);
  simulate->footer(
      "Every frame carries the six-category `category` array. With output.field_spacing > 0 every frame also\n"
      "writes its flow grid fields/fields_NNNNN.vti, and with `inline = true` in the case's [texture] table the\n"
      "texture stage runs inline: RUN_DIR/texture/ (the files of `mistfall texture RUN_DIR`, byte for byte the\n"
      "same) at every frame; --resume rebuilds the cloud from the saved frames first. docs/texture.md.\n"
      "--resume refuses a checkpoint written for another case: a change of case.toml that changes the simulation\n"
      "(dimension, domain, physics, numerics, output.interval and field_spacing, regions, inflows, outflows,\n"
      "vents); output.end_time, [classify], [texture], [render] and names may change (--accept-case-change lets the\n"
      "rest change too, on a copy of a run, and records it in case_changes.txt). A case that cannot fit in the\n"
      "memory available is refused before anything is written.\n" +
      std::string(mistfall::kExitCodeContract));

  mistfall::ClassifyOptions cls;
  auto* classify = app.add_subcommand(
      "classify", "Classify the particles of every frame of a run into six categories (section 3.1): adds a "
                  "`category` array to the frames, writes categories.csv");
  classify->footer(
      "Categories: 1 liquid bulk, 2 liquid surface, 3 droplet, 4 gas bulk, 5 gas surface, 6 bubble; 0 for walls,\n"
      "dummies, escaped and inflow particles; 6 for an entrained bubble point (numerics.entrained_bubble_diameter).\n"
      "Liquid and gas are classified separately from the number density of\n"
      "their own particles (plus walls) and its gradient; the thresholds are the case's [classify] table\n"
      "(docs/case-file.md), read from RUN_DIR/case.toml. Each RUN_DIR/frames/frame_NNNNN.vtp is rewritten in place\n"
      "(atomically, same format, the arrays simulate writes kept bit for bit); RUN_DIR/categories.csv gets one\n"
      "row per frame (frame, time, the six counts). Running it again gives the same files. Frames written by\n"
      "`simulate` already carry the array; run classify after changing [classify] in RUN_DIR/case.toml.\n"
      "Every frame is read before the first is rewritten.\n" +
      std::string(mistfall::kExitCodeContract));
  classify->add_option("run_dir", cls.run_dir, "Run directory written by `mistfall simulate` (holds case.toml and frames/)")
      ->required();
  classify->add_option("--threads,-j", cls.threads, "OpenMP threads (default: all cores); results do not depend on N")
      ->check(CLI::Range(1, 4096));
  classify->add_flag("--plain-progress", cls.force_plain_progress, "Log progress lines instead of a progress bar");
  mistfall::TextureOptions tex;
  auto* texture = app.add_subcommand(
      "texture",
      "Sub-particle-scale texture of a run as a post-process (or inline: [texture] inline = true): droplet/bubble sources shedding mist and micro-bubbles, "
      "moved by eq. (18) through the saved flow fields; writes RUN_DIR/texture/ (.bin, .vtp, .pvd, texture.csv)");
  texture->add_option("run_dir", tex.run_dir,
                      "Run directory of `mistfall simulate` (with output.field_spacing > 0; its frames carry the "
                      "`category` array); parameters from the [texture] table of its case.toml")
      ->required()
      ->check(CLI::ExistingDirectory);
  texture->add_option("--threads,-j", tex.threads, "OpenMP threads (default: all cores); results do not depend on N")
      ->check(CLI::Range(1, 4096));
  texture->add_flag("--ascii", tex.ascii, "Write ASCII VTK files instead of binary");
  texture->add_flag("--overwrite", tex.overwrite, "Replace an existing RUN_DIR/texture");
  texture->add_flag("--plain-progress", tex.force_plain_progress, "Log progress lines instead of a progress bar");
  texture->footer(std::string("Every frame and flow grid is read before anything is written.\n") +
                  mistfall::kExitCodeContract);

  mistfall::RenderOptions ren;
  auto* render = app.add_subcommand(
      "render", "Render a run with POV-Ray: water surface meshes, mist and white water as media, one scene per "
                "frame, images (povray, in parallel) and an animation (ffmpeg: RUN_DIR/render/<case>.mp4 and .gif)");
  render->footer(
      "Reads RUN_DIR/case.toml ([render]: style, camera, sun, sizes, frame_interval; docs/case-file.md), the\n"
      "frames, their category array and RUN_DIR/texture/texture_NNNNN.bin (mist, micro-bubbles) when present.\n"
      "Writes RUN_DIR/render/: materials.inc, natural.inc, lab.inc (once; edit them to restyle), per frame\n"
      "mesh_NNNNN.inc, mist_/white_NNNNN.df3 and scene_NNNNN.pov (deleted once the image is done unless\n"
      "--keep-intermediates), png/frame_NNNNN.png (preview/ with --preview), with --export export/water_NNNNN.ply\n"
      "and export/volumes_NNNNN.vdb, log/, timings.csv and the animation. Frames whose image is newer than the\n"
      "frame, its texture file and case.toml are skipped. Needs the Debian packages povray and ffmpeg\n"
      "(docs/render.md).\n" +
      std::string(mistfall::kExitCodeContract));
  render->add_option("run_dir", ren.run_dir, "Run directory written by `mistfall simulate`")->required();
  render->add_flag("--preview", ren.preview, "Small images (render.preview_width x preview_height), no antialiasing");
  render->add_option("--jobs,-j", ren.jobs, "povray processes at once (default: the number of cores)")
      ->check(CLI::Range(1, 4096));
  render->add_option("--povray-threads", ren.povray_threads, "Render threads of each povray process (default 1)")
      ->check(CLI::Range(1, 4096));
  render->add_flag("--keep-intermediates", ren.keep_intermediates,
                   "Keep each frame's scene, mesh include and density files after its image is done");
  render->add_flag("--export", ren.export_files,
                   "Also write export/water_NNNNN.ply and export/volumes_NNNNN.vdb (Blender, Houdini; docs/render.md)");
  render->add_flag("--plain-progress", ren.force_plain_progress, "Log progress lines instead of a progress bar");

  mistfall::RunOptions pipe;
  auto* run = app.add_subcommand(
      "run", "The whole pipeline: simulate (frames classified as written), texture (when the case has "
             "output.field_spacing > 0) and render, into one run directory");
  run->add_option("case", pipe.case_file, "Case file (TOML); see docs/case-file.md")
      ->required()
      ->check(CLI::ExistingFile);
  run->add_option("--out,-o", pipe.out_dir, "Run directory to write (created; must be new or empty)")->required();
  run->add_option("--until", pipe.until, "Stop the simulation at this time [s], at most output.end_time (default: it)");
  run->add_option("--threads", pipe.threads, "OpenMP threads of simulate and texture (default: all cores)")
      ->check(CLI::Range(1, 4096));
  run->add_option("--jobs,-j", pipe.jobs, "povray processes at once (default: the number of cores)")
      ->check(CLI::Range(1, 4096));
  run->add_flag("--preview", pipe.preview, "Render small preview images (see `render --help`)");
  run->add_flag("--keep-intermediates", pipe.keep_intermediates, "Keep the render's scenes, meshes and densities");
  run->add_flag("--export", pipe.export_files, "Render: also write the PLY meshes and OpenVDB volumes");
  run->add_flag("--overwrite", pipe.overwrite, "Replace the contents of an existing run directory");
  run->add_flag("--plain-progress", pipe.force_plain_progress, "Log progress lines instead of progress bars");
  run->footer(std::string("Stops at the first stage that fails, with its exit code.\n") + mistfall::kExitCodeContract);
  const auto data = mistfall::dataDirectory();
  app.footer(std::string("One command at a time works on a run directory (a lock in RUN_DIR/.mistfall.lock).\n") +
             (data ? "Data files (example cases, render includes): " + data->string() + "\n" : std::string()) +
             mistfall::kExitCodeContract);

  // Command-line errors are bad input, like every other input error (CLI11 would use 100+).
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? mistfall::kExitDone : mistfall::kExitBadInput;
  }

  if (simulate->parsed()) {
    if (!resume_dir.empty()) {
      if (!sim.case_file.empty()) {
        std::cerr << "mistfall: give either a case file or --resume DIR, not both (a run directory holds its case)\n";
        return mistfall::kExitBadInput;
      }
      sim.resume = true;
      sim.out_dir = resume_dir;
    } else if (sim.case_file.empty() || sim.out_dir.empty()) {
      std::cerr << "mistfall simulate: need CASE.toml and --out DIR (or --resume DIR); see --help\n";
      return mistfall::kExitBadInput;
    }
    return mistfall::runSimulate(sim);
  }
  if (classify->parsed()) return mistfall::runClassify(cls);
  if (texture->parsed()) return mistfall::runTexture(tex);
  if (render->parsed()) return mistfall::runRender(ren);
  if (run->parsed()) return mistfall::runPipeline(pipe);
  return 0;
}

#include "cli/simulate.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <fstream>
#include <iostream>
#include <sstream>
#include <utility>

#include "case/case_file.hpp"
#include "case/scene.hpp"
#include "case/case_fingerprint.hpp"
#include "cli/classify.hpp"
#include "cli/exit_codes.hpp"
#include "cli/progress.hpp"
#include "cli/resume_check.hpp"
#include "cli/run_directory.hpp"
#include "cli/run_lock.hpp"
#include "cli/step_counts.hpp"
#include "cli/texture_frames.hpp"
#include "io/atomic_file.hpp"
#include "io/bubble_log.hpp"
#include "io/checkpoint.hpp"
#include "io/diagnostics.hpp"
#include "io/errors.hpp"
#include "io/grid_fields.hpp"
#include "io/pvd_collection.hpp"
#include "io/vent_log.hpp"
#include "io/vtk_writer.hpp"
#include "mps/solver.hpp"
#include "mps/sps_turbulence.hpp"

namespace fs = std::filesystem;

namespace mistfall {

namespace {

constexpr const char* kCaseCopy = "case.toml";
constexpr const char* kCheckpoint = "checkpoint.bin";
constexpr const char* kDiagnostics = "diagnostics.csv";
constexpr const char* kCollection = "frames.pvd";
constexpr const char* kBubbles = "bubbles.csv";
constexpr const char* kVents = "vents.csv";  // a case with vents
constexpr const char* kDiverged = "diverged.txt";  // written when the run diverges
constexpr const char* kCaseChanges = "case_changes.txt";  // --accept-case-change: where the case changed

constexpr const char* kTexture = "texture";      // texture.inline = true: the texture stage's files

std::string frameName(int frame) { return "frames/frame_" + frameNumber(frame) + ".vtp"; }

std::string fieldsName(int frame) { return "fields/fields_" + frameNumber(frame) + ".vti"; }

// The flow fields of a frame on a grid of output.field_spacing over the domain (io/grid_fields.hpp): gas and
// liquid velocity and SPS turbulence energy k (eqs. (25)-(26), Ds = l0, each phase from its own particles).
template <int D>
ImageData flowFields(const SimulationState<D>& s, const CaseConfig& config, MpsSolver<D>& solver) {
  const auto& p = s.particles;
  SpsParameters sps;
  sps.ds = config.numerics.particle_spacing;
  std::vector<double> k;
  spsTurbulenceEnergy<D>(p, solver.currentNeighbours(), solver.constants(), sps, k, samePhaseActive(p));
  GridSpec<D> grid;
  for (int a = 0; a < D; ++a) grid.lower[a] = config.domain.min[a], grid.upper[a] = config.domain.max[a];
  grid.cell_size = config.output.field_spacing;
  grid.radius = kGridSamplingRadiusRatio * config.numerics.particle_spacing;
  return sampleFlowFields<D>(grid, p, k, s.time, [&](std::int32_t j) {
    return p.kind[j] == ParticleKind::Fluid || p.kind[j] == ParticleKind::Inflow;
  });
}

std::string readText(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throwCannotOpen(file, "case file");
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) throw std::runtime_error("error while reading " + file.string());
  return s.str();
}

template <int D>
DiagnosticsRow diagnosticsOf(const SimulationState<D>& s, const CaseConfig& config, const StepReport& last,
                             const std::vector<BubbleStats>& bubbles, double wall_seconds, double n0) {
  DiagnosticsRow row;
  row.time = s.time;
  row.step = s.step;
  row.dt = s.dt;
  const double volume = std::pow(config.numerics.particle_spacing, D);  // particle mass = rho l0^D
  measureParticles(row, s.particles, config.physics.liquid.density * volume, config.physics.gas.density * volume);
  measurePhaseVolumes(row, s.particles, config.numerics.particle_spacing, n0, config.numerics.surface_threshold);
  row.ppe_iterations = last.ppe_iterations;
  row.ppe_residual = last.ppe_residual;
  row.wall_seconds = wall_seconds;
  row.gas_ppe_iterations = last.gas_ppe_iterations;
  row.bubbles = bubbles.size();
  const BubbleStats* largest = nullptr;
  for (const auto& b : bubbles)
    if (!largest || b.particles > largest->particles) largest = &b;
  if (largest) {
    row.bubble_particles = largest->particles;
    row.bubble_pressure = largest->mean_pressure;
    row.bubble_x = largest->centroid[0];
    row.bubble_y = largest->centroid[1];
    row.bubble_z = largest->centroid[2];
    row.bubble_size = largest->size;
  }
  row.created = s.created;
  row.removed = s.removed;
  row.vented_in = s.vented_in;
  row.vented_out = s.vented_out;
  return row;
}

// "stage 12.3 s (45 %), ...": the stages of at least 1 % of the total, largest first.
std::string stageSummary(const StageTimer& timer) {
  std::vector<std::pair<double, Stage>> stages;
  for (int k = 0; k < StageTimer::kCount; ++k) stages.emplace_back(timer.seconds(Stage(k)), Stage(k));
  std::sort(stages.begin(), stages.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  const double total = timer.total();
  std::ostringstream s;
  s << std::fixed << std::setprecision(1);
  for (const auto& [seconds, stage] : stages) {
    if (!(total > 0.0) || seconds < 0.01 * total) continue;
    if (s.tellp() > 0) s << ", ";
    s << stageName(stage) << " " << seconds << " s (" << std::lround(100.0 * seconds / total) << " %)";
  }
  return s.str();
}

template <int D>
int run(const CaseConfig& config, const SimulateOptions& options, const std::string& fingerprint) {
  const fs::path dir = options.out_dir;
  SimulationState<D> state;
  double wall_offset = 0.0;
  std::optional<DiagnosticsRow> previous;  // the last row written (open-boundary rates are since it)
  if (options.resume) {
    std::string stored;
    state = readCheckpoint<D>(dir / kCheckpoint, &stored);
    std::string accepted;
    for (const std::string& note :
         checkResume<D>(dir, state, stored, fingerprint, options.accept_case_change ? &accepted : nullptr))
      std::cerr << "mistfall simulate: note: " << note << "\n";
    if (!accepted.empty()) {  // RUN_DIR/case_changes.txt: when the run became another case, and how
      const fs::path record = dir / kCaseChanges;
      const std::string before = fs::exists(record) ? readText(record) : std::string();
      writeFileAtomically(record, [&](std::ostream& out) {
        out << before << "resumed at t = " << std::setprecision(17) << state.time << " s (step " << state.step
            << ") with case.toml changed in what it simulates (--accept-case-change):" << accepted << "\n";
      });
    }
    if (!config.texture.run_inline && fs::exists(dir / kTexture))
      std::cerr << "mistfall simulate: note: " << (dir / kTexture) << " is not extended (texture.inline = false): "
                << "run `mistfall texture " << dir.string() << " --overwrite` when the run is done\n";
    for (const auto& row : DiagnosticsWriter::read(dir / kDiagnostics))
      if (row.time <= state.time + 1e-12) wall_offset = row.wall_seconds, previous = row;
  } else {
    state.particles = buildParticles<D>(config);
  }
  const double end_time = std::min(config.output.end_time, options.until.value_or(config.output.end_time));
  const double interval = config.output.interval;

  MpsSolver<D> solver(config, state);
  if (options.trace_id) {  // RUN_DIR/traces/trace_ID.csv (a developer's tool, particle_trace.hpp)
    fs::create_directories(dir / "traces");
    solver.traceParticle(*options.trace_id, options.trace_from,
                         (dir / "traces" / ("trace_" + std::to_string(*options.trace_id) + ".csv")).string());
  }
  PvdCollection collection(dir / kCollection);
  std::optional<double> resume_time;
  if (options.resume) {
    collection.load();
    collection.truncateAfter(state.time);
    resume_time = state.time;
  }
  DiagnosticsWriter diagnostics(dir / kDiagnostics, resume_time);
  BubbleLog bubble_log(dir / kBubbles, resume_time);
  // vents.csv: each vent's exchange since the last output (a case with vents only).
  std::optional<VentLog> vent_log;
  std::vector<std::int64_t> vent_in(config.vents.size(), 0), vent_out(config.vents.size(), 0);
  std::vector<std::int64_t> vent_liquid(config.vents.size(), 0);
  double vent_since = state.time;  // the last output's time
  if (!config.vents.empty()) {
    std::vector<std::string> names;
    for (const auto& v : config.vents) names.push_back(v.name);
    vent_log.emplace(dir / kVents, names, std::pow(config.numerics.particle_spacing, D), resume_time);
  }
  // texture.inline: the texture of every frame from the in-memory particles, categories and grid; a resumed run
  // first rebuilds the cloud from the saved frames up to the checkpoint (the post-process path, same values).
  std::optional<TextureWriter> texture;
  if (config.texture.run_inline) {
    fs::remove_all(dir / kTexture);
    fs::create_directories(dir / kTexture);
    texture.emplace(config, dir / kTexture, options.ascii);
    if (options.resume) texture->replay<D>(dir, listSavedFrames(dir, state.time));
  }
  const double wall_start = omp_get_wtime();
  StepReport last;
  StepCounts counts;  // the steps' counts since the last output

  auto writeOutput = [&]() {
    // Output and texture are stages of their own: what the solver's timer counts in here (the neighbour list and
    // the bubbles of the frame) is output's.
    const StageTimer solver_stages = solver.stageTimer();
    const double output_start = omp_get_wtime();
    double texture_seconds = 0.0;
    const std::string name = frameName(state.next_frame);
    const std::vector<std::uint8_t> category = categoryBytes(classifyFrame<D>(state.particles, config));
    writeVtp<D>(dir / name, state.particles, state.time, options.ascii, &category);
    collection.add(state.time, name);
    collection.write();
    const auto bubbles = solver.currentBubbles();
    if (config.output.field_spacing > 0.0) {
      const auto grid = std::make_shared<const ImageData>(flowFields<D>(state, config, solver));
      writeVti(dir / fieldsName(state.next_frame), *grid, options.ascii);
      if (texture) {
        const double texture_start = omp_get_wtime();
        texture->frame<D>(frameNumber(state.next_frame), grid, state.particles, category, state.time);
        texture_seconds = omp_get_wtime() - texture_start;
      }
    }
    DiagnosticsRow row = diagnosticsOf(state, config, last, bubbles, wall_offset + omp_get_wtime() - wall_start,
                                       solver.constants().n0);
    counts.moveInto(row);
    if (previous && row.time > previous->time) {
      row.inflow_rate = static_cast<double>(row.created - previous->created) / (row.time - previous->time);
      row.outflow_rate = static_cast<double>(row.removed - previous->removed) / (row.time - previous->time);
    }
    diagnostics.append(row);
    previous = row;
    bubble_log.append(state.time, bubbles);
    if (vent_log) {
      vent_log->append(state.time, state.time - vent_since, vent_in, vent_out, vent_liquid);
      std::fill(vent_liquid.begin(), vent_liquid.end(), 0);
      std::fill(vent_in.begin(), vent_in.end(), 0);
      std::fill(vent_out.begin(), vent_out.end(), 0);
      vent_since = state.time;
    }
    state.next_frame += 1;
    writeCheckpoint<D>(dir / kCheckpoint, state, fingerprint);
    solver.stageTimer() = solver_stages;
    solver.stageTimer().add(Stage::Output, omp_get_wtime() - output_start - texture_seconds);
    if (texture) solver.stageTimer().add(Stage::Texture, texture_seconds);
  };

  if (!options.resume) writeOutput();  // frame 0: the initial state

  ProgressReporter progress(end_time, state.time, std::cerr, options.force_plain_progress);
  const double eps = 1e-9 * interval;
  std::filesystem::remove(dir / kDiverged);  // a resumed run tries again
  try {
    while (state.time < end_time - eps) {
      const double next_output = std::min(end_time, state.next_frame * interval);
      while (state.time < next_output - eps) {
        last = solver.step(next_output);
        counts.add(last);
        for (std::size_t v = 0; v < last.vented_in_by_vent.size() && v < vent_in.size(); ++v)
          vent_in[v] += last.vented_in_by_vent[v], vent_out[v] += last.vented_out_by_vent[v],
          vent_liquid[v] += last.vented_liquid_by_vent[v];
        progress.update(state.time, state.step, state.dt);
      }
      if (std::abs(state.time - state.next_frame * interval) <= eps) writeOutput();
    }
  } catch (const DivergenceError& e) {
    progress.finish();
    // A record of the divergence next to the frames, for the tools (tools/plot_bubble.py) and later stages.
    writeFileAtomically(dir / kDiverged, [&](std::ostream& out) {
      out << std::setprecision(17) << "time = " << e.time() << "\nstep = " << e.step() << "\nreason = " << e.what()
          << "\n\n# The last steps before it (at most " << MpsSolver<D>::kRecentSteps
          << "): dt and the fastest fluid particle when dt was chosen.\n"
          << solver.recentStepsCsv();
    });
    std::cerr << "mistfall simulate: frames up to t = " << (state.next_frame - 1) * interval << " s are kept in "
              << dir << "; " << (dir / kDiverged) << " records the divergence\n";
    throw;  // exit code 3 (exit_codes.cpp)
  }
  progress.finish();
  std::cerr << "mistfall: done, t = " << state.time << " s in " << state.step << " steps, "
            << state.next_frame << " frames in " << (dir / "frames") << "\n";
  std::cerr << "mistfall: wall time by stage: " << stageSummary(solver.stageTimer()) << "\n";
  if (texture && !texture->rows().empty()) {
    const auto& c = texture->rows().back().counts;
    std::cerr << "mistfall: texture in " << (dir / kTexture) << ": " << c[0] << " droplets, " << c[1] << " mist, "
              << c[2] << " bubbles, " << c[3] << " micro-bubbles\n";
  }
  return 0;
}

// --until past the case's output.end_time would stop at end_time without saying so: refused.
static void checkUntil(const SimulateOptions& options, const CaseConfig& config, const fs::path& case_file) {
  if (!options.until || *options.until <= config.output.end_time * (1.0 + 1e-12)) return;
  std::ostringstream message;
  message << "--until " << *options.until << " s is past output.end_time = " << config.output.end_time
          << " s of " << case_file.string() << "; raise output.end_time there (on --resume it may change)";
  throw InputError(message.str());
}

// Everything before the run: the case (validated, its size against the memory), the run directory (free, empty
// or --overwrite), then, for a new run, the directory taken over and the case copied into it.
int simulate(const SimulateOptions& options) {
  const fs::path& dir = options.out_dir;
  if (options.until && !(*options.until > 0.0)) throw InputError("--until must be a positive time in seconds");
  CaseConfig config;
  std::string case_text;
  std::optional<RunDirLock> lock;
  if (options.resume) {
    if (!fs::is_directory(dir)) throw InputError("cannot resume: run directory " + dir.string() + " does not exist");
    if (!fs::exists(dir / kCheckpoint))
      throw InputError("cannot resume: " + (dir / kCheckpoint).string() + " does not exist");
    lock.emplace(dir, "simulate");
    config = loadCaseFile(dir / kCaseCopy);
    checkUntil(options, config, dir / kCaseCopy);
    case_text = readText(dir / kCaseCopy);
    const int dim = checkpointDimension(dir / kCheckpoint);
    if (dim != config.dimension)
      throw InputError("cannot resume: checkpoint is " + std::to_string(dim) + "D but the case is " +
                       std::to_string(config.dimension) + "D");
  } else {
    config = loadCaseFile(options.case_file);
    checkUntil(options, config, options.case_file);
    if (dir.empty()) throw InputError("no output directory given (--out DIR)");
    checkOutputPath(dir);
    if (fs::exists(dir)) RunDirLock::checkFree(dir);
    auto checkEmpty = [&] {
      if (!options.overwrite && !isEmptyRunDirectory(dir))
        throw InputError("output directory " + dir.string() +
                         " exists and is not empty (use --overwrite to replace it, or --resume to continue it)");
    };
    checkEmpty();
    case_text = readText(options.case_file);
    fs::create_directories(dir);
    lock.emplace(dir, "simulate");
    checkEmpty();  // (again, holding the lock)
    if (options.overwrite) {
      const std::vector<std::string> kept = clearRunDirectory(dir);
      if (!kept.empty()) {
        std::string names;
        for (const auto& k : kept) names += (names.empty() ? "" : ", ") + k;
        std::cerr << "mistfall simulate: note: --overwrite removed the earlier run's files from " << dir
                  << " and kept what mistfall did not write: " << names << "\n";
      }
    }
    fs::create_directories(dir / "frames");
    if (config.output.field_spacing > 0.0) fs::create_directories(dir / "fields");
    writeFileAtomically(dir / kCaseCopy, [&](std::ostream& out) { out << case_text; });
  }
  const std::string fingerprint = caseFingerprint(case_text, (dir / kCaseCopy).string());
  if (options.threads > 0) omp_set_num_threads(options.threads);
  return config.dimension == 2 ? run<2>(config, options, fingerprint) : run<3>(config, options, fingerprint);
}

}  // namespace

int runSimulate(const SimulateOptions& options) {
  return runReportingErrors("mistfall simulate", [&] { return simulate(options); });
}

}  // namespace mistfall

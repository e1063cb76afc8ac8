// Tests of output/restart I/O: VTK frames, .pvd collection, diagnostics CSV, checkpoints, progress reporting.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <unistd.h>
#include <vector>

#include "cli/progress.hpp"
#include "io/bubble_log.hpp"
#include "io/checkpoint.hpp"
#include "io/diagnostics.hpp"
#include "io/pvd_collection.hpp"
#include "io/vtk_writer.hpp"
#include "support/same_particles.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;
using namespace mistfall;

namespace {

using test_support::freshDir;
using test_support::slurp;

bool noTmpFiles(const fs::path& dir) {
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().extension() == ".tmp") return false;
  return true;
}

template <int D>
Particles<D> sampleParticles(std::size_t n) {
  Particles<D> p;
  const ParticleKind kinds[] = {ParticleKind::Fluid, ParticleKind::Wall,   ParticleKind::Dummy,
                                ParticleKind::Escaped, ParticleKind::Inflow, ParticleKind::Point};
  for (std::size_t i = 0; i < n; ++i) {
    Vec<D> x, u;
    for (int k = 0; k < D; ++k) {
      x[k] = 0.1 * static_cast<double>(i) + 1.0 / (3.0 + k) - 1e-17 * k;
      u[k] = std::sin(1.7 * static_cast<double>(i) + k) * 1e-3 / 7.0;
    }
    p.add(x, u, kinds[i % 6], (i % 3 == 0) ? Phase::Gas : Phase::Liquid);
    p.pressure.back() = 1000.0 / 3.0 * static_cast<double>(i) - 5.0;
    p.number_density.back() = 6.0 + std::cos(static_cast<double>(i)) / 11.0;
    p.enclosed.back() = (i % 6 == 0);  // some gas particles in a bubble
  }
  return p;
}

using test_support::expectSameParticles;

template <int D>
void vtpRoundTrip(bool ascii) {
  const fs::path dir = freshDir("vtp" + std::to_string(D) + (ascii ? "a" : "b"));
  const fs::path file = dir / "frame.vtp";
  const Particles<D> p = sampleParticles<D>(37);
  const double time = 0.1 + 1.0 / 3.0;
  writeVtp<D>(file, p, time, ascii);
  const std::string text = slurp(file);
  EXPECT_EQ(0u, text.rfind("<?xml", 0));
  EXPECT_NE(std::string::npos, text.find("<VTKFile type=\"PolyData\""));
  EXPECT_NE(std::string::npos, text.find(ascii ? "format=\"ascii\"" : "<AppendedData encoding=\"raw\">"));
  double t_read = -1.0;
  const Particles<D> q = readVtp<D>(file, &t_read);
  EXPECT_EQ(time, t_read);
  expectSameParticles(p, q);
  EXPECT_TRUE(noTmpFiles(dir));
}

}  // namespace

TEST(Vtk, RoundTrip2DBinary) { vtpRoundTrip<2>(false); }
TEST(Vtk, RoundTrip2DAscii) { vtpRoundTrip<2>(true); }
TEST(Vtk, RoundTrip3DBinary) { vtpRoundTrip<3>(false); }
TEST(Vtk, RoundTrip3DAscii) { vtpRoundTrip<3>(true); }

TEST(Vtk, EmptyParticleSet) {
  const fs::path dir = freshDir("vtp_empty");
  writeVtp<3>(dir / "e.vtp", Particles<3>{}, 0.0, false);
  EXPECT_EQ(0u, readVtp<3>(dir / "e.vtp").size());
}

TEST(Vtk, TwoDimensionalFileHasZeroZ) {
  const fs::path dir = freshDir("vtp_z");
  const Particles<2> p = sampleParticles<2>(5);
  writeVtp<2>(dir / "f.vtp", p, 0.0, false);
  // Reading it as 3D exposes the stored z component.
  const Particles<3> q = readVtp<3>(dir / "f.vtp");
  ASSERT_EQ(q.size(), p.size());
  for (std::size_t i = 0; i < q.size(); ++i) {
    EXPECT_EQ(0.0, q.position[i][2]);
    EXPECT_EQ(0.0, q.velocity[i][2]);
    EXPECT_EQ(p.position[i][0], q.position[i][0]);
  }
  writeVtp<2>(dir / "a.vtp", p, 0.0, true);
  const std::string text = slurp(dir / "a.vtp");
  EXPECT_NE(std::string::npos, text.find("NumberOfComponents=\"3\""));
}

TEST(Vtk, MalformedInputThrowsWithPath) {
  const fs::path dir = freshDir("vtp_bad");
  writeVtp<2>(dir / "f.vtp", sampleParticles<2>(10), 0.0, false);
  std::string text = slurp(dir / "f.vtp");
  {
    std::ofstream out(dir / "cut.vtp", std::ios::binary);
    out << text.substr(0, text.size() - 200);
  }
  try {
    readVtp<2>(dir / "cut.vtp");
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string::npos, std::string(e.what()).find("cut.vtp")) << e.what();
  }
  EXPECT_THROW(readVtp<2>(dir / "missing.vtp"), std::runtime_error);
  {
    std::ofstream out(dir / "junk.vtp");
    out << "hello";
  }
  EXPECT_THROW(readVtp<2>(dir / "junk.vtp"), std::runtime_error);
}

TEST(Pvd, AddWriteLoadTruncate) {
  const fs::path dir = freshDir("pvd");
  const fs::path file = dir / "run.pvd";
  PvdCollection c(file);
  const double times[] = {0.0, 0.1, 0.2, 1.0 / 3.0};
  for (int i = 0; i < 4; ++i) c.add(times[i], "frames/frame_0000" + std::to_string(i) + ".vtp");
  c.write();
  EXPECT_TRUE(noTmpFiles(dir));
  const std::string text = slurp(file);
  EXPECT_NE(std::string::npos, text.find("<VTKFile type=\"Collection\""));
  EXPECT_NE(std::string::npos, text.find("part=\"0\" file=\"frames/frame_00003.vtp\""));

  PvdCollection d(file);
  d.load();
  ASSERT_EQ(4u, d.entries().size());
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(times[i], d.entries()[i].time);  // 17 digits: exact
    EXPECT_EQ("frames/frame_0000" + std::to_string(i) + ".vtp", d.entries()[i].file);
  }
  d.truncateAfter(0.1);
  ASSERT_EQ(2u, d.entries().size());
  d.add(0.15, "frames/frame_00002.vtp");
  d.write();
  PvdCollection e(file);
  e.load();
  ASSERT_EQ(3u, e.entries().size());
  EXPECT_EQ(0.15, e.entries()[2].time);

  PvdCollection missing(dir / "none.pvd");
  missing.load();
  EXPECT_TRUE(missing.entries().empty());
}

TEST(Diagnostics, HeaderAndRoundTrip) {
  EXPECT_EQ(
      "time,step,dt,liquid,gas,wall,dummy,escaped,max_speed,kinetic_energy,ppe_iterations,ppe_residual,wall_seconds,"
      "gas_ppe_iterations,bubbles,bubble_particles,bubble_pressure,bubble_x,bubble_y,bubble_z,bubble_size,"
      "inflow,created,removed,inflow_rate,outflow_rate,gas_capped,collisions,gradient_fallbacks,thin_support,"
      "liquid_volume,gas_volume,gas_compression,gas_pressure,dispersed_gas,entrained_swaps,regularised_rows,"
      "gas_set_dt,liquid_dt_steps,entrained_gas,gas_correction_capped,gas_speed_capped,largest_shift,"
      "vented_in,vented_out,shift_cuts,bubble_points,points_made,points_released,point_wall_stops,points_unpaired,"
      "gap_water_floors,vent_crowded_out,shift_wall_stops,respacing_wall_stops,respacing_cuts,"
      "collision_wall_limits,vent_liquid_stops,neighbour_surfaces,liquid_wall_collisions,points_coalesced,bubble_gas_wall_stops,"
      "curvature_unfitted,long_respacings,respacing_fluid_stops,largest_shift_id,largest_shift_time,shift_bounded",
      DiagnosticsWriter::header());
  const fs::path dir = freshDir("diag_rt");
  DiagnosticsRow r;
  r.time = 1.0 / 3.0;
  r.step = 123456789012LL;
  r.dt = 1e-4 / 3.0;
  r.liquid = 10; r.gas = 2; r.wall = 3; r.dummy = 4; r.escaped = 5;
  r.max_speed = 1.25; r.kinetic_energy = 0.5; r.ppe_iterations = 42; r.ppe_residual = 1e-9; r.wall_seconds = 12.5;
  r.bubbles = 2; r.bubble_particles = 77; r.bubble_pressure = 563.25; r.bubble_y = 0.0925; r.bubble_size = 4.8e-4;
  r.inflow = 120; r.created = 4000; r.removed = 3900; r.inflow_rate = 6400.5; r.outflow_rate = 6399.25;
  r.gas_capped = 31;
  r.collisions = 7; r.gradient_fallbacks = 8; r.thin_support = 9;
  r.liquid_volume = 0.04003125; r.gas_volume = 0.5; r.gas_compression = -1.25e-3; r.gas_pressure = -173.5;
  r.dispersed_gas = 11; r.entrained_swaps = 12; r.regularised_rows = 13;
  r.gas_set_dt = 14; r.liquid_dt_steps = 15.25; r.entrained_gas = 16;
  r.gas_correction_capped = 17; r.gas_speed_capped = 18; r.largest_shift = 0.03125;
  r.vented_in = 21; r.vented_out = 22; r.shift_cuts = 23;
  r.bubble_points = 24; r.points_made = 25; r.points_released = 26; r.point_wall_stops = 27; r.points_unpaired = 28;
  r.gap_water_floors = 29; r.vent_crowded_out = 30; r.shift_wall_stops = 31; r.respacing_wall_stops = 32;
  r.respacing_cuts = 33; r.collision_wall_limits = 34; r.vent_liquid_stops = 35; r.neighbour_surfaces = 36;
  r.liquid_wall_collisions = 37; r.points_coalesced = 38; r.bubble_gas_wall_stops = 39; r.curvature_unfitted = 40;
  r.long_respacings = 41; r.respacing_fluid_stops = 42; r.largest_shift_id = 43; r.largest_shift_time = 1.7426101725;
  r.shift_bounded = 44;
  {
    DiagnosticsWriter w(dir / "diagnostics.csv");
    w.append(r);
  }
  const auto rows = DiagnosticsWriter::read(dir / "diagnostics.csv");
  ASSERT_EQ(1u, rows.size());
  EXPECT_EQ(r.time, rows[0].time);
  EXPECT_EQ(r.dt, rows[0].dt);
  EXPECT_EQ(r.step, rows[0].step);
  EXPECT_EQ(5u, rows[0].escaped);
  EXPECT_EQ(42, rows[0].ppe_iterations);
  EXPECT_DOUBLE_EQ(1e-9, rows[0].ppe_residual);
  EXPECT_EQ(2u, rows[0].bubbles);
  EXPECT_EQ(77u, rows[0].bubble_particles);
  EXPECT_EQ(563.25, rows[0].bubble_pressure);
  EXPECT_EQ(0.0925, rows[0].bubble_y);
  EXPECT_EQ(4.8e-4, rows[0].bubble_size);
  EXPECT_EQ(120u, rows[0].inflow);
  EXPECT_EQ(4000, rows[0].created);
  EXPECT_EQ(3900, rows[0].removed);
  EXPECT_EQ(6400.5, rows[0].inflow_rate);
  EXPECT_EQ(6399.25, rows[0].outflow_rate);
  EXPECT_EQ(31, rows[0].gas_capped);
  EXPECT_EQ(17, rows[0].gas_correction_capped);
  EXPECT_EQ(18, rows[0].gas_speed_capped);
  EXPECT_EQ(0.03125, rows[0].largest_shift);
  EXPECT_EQ(21, rows[0].vented_in);
  EXPECT_EQ(22, rows[0].vented_out);
  EXPECT_EQ(23, rows[0].shift_cuts);
  EXPECT_EQ(7, rows[0].collisions);
  EXPECT_EQ(8, rows[0].gradient_fallbacks);
  EXPECT_EQ(9, rows[0].thin_support);
  EXPECT_EQ(0.04003125, rows[0].liquid_volume);
  EXPECT_EQ(0.5, rows[0].gas_volume);
  EXPECT_EQ(-1.25e-3, rows[0].gas_compression);
  EXPECT_EQ(-173.5, rows[0].gas_pressure);
  EXPECT_EQ(11, rows[0].dispersed_gas);
  EXPECT_EQ(12, rows[0].entrained_swaps);
  EXPECT_EQ(13, rows[0].regularised_rows);
  EXPECT_EQ(14, rows[0].gas_set_dt);
  EXPECT_EQ(15.25, rows[0].liquid_dt_steps);
  EXPECT_EQ(16, rows[0].entrained_gas);
  EXPECT_EQ(24u, rows[0].bubble_points);
  EXPECT_EQ(25, rows[0].points_made);
  EXPECT_EQ(26, rows[0].points_released);
  EXPECT_EQ(27, rows[0].point_wall_stops);
  EXPECT_EQ(28, rows[0].points_unpaired);
  EXPECT_EQ(29, rows[0].gap_water_floors);
  EXPECT_EQ(30, rows[0].vent_crowded_out);
  EXPECT_EQ(31, rows[0].shift_wall_stops);
  EXPECT_EQ(32, rows[0].respacing_wall_stops);
  EXPECT_EQ(39, rows[0].bubble_gas_wall_stops);
  EXPECT_EQ(33, rows[0].respacing_cuts);
  EXPECT_EQ(34, rows[0].collision_wall_limits);
  EXPECT_EQ(35, rows[0].vent_liquid_stops);
  EXPECT_EQ(36, rows[0].neighbour_surfaces);
  EXPECT_EQ(37, rows[0].liquid_wall_collisions);
  EXPECT_EQ(38, rows[0].points_coalesced);
  EXPECT_EQ(40, rows[0].curvature_unfitted);
  EXPECT_EQ(41, rows[0].long_respacings);
  EXPECT_EQ(42, rows[0].respacing_fluid_stops);
  EXPECT_EQ(43, rows[0].largest_shift_id);
  EXPECT_EQ(1.7426101725, rows[0].largest_shift_time);
  EXPECT_EQ(44, rows[0].shift_bounded);
  EXPECT_TRUE(noTmpFiles(dir));
}

TEST(Diagnostics, ResumeKeepsEarlierRowsAndAppends) {
  const fs::path dir = freshDir("diag_resume");
  const fs::path file = dir / "diagnostics.csv";
  auto row = [](double t, std::int64_t step) {
    DiagnosticsRow r;
    r.time = t;
    r.step = step;
    r.dt = 1e-3;
    r.liquid = static_cast<std::size_t>(step);
    return r;
  };
  {
    DiagnosticsWriter w(file);
    w.append(row(0.1, 10));
    w.append(row(0.2, 20));
    w.append(row(0.3, 30));
  }
  ASSERT_EQ(3u, DiagnosticsWriter::read(file).size());
  {
    DiagnosticsWriter w(file, 0.2);
    w.append(row(0.25, 25));
  }
  const std::string text = slurp(file);
  EXPECT_EQ(0u, text.rfind(DiagnosticsWriter::header() + "\n", 0));
  const auto rows = DiagnosticsWriter::read(file);
  ASSERT_EQ(3u, rows.size());
  EXPECT_EQ(0.1, rows[0].time);
  EXPECT_EQ(0.2, rows[1].time);
  EXPECT_EQ(0.25, rows[2].time);
  EXPECT_EQ(25, rows[2].step);
  EXPECT_TRUE(noTmpFiles(dir));

  // A torn final line (crash mid-append) is ignored by read and dropped on resume.
  { std::ofstream(file, std::ios::app) << "0.3,30,0.00"; }
  EXPECT_EQ(3u, DiagnosticsWriter::read(file).size());
  // Without resume_time the file starts over.
  { DiagnosticsWriter w(file); }
  EXPECT_EQ(DiagnosticsWriter::header() + "\n", slurp(file));
}

TEST(Diagnostics, MeasureParticles) {
  Particles<2> p;
  p.add(Vec<2>(0, 0), Vec<2>(3, 4), ParticleKind::Fluid, Phase::Liquid);
  p.add(Vec<2>(0, 0), Vec<2>(1, 0), ParticleKind::Fluid, Phase::Gas);
  p.add(Vec<2>(0, 0), Vec<2>(0, 0), ParticleKind::Wall, Phase::Liquid);
  p.add(Vec<2>(0, 0), Vec<2>(0, 0), ParticleKind::Dummy, Phase::Liquid);
  p.add(Vec<2>(0, 0), Vec<2>(9, 9), ParticleKind::Escaped, Phase::Liquid);
  DiagnosticsRow r;
  measureParticles(r, p, 2.0, 0.5);
  EXPECT_EQ(1u, r.liquid);
  EXPECT_EQ(1u, r.gas);
  EXPECT_EQ(1u, r.wall);
  EXPECT_EQ(1u, r.dummy);
  EXPECT_EQ(1u, r.escaped);
  EXPECT_DOUBLE_EQ(5.0, r.max_speed);
  EXPECT_DOUBLE_EQ(0.5 * 2.0 * 25.0 + 0.5 * 0.5 * 1.0, r.kinetic_energy);
}

namespace {

template <int D>
SimulationState<D> sampleState() {
  SimulationState<D> s;
  s.time = 0.1 + 0.2;
  s.step = 9876543210LL;
  s.dt = 1.0 / 7.0 * 1e-4;
  s.next_frame = 17;
  s.created = 1234567;
  s.removed = 7654321;
  s.vented_in = 3456;
  s.vented_out = 6543;
  s.particles = sampleParticles<D>(101);
  s.point_forces[3] = Vec<D>::Constant(1.0 / 3.0);
  s.point_forces[77] = Vec<D>::Constant(-2e-7 / 9.0);
  s.gas_reference_pressure[5] = 2525.0 / 3.0;
  s.gas_reference_pressure[90] = -1.0 / 7.0;
  return s;
}

template <int D>
void checkpointRoundTrip() {
  const fs::path dir = freshDir("ckpt" + std::to_string(D));
  const SimulationState<D> s = sampleState<D>();
  writeCheckpoint<D>(dir / "state.ckpt", s);
  EXPECT_TRUE(noTmpFiles(dir));
  EXPECT_EQ(D, checkpointDimension(dir / "state.ckpt"));
  const SimulationState<D> r = readCheckpoint<D>(dir / "state.ckpt");
  EXPECT_EQ(0, std::memcmp(&s.time, &r.time, sizeof(double)));
  EXPECT_EQ(0, std::memcmp(&s.dt, &r.dt, sizeof(double)));
  EXPECT_EQ(s.step, r.step);
  EXPECT_EQ(s.next_frame, r.next_frame);
  EXPECT_EQ(s.created, r.created);
  EXPECT_EQ(s.removed, r.removed);
  EXPECT_EQ(s.vented_in, r.vented_in);
  EXPECT_EQ(s.vented_out, r.vented_out);
  ASSERT_EQ(s.point_forces.size(), r.point_forces.size());
  for (const auto& [id, force] : s.point_forces) {
    ASSERT_EQ(r.point_forces.count(id), 1u) << "point " << id;
    EXPECT_EQ(0, std::memcmp(force.data(), r.point_forces.at(id).data(), sizeof(Vec<D>))) << "point " << id;
  }
  ASSERT_EQ(s.gas_reference_pressure.size(), r.gas_reference_pressure.size());
  for (const auto& [id, reference] : s.gas_reference_pressure) {
    ASSERT_EQ(r.gas_reference_pressure.count(id), 1u) << "gas " << id;
    EXPECT_EQ(0, std::memcmp(&reference, &r.gas_reference_pressure.at(id), sizeof(double))) << "gas " << id;
  }
  expectSameParticles(s.particles, r.particles);
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "<no exception>";
}

}  // namespace

TEST(Checkpoint, RoundTripIsBitExact2D) { checkpointRoundTrip<2>(); }
TEST(Checkpoint, RoundTripIsBitExact3D) { checkpointRoundTrip<3>(); }

TEST(Checkpoint, Errors) {
  const fs::path dir = freshDir("ckpt_err");
  const fs::path good = dir / "good.ckpt";
  writeCheckpoint<3>(good, sampleState<3>());
  const std::string bytes = slurp(good);

  EXPECT_NE(std::string::npos, errorOf([&] { readCheckpoint<2>(dir / "missing.ckpt"); }).find("does not exist"));

  EXPECT_NE(std::string::npos, errorOf([&] { readCheckpoint<2>(good); }).find("checkpoint is 3D, case is 2D"));

  std::string bad = bytes;
  bad[0] = 'X';
  { std::ofstream(dir / "magic.ckpt", std::ios::binary) << bad; }
  EXPECT_NE(std::string::npos, errorOf([&] { readCheckpoint<3>(dir / "magic.ckpt"); }).find("wrong magic"));

  bad = bytes;
  bad[12] = 99;  // version
  { std::ofstream(dir / "version.ckpt", std::ios::binary) << bad; }
  EXPECT_NE(std::string::npos, errorOf([&] { readCheckpoint<3>(dir / "version.ckpt"); }).find("version 99"));

  for (std::size_t cut : {std::size_t{5}, std::size_t{30}, bytes.size() / 2, bytes.size() - 1}) {
    { std::ofstream(dir / "cut.ckpt", std::ios::binary) << bytes.substr(0, cut); }
    const std::string msg = errorOf([&] { readCheckpoint<3>(dir / "cut.ckpt"); });
    EXPECT_NE(std::string::npos, msg.find("truncated")) << "cut at " << cut << ": " << msg;
    EXPECT_NE(std::string::npos, msg.find("cut.ckpt")) << msg;
  }

  bad = bytes;
  bad[bytes.size() / 2] ^= 0x10;  // flip a bit in the particle data
  { std::ofstream(dir / "flip.ckpt", std::ios::binary) << bad; }
  EXPECT_NE(std::string::npos, errorOf([&] { readCheckpoint<3>(dir / "flip.ckpt"); }).find("checksum"));
}

TEST(Progress, DurationFormatting) {
  EXPECT_EQ("0:00", formatDuration(0.0));
  EXPECT_EQ("0:07", formatDuration(7.4));
  EXPECT_EQ("1:05", formatDuration(65.0));
  EXPECT_EQ("59:59", formatDuration(3599.0));
  EXPECT_EQ("1:00:00", formatDuration(3600.0));
  EXPECT_EQ("27:46:40", formatDuration(100000.0));
  EXPECT_EQ("--:--", formatDuration(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_EQ("--:--", formatDuration(std::numeric_limits<double>::infinity()));
  EXPECT_EQ("--:--", formatDuration(-1.0));
}

TEST(Progress, TerminalLineFitsAndShowsFields) {
  ProgressSnapshot s;
  s.sim_time = 0.168;
  s.end_time = 0.4;
  s.step = 1234;
  s.dt = 1.2e-4;
  s.steps_per_second = 57.3;
  s.eta_seconds = 12.0;
  const std::string line = formatTerminalLine(s);
  EXPECT_EQ("[########............]   42.0%  t=0.1680/0.4000 s  step 1234  dt=1.2e-04 s  57.3 steps/s  ETA 0:12",
            line);
  EXPECT_LE(line.size(), 100u);
  s.step = 123456789012LL;
  s.steps_per_second = 123456.0;
  s.eta_seconds = 1e6;
  EXPECT_LE(formatTerminalLine(s).size(), 100u);
}

TEST(Progress, PlainModePrintsEveryTenPercent) {
  std::ostringstream out;
  double now = 0.0;
  ProgressReporter r(0.4, 0.0, out, ProgressMode::Plain, [&now] { return now; });
  EXPECT_FALSE(r.terminal());
  int lines_at_marks = 0;
  for (int step = 1; step <= 400; ++step) {
    now = step * 0.01;  // 100 steps per wall second
    const std::size_t before = out.str().size();
    r.update(step * 0.001, step, 0.001);
    const bool printed = out.str().size() != before;
    EXPECT_EQ(step % 40 == 0, printed) << "step " << step;
    lines_at_marks += printed;
  }
  EXPECT_EQ(10, lines_at_marks);
  std::istringstream lines(out.str());
  std::string first;
  std::getline(lines, first);
  // 0.36 sim-s left at 0.1 sim-s per wall-s: ETA 3.6 s.
  EXPECT_EQ("progress: t=0.0400/0.4000 s (10%), step 40, 100 steps/s, ETA 0:04", first);
  r.finish();
  r.finish();
  EXPECT_NE(std::string::npos, out.str().find("progress: done"));
  EXPECT_EQ(out.str().find("progress: done"), out.str().rfind("progress: done"));
}

TEST(Progress, ResumeStartsAtNextMark) {
  std::ostringstream out;
  double now = 0.0;
  ProgressReporter r(1.0, 0.55, out, ProgressMode::Plain, [&now] { return now; });
  now = 1.0;
  r.update(0.58, 100, 0.01);
  EXPECT_TRUE(out.str().empty());
  now = 2.0;
  r.update(0.61, 106, 0.01);
  EXPECT_NE(std::string::npos, out.str().find("(61%)"));
  // Sim rate since start: 0.06 s per 2 wall-s, 0.39 left -> 13 s.
  EXPECT_NE(std::string::npos, out.str().find("ETA 0:13"));
}

// A long run's log shows it is alive between its 10 % marks: a line once kPlainLineGapSeconds of wall time have
// passed since the last line, the marks still at every 10 %.
TEST(Progress, PlainModePrintsALineAfterALongGap) {
  std::ostringstream out;
  double now = 0.0;
  ProgressReporter r(1.0, 0.0, out, ProgressMode::Plain, [&now] { return now; });
  auto lines = [&out] {
    const std::string text = out.str();
    return std::count(text.begin(), text.end(), '\n');
  };
  const double step_wall = kPlainLineGapSeconds / 4.0;  // 10 % of the run (10 steps) takes 2.5 gaps of wall time
  std::vector<std::int64_t> printed_at;
  for (int step = 1; step <= 100; ++step) {
    now = step * step_wall;
    const auto before = lines();
    r.update(step * 0.01, step, 0.01);
    if (lines() != before) printed_at.push_back(step);
  }
  // At each 10 % mark (every 10 steps) and a gap (4 steps) after the last line: 4, 8, 10, 14, 18, 20, 24, ...
  std::vector<std::int64_t> expected;
  std::int64_t last = 0;
  for (int step = 1; step <= 100; ++step)
    if (step % 10 == 0 || step - last >= 4) expected.push_back(step), last = step;
  EXPECT_EQ(expected, printed_at);
  EXPECT_EQ(30u, expected.size());
  EXPECT_NE(std::string::npos, out.str().find("(4%)"));  // a gap's line, before the first mark
}

TEST(Progress, TerminalModeThrottlesAndLogsCleanly) {
  std::ostringstream out;
  double now = 0.0;
  ProgressReporter r(1.0, 0.0, out, ProgressMode::Terminal, [&now] { return now; });
  r.update(0.01, 1, 0.01);
  const std::size_t after_first = out.str().size();
  EXPECT_GT(after_first, 0u);
  now = 0.05;
  r.update(0.02, 2, 0.01);
  EXPECT_EQ(after_first, out.str().size());  // throttled
  now = 0.2;
  r.update(0.03, 3, 0.01);
  EXPECT_GT(out.str().size(), after_first);
  r.log("hello");
  const std::string s = out.str();
  const std::size_t hello = s.find("hello\n");
  ASSERT_NE(std::string::npos, hello);
  EXPECT_EQ('\r', s[hello - 1]);               // bar cleared before the line
  EXPECT_EQ('\r', s[hello + 6]);               // and redrawn after it
  r.finish();
  EXPECT_EQ('\n', out.str().back());
}

TEST(BubbleLog, WritesEveryBubbleAndKeepsEarlierLinesOnResume) {
  const fs::path dir = freshDir("bubble_log");
  const fs::path file = dir / "bubbles.csv";
  BubbleStats a;
  a.region = 0, a.particles = 256, a.mean_pressure = 563.5, a.centroid = {0.1, 0.0925, 0.0}, a.size = 1.6e-3;
  BubbleStats b = a;
  b.region = 3, b.particles = 1, b.mean_pressure = 12.0;
  auto lines = [&]() {
    std::ifstream in(file);
    std::vector<std::string> out;
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
  };
  {
    BubbleLog log(file);
    log.append(0.0, {a, b});
    log.append(0.1, {});
    log.append(0.2, {a});
  }
  auto all = lines();
  ASSERT_EQ(4u, all.size());
  EXPECT_EQ(BubbleLog::header(), all[0]);
  EXPECT_EQ(0u, all[1].rfind("0,0,256,563.5,0.1,0.0925,0,0.0016", 0)) << all[1];
  EXPECT_EQ(0u, all[2].rfind("0,3,1,12,", 0)) << all[2];
  EXPECT_EQ(0u, all[3].rfind("0.2", 0)) << all[3];
  {
    BubbleLog resumed(file, 0.1);  // the line at t = 0.2 is dropped
    resumed.append(0.15, {b});
  }
  all = lines();
  ASSERT_EQ(4u, all.size());
  EXPECT_EQ(0.15, std::stod(all[3].substr(0, all[3].find(',')))) << all[3];
  EXPECT_NE(std::string::npos, all[3].find(",3,1,12,")) << all[3];
  EXPECT_TRUE(noTmpFiles(dir));
}

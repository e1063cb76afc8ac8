// Case file reader: parses TOML with toml++, checks every key against the layout in docs/case-file.md and
// fills a CaseConfig. Errors name the file, the key path, the offending value and what is allowed.
// The checked TOML access is in toml_reader.cpp, the region geometry checks in case_regions.cpp.
#include "case/case_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <sstream>
#include <system_error>

#include "case/scene.hpp"
#include "case/toml_reader.hpp"

namespace mistfall {
namespace {

using detail::Field;
using detail::Range;
using detail::Reader;
using detail::show;

std::string fmt(double v) { return detail::formatNumber(v); }

// [physics.<name>]: density, kinematic_viscosity, sound_speed (same keys and ranges for every phase).
void readPhase(const Reader& rd, const toml::table& physics, std::string_view name, PhaseProperties& out) {
  const std::string path = "physics." + std::string(name);
  const toml::table& t = rd.table(physics, "physics", name);
  rd.checkKeys(t, path, {"density", "kinematic_viscosity", "sound_speed"});
  rd.number(t, path, "density", {0.0, 1e5, true, false}, out.density);
  rd.number(t, path, "kinematic_viscosity", {0.0, 1.0, false, false}, out.kinematic_viscosity);
  if (Field f = rd.field(t, path, "sound_speed"); f.node) {
    const std::string allowed = "a number > 0 or the string \"inf\"";
    if (f.node->is_string()) {
      if (f.node->as_string()->get() != "inf") rd.fail(f.path + " = " + show(*f.node) + " is not allowed; allowed " + allowed);
      out.sound_speed = std::numeric_limits<double>::infinity();
    } else {
      const double v = rd.toNumber(f, allowed);
      if (!(v > 0.0)) rd.outOfRange(f.path, show(*f.node), allowed);
      out.sound_speed = v;
    }
  }
}

// Keys `keys` of region `p` must be absent for shape `shape`.
void rejectKeys(const Reader& rd, const toml::table& t, const std::string& p, const std::string& shape,
                std::initializer_list<std::string_view> keys, const std::string& allowed) {
  for (auto key : keys)
    if (Field f = rd.field(t, p, key); f.node)
      rd.fail(f.path + " = " + show(*f.node) + " is not allowed with shape = \"" + shape + "\"; allowed " + allowed);
}

// One [[region]] table (geometry checks come later, in detail::validateRegions).
Region readRegion(const Reader& rd, const toml::table& t, const std::string& p, const CaseConfig& c) {
  const int dim = c.dimension;
  rd.checkKeys(t, p, {"name", "material", "shape", "min", "max", "center", "radius", "velocity"});
  Region r;
  Field nf = rd.field(t, p, "name");
  if (!nf.node) rd.missing(nf, "a non-empty unique string");
  r.name = rd.string(nf, "a non-empty unique string");
  if (r.name.empty()) rd.fail(nf.path + " = \"\" is empty; allowed a non-empty unique string");
  for (std::size_t j = 0; j < c.regions.size(); ++j)
    if (c.regions[j].name == r.name)
      rd.fail(nf.path + " = \"" + r.name + "\" duplicates region[" + std::to_string(j) +
              "].name; allowed unique region names");
  switch (rd.choice(t, p, "material", {"water", "wall", "gas"})) {
    case 1: r.material = Material::Wall; break;
    case 2: r.material = Material::Gas; break;
    default: r.material = Material::Water; break;
  }
  if (rd.choice(t, p, "shape", {"box", "circle"}) == 1) r.shape = RegionShape::Circle;
  if (r.shape == RegionShape::Box) {
    rejectKeys(rd, t, p, "box", {"center", "radius"}, "min and max (center and radius need shape = \"circle\")");
    rd.vector(t, p, "min", dim, r.box.min, true);
    rd.vector(t, p, "max", dim, r.box.max, true);
  } else {
    rejectKeys(rd, t, p, "circle", {"min", "max"}, "center and radius (min and max need shape = \"box\")");
    rd.vector(t, p, "center", dim, r.center, true);
    rd.number(t, p, "radius", {0.0, std::numeric_limits<double>::infinity(), true, true}, r.radius, true);
    for (int k = 0; k < dim; ++k) {
      r.box.min[k] = r.center[k] - r.radius;
      r.box.max[k] = r.center[k] + r.radius;
    }
  }
  if (Field vf = rd.field(t, p, "velocity"); vf.node && r.material == Material::Wall)
    rd.fail(vf.path + " = " + show(*vf.node) +
            " is not allowed for material = \"wall\"; allowed only in water and gas regions");
  rd.vector(t, p, "velocity", dim, r.initial_velocity);
  return r;
}

}  // namespace

CaseConfig parseCase(std::string_view toml_text, const std::string& source_name) {
  const toml::table root = detail::parseToml(toml_text, source_name);
  const Reader rd(source_name);
  CaseConfig c;
  rd.checkKeys(root, "",
               {"case", "domain", "physics", "numerics", "output", "classify", "texture", "render", "region", "inflow", "outflow", "vent"});

  // [case]
  const toml::table& cs = rd.table(root, "", "case");
  rd.checkKeys(cs, "case", {"name", "dimension"});
  {
    Field f = rd.field(cs, "case", "name");
    if (!f.node) rd.missing(f, detail::kFileNameAllowed);
    c.name = rd.string(f, detail::kFileNameAllowed);
    if (const std::string why = detail::fileNameProblem(c.name); !why.empty())  // it names render/<name>.mp4
      rd.fail(f.path + " = " + show(*f.node) + " " + why + "; allowed " + detail::kFileNameAllowed);
  }
  rd.integer(cs, "case", "dimension", 2, 3, "2 or 3", c.dimension, true);
  const int dim = c.dimension;

  // [domain]
  const toml::table& dm = rd.table(root, "", "domain");
  rd.checkKeys(dm, "domain", {"min", "max"});
  rd.vector(dm, "domain", "min", dim, c.domain.min, true);
  rd.vector(dm, "domain", "max", dim, c.domain.max, true);
  for (int k = 0; k < dim; ++k)
    if (!(c.domain.max[k] > c.domain.min[k]))
      rd.outOfRange("domain.max[" + std::to_string(k) + "]", fmt(c.domain.max[k]),
                    "> domain.min[" + std::to_string(k) + "] = " + fmt(c.domain.min[k]));

  // [physics]
  const toml::table& ph = rd.table(root, "", "physics");
  rd.checkKeys(ph, "physics", {"gravity", "liquid", "gas", "surface_tension"});
  c.physics.gravity = {0.0, 0.0, 0.0};
  c.physics.gravity[static_cast<std::size_t>(dim - 1)] = -9.81;  // vertical axis is the last one
  rd.vector(ph, "physics", "gravity", dim, c.physics.gravity);
  readPhase(rd, ph, "liquid", c.physics.liquid);
  readPhase(rd, ph, "gas", c.physics.gas);
  rd.number(ph, "physics", "surface_tension", {0.0, 10.0, true, false}, c.physics.surface_tension);

  // [numerics]
  const std::string np = "numerics";
  const toml::table& nm = rd.table(root, "", np);
  rd.checkKeys(nm, np,
               {"particle_spacing", "scheme", "liquid_support_fraction", "thin_row_pressure", "gradient_correction_min_determinant",
                "pressure_repulsion", "particle_shifting", "shifting_kernel", "shift_limit", "shift_stability", "shift_wall_stop", "bubble_gas_wall_stop", "respacing_limit", "respacing_walls", "respacing_stop", "radius_number_density", "radius_laplacian", "courant", "dt_max", "dt_min",
                "surface_threshold", "surface_neighbour_fraction", "surface_asymmetry", "collision_distance", "collision_restitution", "pressure_source", "source_relaxation", "source_relaxation_basis", "pressure_solver",
                "solver_tolerance", "solver_max_iterations", "max_escaped_fraction", "bubble_min_particles", "closed_pockets",
                "gas_domain", "entrained_gas_rise_speed", "entrained_bubble_diameter", "gas_correction_limit", "gas_region_link",
                "dispersed_gas_fraction", "gas_speed_limit", "gas_pressure_memory", "dispersed_gas_touch",
                "bubble_initial_pressure", "bubble_divergence", "bubble_cavity", "bubble_surface_tension",
                "surface_tension_fit_radius",
                "bubble_gas_motion", "bubble_regularisation", "coupling", "gas_operators", "vent_outlet",
                "gap_water_floor", "gas_collision_after_correction", "liquid_collision_after_correction",
                "collision_wall_limit", "vent_liquid_stop", "vent_crowding_at_mouth", "collision_passes",
                "entrained_gas_inertia", "bubble_gas_inertia", "bubble_gas_in_water_density"});
  NumericsConfig& n = c.numerics;
  rd.number(nm, np, "particle_spacing", {0.0, 10.0, true, false}, n.particle_spacing, true);
  if (int s = rd.choice(nm, np, "scheme", {"paper", "stabilised"}); s >= 0)
    n.scheme = s == 0 ? Scheme::Paper : Scheme::Stabilised;
  // Below the liquid-side support of a particle in a container's corner (a quadrant of the lattice: 0.39 of a full
  // one in 2D; an octant: 0.29 in 3D), which is no free surface: 0.3 in 2D, 0.2 in 3D.
  if (c.dimension == 3) n.liquid_support_fraction = 0.2;
  rd.number(nm, np, "liquid_support_fraction", {0.0, 1.0, false, true}, n.liquid_support_fraction);
  if (int s = rd.choice(nm, np, "thin_row_pressure", {"surface", "liquid"}); s >= 0) n.thin_rows_hold_liquid = s == 1;
  rd.number(nm, np, "gradient_correction_min_determinant", {0.0, 1.0, true, false},
            n.gradient_correction_min_determinant);
  rd.number(nm, np, "pressure_repulsion", {0.0, 10.0, false, false}, n.pressure_repulsion);
  rd.number(nm, np, "particle_shifting", {0.0, 100.0, false, false}, n.particle_shifting);
  if (int s = rd.choice(nm, np, "shifting_kernel", {"mps", "wendland"}); s >= 0)
    n.shifting_kernel = static_cast<NumericsConfig::ShiftingKernel>(s);
  rd.number(nm, np, "shift_limit", {0.0, 10.0, false, false}, n.shift_limit);
  rd.number(nm, np, "shift_stability", {0.0, 10.0, false, false}, n.shift_stability);
  rd.boolean(nm, np, "shift_wall_stop", n.shift_wall_stop);
  rd.boolean(nm, np, "bubble_gas_wall_stop", n.bubble_gas_wall_stop);
  rd.number(nm, np, "respacing_limit", {0.0, 10.0, false, false}, n.respacing_limit);
  if (int s = rd.choice(nm, np, "respacing_walls", {"free", "slip"}); s >= 0) n.respacing_slip = s == 1;
  if (int s = rd.choice(nm, np, "respacing_stop", {"none", "water", "fluid"}); s >= 0)
    n.respacing_stop = static_cast<NumericsConfig::RespacingStop>(s);
  rd.number(nm, np, "radius_number_density", {1.5, 5.0, false, false}, n.radius_number_density);
  rd.number(nm, np, "radius_laplacian", {1.5, 5.0, false, false}, n.radius_laplacian);
  rd.number(nm, np, "courant", {0.0, 1.0, true, false}, n.courant);
  rd.number(nm, np, "dt_max", {0.0, 1.0, true, false}, n.dt_max);
  rd.number(nm, np, "dt_min", {0.0, n.dt_max, true, true, "numerics.dt_max"}, n.dt_min);
  rd.number(nm, np, "surface_threshold", {0.0, 1.0, true, true}, n.surface_threshold);
  rd.number(nm, np, "surface_neighbour_fraction", {0.0, 1.0, false, true}, n.surface_neighbour_fraction);
  rd.number(nm, np, "surface_asymmetry", {0.0, 1.0, false, false}, n.surface_asymmetry);
  rd.number(nm, np, "collision_distance", {0.0, 1.0, false, true}, n.collision_distance);
  rd.number(nm, np, "collision_restitution", {0.0, 1.0, false, false}, n.collision_restitution);
  rd.boolean(nm, np, "collision_wall_limit", n.collision_wall_limit);
  rd.integer(nm, np, "collision_passes", 1, 10, "[1, 10]", n.collision_passes);
  if (int s = rd.choice(nm, np, "entrained_gas_inertia", {"gas", "liquid"}); s >= 0)
    n.entrained_gas_liquid_inertia = s == 1;
  if (int s = rd.choice(nm, np, "bubble_gas_inertia", {"gas", "liquid"}); s >= 0) n.bubble_gas_liquid_inertia = s == 1;
  if (int s = rd.choice(nm, np, "bubble_gas_in_water_density", {"particle", "volume"}); s >= 0)
    n.bubble_gas_counts_by_volume = s == 1;
  rd.boolean(nm, np, "vent_liquid_stop", n.vent_liquid_stop);
  rd.boolean(nm, np, "vent_crowding_at_mouth", n.vent_crowding_at_mouth);
  if (int s = rd.choice(nm, np, "pressure_source", {"standard", "mixed"}); s >= 0)
    n.pressure_source = s == 0 ? PressureSource::Standard : PressureSource::Mixed;
  rd.number(nm, np, "source_relaxation", {0.0, 1.0, false, false}, n.source_relaxation);
  if (int s = rd.choice(nm, np, "source_relaxation_basis", {"step", "time"}); s >= 0)
    n.source_relaxation_per_time = s == 1;
  if (n.scheme == Scheme::Stabilised && n.pressure_source != PressureSource::Mixed)
    rd.fail("numerics.scheme = \"stabilised\" needs numerics.pressure_source = \"mixed\" (its walls act through the "
            "velocity-divergence source; docs/case-file.md)");
  if (int s = rd.choice(nm, np, "pressure_solver", {"iccg", "amg"}); s >= 0)
    n.pressure_solver = s == 0 ? PressureSolverKind::EigenIccg : PressureSolverKind::HypreAmg;
  rd.number(nm, np, "solver_tolerance", {0.0, 1e-2, true, false}, n.solver_tolerance);
  rd.integer(nm, np, "solver_max_iterations", 1, 100000, "[1, 100000]", n.solver_max_iterations);
  rd.number(nm, np, "max_escaped_fraction", {0.0, 1.0, true, false}, n.max_escaped_fraction);
  rd.integer(nm, np, "bubble_min_particles", 1, 1000000, "[1, 1000000]", n.bubble_min_particles);
  if (int s = rd.choice(nm, np, "gas_domain", {"open", "closed"}); s >= 0)
    n.gas_domain = s == 0 ? GasDomain::Open : GasDomain::Closed;
  rd.number(nm, np, "entrained_gas_rise_speed", {0.0, 10.0, false, false}, n.entrained_gas_rise_speed);
  rd.number(nm, np, "entrained_bubble_diameter", {0.0, 1.0, false, false}, n.entrained_bubble_diameter);
  if (n.entrained_bubble_diameter > 0.0 && n.entrained_gas_rise_speed > 0.0)
    rd.fail("numerics.entrained_bubble_diameter = " + fmt(n.entrained_bubble_diameter) +
            " moves entrained gas as points, numerics.entrained_gas_rise_speed = " + fmt(n.entrained_gas_rise_speed) +
            " by phase swaps; allowed one of them (the other 0)");
  rd.number(nm, np, "gas_correction_limit", {0.0, 1.0, false, false}, n.gas_correction_limit);
  rd.number(nm, np, "gas_region_link", {0.0, 5.0, false, false}, n.gas_region_link);
  rd.number(nm, np, "dispersed_gas_fraction", {0.0, 1.0, false, false}, n.dispersed_gas_fraction);
  rd.number(nm, np, "gas_speed_limit", {0.0, 1000.0, false, false}, n.gas_speed_limit);
  if (const auto f = rd.field(nm, np, "gas_pressure_memory"); f.node && f.node->is_string()) {
    const int s = rd.choice(nm, np, "gas_pressure_memory", {"bubbles", "open_gas"});
    if (s >= 0) n.gas_pressure_memory_open = s == 1, n.gas_pressure_memory_bubbles = s == 0;
  } else if (f.node && !f.node->is_boolean()) {
    rd.wrongType(f, "true, false, \"bubbles\" or \"open_gas\"");
  } else {
    bool memory = false;  // absent: false, the default
    rd.boolean(nm, np, "gas_pressure_memory", memory);
    n.gas_pressure_memory_open = n.gas_pressure_memory_bubbles = memory;
  }
  if (int s = rd.choice(nm, np, "bubble_initial_pressure", {"zero", "water"}); s >= 0)
    n.bubble_start_at_water_pressure = s == 1;
  if (int s = rd.choice(nm, np, "bubble_divergence", {"interface", "whole_bubble"}); s >= 0)
    n.bubble_divergence_whole = s == 1;
  rd.boolean(nm, np, "gas_collision_after_correction", n.gas_collision_after_correction);
  rd.boolean(nm, np, "liquid_collision_after_correction", n.liquid_collision_after_correction);
  if (int s = rd.choice(nm, np, "gas_operators", {"paper", "stabilised"}); s >= 0) n.gas_stabilised = s == 1;
  if (int s = rd.choice(nm, np, "vent_outlet", {"buffer", "zero_gradient"}); s >= 0) n.vent_zero_gradient = s == 1;
  if (n.gas_stabilised && n.pressure_source != PressureSource::Mixed)
    rd.fail("numerics.gas_operators = \"stabilised\" needs numerics.pressure_source = \"mixed\" (the walls act through the "
            "velocity-divergence source; docs/case-file.md)");
  rd.number(nm, np, "dispersed_gas_touch", {0.0, 5.0, false, false}, n.dispersed_gas_touch);
  if (int s = rd.choice(nm, np, "bubble_gas_motion", {"follow_liquid", "own_pressure", "follow_void"}); s >= 0)
    n.bubble_gas_motion = s == 0   ? NumericsConfig::BubbleGasMotion::FollowLiquid
                          : s == 1 ? NumericsConfig::BubbleGasMotion::OwnPressure
                                   : NumericsConfig::BubbleGasMotion::FollowVoid;
  rd.number(nm, np, "bubble_regularisation", {0.0, 1e6, false, false}, n.bubble_regularisation);
  if (int s = rd.choice(nm, np, "coupling", {"two_systems", "one_equation"}); s >= 0)
    n.coupling = s == 0 ? NumericsConfig::Coupling::TwoSystems : NumericsConfig::Coupling::OneEquation;
  if (int s = rd.choice(nm, np, "bubble_cavity", {"none", "joined"}); s >= 0) n.bubble_cavity_joined = s == 1;
  if (n.bubble_cavity_joined && c.dimension != 2)
    rd.fail("numerics.bubble_cavity = \"joined\" is built for 2D cases (its cavity is found on a 2D grid: "
            "src/mps/bubble_cavity.hpp); this case has dimension = " + std::to_string(c.dimension));
  if (n.bubble_cavity_joined && n.coupling == NumericsConfig::Coupling::OneEquation)
    rd.fail("numerics.bubble_cavity = \"joined\" needs numerics.coupling = \"two_systems\" (the one equation has no "
            "bubble unknown to join)");
  if (n.coupling == NumericsConfig::Coupling::OneEquation && n.scheme != Scheme::Stabilised)
    rd.fail("numerics.coupling = \"one_equation\" is built on numerics.scheme = \"stabilised\" (its mirrored walls, "
            "corrected gradient and consistent Laplacian; docs/two-phase.md)");
  if (n.thin_rows_hold_liquid && (n.scheme != Scheme::Stabilised || n.coupling != NumericsConfig::Coupling::TwoSystems))
    rd.fail("numerics.thin_row_pressure = \"liquid\" needs numerics.scheme = \"stabilised\" and numerics.coupling = "
            "\"two_systems\" (it sets the rows that liquid_support_fraction makes free surface in the stabilised liquid "
            "system)");
  if (int s = rd.choice(nm, np, "bubble_surface_tension", {"none", "jump"}); s >= 0) n.bubble_surface_tension = s == 1;
  rd.number(nm, np, "surface_tension_fit_radius", {2.0, 10.0, false, false}, n.surface_tension_fit_radius);
  if (n.bubble_surface_tension && n.coupling == NumericsConfig::Coupling::OneEquation)
    rd.fail("numerics.bubble_surface_tension = \"jump\" needs numerics.coupling = \"two_systems\" (the jump is set "
            "between a bubble's unknown P_B and the water; the one equation has no bubble unknown)");
  if (n.bubble_surface_tension && n.scheme == Scheme::Stabilised)
    rd.fail("numerics.bubble_surface_tension = \"jump\" is built on numerics.scheme = \"paper\": on the stabilised "
            "scheme a weightless bubble does not stay at rest even without the jump (water at 0.2 m/s within 0.1 s), and "
            "with bubble_divergence = \"whole_bubble\", at rest without it, the jump rings it up to 4-26 sigma / R "
            "(docs/validation.md)");
  if (int s = rd.choice(nm, np, "closed_pockets", {"small", "unvented"}); s >= 0)
    n.closed_pockets = s == 0 ? NumericsConfig::ClosedPockets::Small : NumericsConfig::ClosedPockets::Unvented;
  if (n.closed_pockets == NumericsConfig::ClosedPockets::Unvented && n.gas_domain != GasDomain::Closed)
    rd.fail("numerics.closed_pockets = \"unvented\" is a rule of a closed gas domain (an open one's gas reaches the "
            "atmosphere through its free surface); allowed with numerics.gas_domain = \"closed\", or \"small\"");
  rd.boolean(nm, np, "gap_water_floor", n.gap_water_floor);
  if (n.gap_water_floor && n.coupling != NumericsConfig::Coupling::OneEquation)
    rd.fail("numerics.gap_water_floor = true is a condition of the one equation's water rows (the two systems' water "
            "already holds p = 0 at its free surface); allowed with numerics.coupling = \"one_equation\", or false");
  if (n.gas_domain == GasDomain::Closed && !std::isfinite(c.physics.gas.sound_speed))
    rd.fail("numerics.gas_domain = \"closed\" needs a finite physics.gas.sound_speed (a closed incompressible gas "
            "has no pressure level); allowed \"open\", or a sound speed > 0");
  for (int k = 0; k < dim; ++k) {
    const double cells = (c.domain.max[k] - c.domain.min[k]) / n.particle_spacing;
    if (!(cells <= static_cast<double>(kMaxLatticeIndex)))
      rd.outOfRange("numerics.particle_spacing", fmt(n.particle_spacing),
                    "a spacing giving at most " + std::to_string(kMaxLatticeIndex) +
                        " lattice points along each domain axis (axis " + std::to_string(k) + " has " +
                        fmt(std::floor(cells)) + ")");
  }

  // [output]
  const toml::table& out = rd.table(root, "", "output");
  rd.checkKeys(out, "output", {"end_time", "interval", "field_spacing"});
  rd.number(out, "output", "end_time", {0.0, 1e4, true, false}, c.output.end_time, true);
  rd.number(out, "output", "interval", {0.0, c.output.end_time, true, false, "output.end_time"}, c.output.interval);
  rd.number(out, "output", "field_spacing", {0.0, 1e3, false, false}, c.output.field_spacing);

  // [classify] (optional): thresholds of the six-category classification, relative to n0.
  const toml::table& cl = rd.table(root, "", "classify");
  rd.checkKeys(cl, "classify",
               {"isolated_number_density", "isolated_neighbour_fraction", "surface_number_density", "surface_gradient"});
  const Range fraction{0.0, 1.0, false, false};
  rd.number(cl, "classify", "isolated_number_density", fraction, c.classify.isolated_number_density);
  rd.number(cl, "classify", "isolated_neighbour_fraction", fraction, c.classify.isolated_neighbour_fraction);
  rd.number(cl, "classify", "surface_number_density", fraction, c.classify.surface_number_density);
  rd.number(cl, "classify", "surface_gradient", {0.0, std::numeric_limits<double>::infinity(), false, true},
            c.classify.surface_gradient);

  // [[region]]
  Field rf = rd.field(root, "", "region");
  const std::string regions_allowed = "an array of tables written as [[region]], at least one with material = \"water\"";
  if (!rf.node) rd.missing(rf, regions_allowed);
  if (!rf.node->is_array_of_tables() || rf.node->as_array()->empty()) rd.wrongType(rf, regions_allowed);
  const toml::array& ra = *rf.node->as_array();
  for (std::size_t i = 0; i < ra.size(); ++i)
    c.regions.push_back(readRegion(rd, *ra[i].as_table(), "region[" + std::to_string(i) + "]", c));
  detail::validateRegions(c, source_name);
  detail::readOpenBoundaries(rd, root, c);
  if (c.numerics.closed_pockets == NumericsConfig::ClosedPockets::Unvented && c.vents.empty())
    rd.fail("numerics.closed_pockets = \"unvented\" tells the atmosphere by the vents' gas, and this case has no "
            "[[vent]]; allowed with a [[vent]], or \"small\"");
  // The stabilised scheme takes gas under either coupling (experimental with open boundaries: docs/two-phase.md,
  // "The stabilised liquid under the two-systems coupling"). Water alone takes inflow and outflow boundaries: its
  // channel carries the critical energy of a frictionless free overfall (docs/waterfall.md,
  // tests/test_open_boundaries.cpp).
  detail::readTexture(rd, root, c);
  detail::readRender(rd, root, c);
  return c;
}

CaseConfig loadCaseFile(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw CaseError(name + ": case file does not exist");
  if (!std::filesystem::is_regular_file(path, ec)) throw CaseError(name + ": case file is not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CaseError(name + ": cannot open case file for reading");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw CaseError(name + ": error while reading case file");
  return parseCase(text.str(), name);
}

}  // namespace mistfall

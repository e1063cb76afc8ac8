// A case: everything that describes one simulation. Filled from a TOML case file (case_file.hpp);
// every default below is documented in docs/case-file.md. The code holds no scene geometry.
#pragma once

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "classify/classification_parameters.hpp"
#include "texture/fluctuation_model.hpp"

namespace mistfall {

// Axis-aligned box; only the first `dimension` components are used.
struct Box {
  std::array<double, 3> min{0.0, 0.0, 0.0};
  std::array<double, 3> max{0.0, 0.0, 0.0};
};

// Gas is the second fluid phase (air). Which material a lattice point gets where regions overlap is
// described in docs/case-file.md ("Overlapping regions"): walls always win; among water and gas regions
// the one declared last wins.
enum class Material { Water, Wall, Gas };

// Box: the points of `box`. Circle: a disc (2D) or sphere (3D) of `radius` around `center`.
enum class RegionShape { Box, Circle };

struct Region {
  std::string name;
  Material material = Material::Water;
  RegionShape shape = RegionShape::Box;
  // Box shape: the region. Circle shape: its bounding box center -/+ radius (set by the parser).
  Box box;
  std::array<double, 3> center{0.0, 0.0, 0.0};  // circle only
  double radius = 0.0;                           // circle only
  std::array<double, 3> initial_velocity{0.0, 0.0, 0.0};
};

// Open boundaries (mps/open_boundaries.hpp). An inflow buffer is a box filled with water that is driven at the
// speed U along `axis` (sign +1 or -1) and feeds the domain one lattice layer at a time:
// U = discharge / depth, depth = the box's extent along the axis of gravity (2D: q per unit width [m^2/s];
// 3D: q per unit width across the box).
struct Inflow {
  std::string name;
  Box box;
  int axis = 0;            // the flow's coordinate axis
  int sign = 1;            // +1: along +axis, -1: along -axis
  double discharge = 0.0;  // q [m^2/s]
  double speed = 0.0;      // U = q / depth [m/s] (set by the parser)
  // The buffer's rows (mps/inflow_pressure.hpp): with the water's source ("solved"), or none, lap p = 0 ("harmonic").
  enum class Pressure { Solved, Harmonic } pressure = Pressure::Solved;
};

// An outflow box removes every liquid particle that enters it (the arrays are compacted); gas passes through.
struct Outflow {
  std::string name;
  Box box;
};

// A gas vent (mps/gas_vent.hpp): an opening of the air to the ambient atmosphere, a box cut through a wall (clear of
// wall regions), filled with gas at set-up. Its gas holds the ambient pressure rho_g g.x and moves along `axis`
// with the air in front of it; gas leaves through the outer face (the face on the `sign` side) and enters there.
struct Vent {
  std::string name;
  Box box;
  int axis = 0;  // the vent's axis
  int sign = 1;  // +1: the outer face is box.max[axis] (outward along +axis), -1: box.min[axis]
  // The pressure of the air it lets in (gas_vent.hpp): the ambient's total pressure (the air drawn from rest, the
  // default), or its static pressure.
  enum class Inflow { TotalPressure, Static } inflow = Inflow::TotalPressure;
  // Where liquid leaves the domain through it (gas_vent.hpp): past the outer face (the default), or as soon as it
  // enters the box at the inner face (an opening to the atmosphere takes the spray that reaches it).
  enum class LiquidExit { OuterFace, InnerFace } liquid_exit = LiquidExit::OuterFace;
};

struct PhaseProperties {
  double density = 1000.0;               // [kg/m^3]
  double kinematic_viscosity = 1.0e-6;   // [m^2/s]
  // Speed of sound [m/s] for the compressible pressure equation (17); infinity = incompressible (9).
  double sound_speed = std::numeric_limits<double>::infinity();
};

struct PhysicsConfig {
  std::array<double, 3> gravity{0.0, -9.81, 0.0};  // [m/s^2]
  // [N/m] of the liquid against the gas: water-air at 20 C. Used by the entrained bubbles' drag (Eotvos number,
  // mps/entrained_bubbles.hpp) only; the MPS particles carry no surface tension.
  double surface_tension = 0.0728;
  PhaseProperties liquid{};
  // Air; weakly compressible (finite sound speed: eq. (17)).
  PhaseProperties gas{1.2, 1.5e-5, 340.0};
};

// Properties of phase `phase_index`, numbered as the Phase enum of mps/particles.hpp: 0 = liquid,
// 1 = gas. Throws std::out_of_range for any other index.
const PhaseProperties& phaseProperties(const PhysicsConfig& physics, int phase_index);

enum class PressureSolverKind { EigenIccg, HypreAmg };
// Source term of the PPE. Standard: eq. (9), -rho/dt^2 (n* - n0)/n0 (the paper's original MPS).
// Mixed (Tanaka & Masunaga 2010): rho/dt div u* - gamma rho/dt^2 (n* - n0)/n0, far less pressure noise.
// The space the gas fills. Open: it borders open space (a domain open at the top), so gas with a low number density
// or too few neighbours is a free surface (p = 0) and negative gas pressures are set to 0, like the liquid's.
// Closed: the gas fills a closed box; every gas particle and the walls and liquid around it carry a pressure
// unknown (no free surface), and gas pressures may fall below the ambient: eq. (17)'s compressibility fixes their
// level. A void in closed gas then draws the gas in gently instead of being a free surface that the surrounding
// pressure accelerates the gas into at 1/rho_g (docs/waterfall.md).
enum class GasDomain { Open, Closed };

enum class PressureSource { Standard, Mixed };

// The liquid's pressure scheme (docs/validation.md). Paper: the MPS of Koshizuka & Oka the paper uses (walls carry
// pressure unknowns, dummies take the nearest wall's pressure extrapolated, the minimum-pressure gradient, p = 0 at
// free-surface particles). Stabilised: mirrored walls (wall_mirror.hpp), the corrected gradient
// (corrected_gradient.hpp), the first-order consistent Laplacian (laplacian_consistency.hpp) and the surface
// particles' pressure half a spacing inside the surface (surface_pressure.hpp): still water is an exact equilibrium.
enum class Scheme { Paper, Stabilised };

struct NumericsConfig {
  double particle_spacing = 0.0;        // l0 [m]; required
  Scheme scheme = Scheme::Paper;
  // Stabilised scheme only (numerical thresholds; how often they act is counted in diagnostics.csv):
  // a fluid particle carries a pressure unknown only if its liquid-side neighbours within the Laplacian radius give
  // at least this fraction of n0 (below it the mirrored walls would dominate its row: it is a free surface)
  double liquid_support_fraction = 0.3;  // 2D; the reader sets 0.2 in 3D (below a container corner's 0.29)
  // numerics.thin_row_pressure = "liquid": a row made free surface by liquid_support_fraction holds its liquid
  // neighbours' last pressure continued hydrostatically to it (solver_liquid_stabilised.cpp), not a free surface's
  // value: a particle crowded into a wall corner is inside the water. false ("surface"): the free surface's value.
  bool thin_rows_hold_liquid = false;
  // the corrected gradient falls back to the standard form where det(C_i^-1) is below this (1 on a full lattice)
  double gradient_correction_min_determinant = 0.3;
  // K of the repulsive part of the stabilised gradient (pressure_repulsion.hpp): zero in a linear pressure field, so
  // still water keeps its exact equilibrium; 0 = the corrected gradient alone
  double pressure_repulsion = 2.0;
  // A of the particle shifting after the correction (particle_shifting.hpp), delta r = -A l0 |u| dt P grad C: zero at
  // rest; 0 = none
  double particle_shifting = 3.0;
  // The concentration gradient of the shift (particle_shifting.hpp): "mps", the first moment of the MPS weight,
  // sum r w / r^2, which grows as 1/r^2 for a close pair; "wendland", the gradient of the Wendland C2 kernel of
  // support re as Lind et al. (2012) and Skillen et al. (2013) wrote the shift, which vanishes as r -> 0 and is
  // bounded (experimental, fiftieth session)
  enum class ShiftingKernel { Mps, Wendland };
  ShiftingKernel shifting_kernel = ShiftingKernel::Mps;
  // [l0] a guard: a particle shift longer than this is shortened to it (counted: shift_cuts in diagnostics.csv);
  // 0 = none. The shift's first moment grows as 1/r^2 for a close pair (docs/two-phase.md).
  double shift_limit = 0.0;
  // beta of the shift's stability bound (shift_stability.hpp): a particle's shift coefficient K is cut to
  // beta / S_i, S_i the sum of the norms of its pair terms' Jacobians, so that the explicit shift does not overshoot
  // between close neighbours (counted: shift_bounded in diagnostics.csv); 1 = the stability limit of a particle
  // between two neighbours on a line; 0 = none
  double shift_stability = 0.0;
  // a guard: a position-only displacement (the liquid's shift, the gas system's re-spacing of a bubble's gas) does not
  // approach a wall or dummy particle it would bring within collision_distance (wall_stop.hpp; counted:
  // shift_wall_stops and respacing_wall_stops in diagnostics.csv)
  bool shift_wall_stop = false;
  // a guard: a bubble's gas (which follows the water, bubble_gas_motion.hpp) does not move towards a wall or dummy
  // particle it would come within collision_distance of, by the water's velocity extended into the bubble nor by the
  // gas system's re-spacing (wall_stop.hpp; counted: bubble_gas_wall_stops and respacing_wall_stops)
  bool bubble_gas_wall_stop = false;
  // [l0] a guard: the gas system's re-spacing of a bubble's gas (a move without a velocity) is shortened to at most
  // this in a step (counted: respacing_cuts in diagnostics.csv); 0 = none
  double respacing_limit = 0.0;
  // numerics.respacing_walls = "slip": the gas system's re-spacing of a bubble's gas loses its component into the
  // walls within re (wall_slip.hpp; the no-penetration condition on the displacement; counted with the stops:
  // respacing_wall_stops); "free" (default): it is not told about the walls
  bool respacing_slip = false;
  // numerics.respacing_stop (a guard, counted: respacing_fluid_stops in diagnostics.csv): the gas system's re-spacing
  // of a bubble's gas does not approach a particle it would bring within collision_distance (wall_stop.hpp with these
  // particles as the walls): "water" the water around the bubble (its other wall), "fluid" every fluid particle, the
  // bubble's own gas too; "none" (default) neither
  enum class RespacingStop { None, Water, Fluid };
  RespacingStop respacing_stop = RespacingStop::None;
  double radius_number_density = 2.1;   // re / l0 for number density and gradient
  double radius_laplacian = 3.1;        // re / l0 for the Laplacian (13)
  double courant = 0.2;                 // dt <= courant * l0 / max|u|
  double dt_max = 1.0e-3;               // [s] cap on the time step
  double dt_min = 1.0e-8;               // [s] a step below this is a divergence
  double surface_threshold = 0.97;      // beta: n* < beta n0 -> free surface, p = 0
  // Also a free surface: a fluid particle with fewer neighbours within re than this fraction of a full
  // lattice's (0 = off). Catches the clumps of a splash, whose n* is high but whose neighbourhood is not.
  double surface_neighbour_fraction = 0.0;
  // Also a free surface: a fluid particle whose neighbours within re lie lopsided, |sum_j w_ij r_ij / |r_ij|| above
  // this fraction of n0 (0 = off; after the symmetric-arrangement criterion of Khayyer, Gotoh & Shao 2009).
  double surface_asymmetry = 0.0;
  double collision_distance = 0.5;      // too-close pair distance / l0
  double collision_restitution = 0.2;   // restitution of the collision model
  // The collision model's wall limit (collision.hpp; a guard, counted: collision_wall_limits in diagnostics.csv): a
  // velocity the pass changed keeps no approach to a wall or dummy particle within collision_distance.
  bool collision_wall_limit = false;
  // Passes of the collision model a stage (collision.hpp; experimental, 1 = the model as published): each pass after
  // the first reverses the approaching pairs within the distance that the pass before left or made, since a Jacobi
  // pass's reversal can send a particle into a third one that no pair of it saw (docs/waterfall.md, twenty-ninth
  // session). Its reversals count with the collisions.
  int collision_passes = 1;
  // numerics.entrained_gas_inertia: the mass the collision model gives the gas of an enclosed region below a bubble's
  // resolution, which takes part in the liquid system as liquid (phase_coupling.hpp) and is corrected with the
  // water's density: "liquid" (default since the fifty-first session) the water's, as it is moved; "gas" its own, so
  // water approaching it kept its approach (docs/waterfall.md, fifty-first session: a soft bubble squeezed to 1.7 n0
  // became such gas with water 0.5 l0 from it closing at 4.4 m/s)
  bool entrained_gas_liquid_inertia = true;
  // numerics.bubble_gas_inertia: the mass the collision model after the prediction gives a resolved bubble's gas
  // while it follows the liquid (bubble_gas_motion.hpp: its velocity is the water's extended into the bubble, it
  // carries no momentum of its own): "gas" (default) its own, so water closing on it keeps its approach; "liquid" the
  // water's, so the pair shares the approach as two water particles do (solver_collisions.cpp; docs/waterfall.md,
  // fifty-third session). The collision after the gas correction, which moves the gas alone, is the same either way.
  bool bubble_gas_liquid_inertia = false;
  // numerics.bubble_gas_in_water_density: how the rows outside the bubbles count a bubble's gas in their n*:
  // "particle" (default, the paper's n*) each gas particle as one; "volume" (both waterfall cases since the fifty-second
  // session) by the volume it stands for, n0 / n_j (solver_liquid.cpp, countBubbleGasByVolume), so a squeezed
  // bubble's crowded gas does not raise the water's n*
  bool bubble_gas_counts_by_volume = false;
  PressureSource pressure_source = PressureSource::Standard;
  double source_relaxation = 0.01;      // gamma of the mixed source term (ignored by "standard")
  // What gamma relaxes (sourceTermFor, mps/pressure_poisson.hpp): "step" (Tanaka & Masunaga), a fraction gamma of
  // the number-density error per step, whatever its length; "time", gamma per step of dt_max, so a step of dt
  // relaxes gamma dt/dt_max and the velocity the correction gives, ~ gamma delta L/dt_max, does not grow as the
  // Courant limit shortens the step.
  bool source_relaxation_per_time = false;
  PressureSolverKind pressure_solver = PressureSolverKind::HypreAmg;
  double solver_tolerance = 1.0e-8;     // relative residual |b - Ax| / |b|
  int solver_max_iterations = 1000;
  double max_escaped_fraction = 0.05;   // fluid fraction leaving the domain that stops the run
  int bubble_min_particles = 6;         // smaller gas regions inside the liquid move as liquid (docs/two-phase.md)
  // Which gas regions of a closed gas domain touching the liquid are pockets in it (enclosed, bubbles), whatever else
  // they border (enclosed_gas.hpp). Small: those below bubble_min_particles. Unvented: every one that holds no gas of a
  // vent (the atmosphere), but the largest (needs [[vent]]s).
  enum class ClosedPockets { Small, Unvented } closed_pockets = ClosedPockets::Small;
  GasDomain gas_domain = GasDomain::Open;
  // [m/s] terminal rise speed of entrained gas below a bubble's resolution (mps/entrained_gas_rise.hpp); 0 = none
  double entrained_gas_rise_speed = 0.0;
  // [m] diameter of the bubbles that entrained gas below a bubble's resolution stands for, moved as points through
  // the water by eq. (18) with its reaction returned to the water (mps/entrained_bubbles.hpp); 0 = off (the gas is
  // carried by the water, or swapped by entrained_gas_rise_speed)
  double entrained_bubble_diameter = 0.0;
  // Largest move of a gas particle by its pressure correction in one step, / l0 (0 = no limit; docs/waterfall.md)
  double gas_correction_limit = 0.0;
  // Gas particles closer than this (/ l0) belong to one gas region (enclosed_gas.hpp); 0 = radius_number_density
  double gas_region_link = 0.0;
  // Gas with at least this fraction of liquid among its neighbours is mixed into the water and joins no gas region
  // (enclosed_gas.hpp); 0 = off
  double dispersed_gas_fraction = 0.0;
  // Dispersed gas closer than this (/ l0) to gas that is not dispersed joins the nearest such particle's region
  // (enclosed_gas.hpp); 0 = off
  double dispersed_gas_touch = 0.0;
  // [m/s] largest speed of open gas after its pressure correction (solver_gas.cpp); 0 = no limit
  double gas_speed_limit = 0.0;
  // With pressure_source = "mixed", the compressible rows of eq. (17) carry the last pressure (the time-integrated
  // continuity equation of the gas; pressure_poisson.hpp), so compressed gas holds p = rho_g c^2 (n - n0)/n0.
  // Which rows carry it: the open gas's (the key gas_pressure_memory's `true` and "open_gas") and the bubbles' merged
  // rows (`true` and "bubbles"). Neither (the key's `false`, the default until the coupling is rebuilt,
  // docs/two-phase.md): the rows as before, where the gas settles at source_relaxation times that (100x too soft at
  // 0.01); the shipped bubble only rises with that softness.
  bool gas_pressure_memory_open = false;
  bool gas_pressure_memory_bubbles = false;
  // With the bubbles' memory: a fresh run's first step holds each bubble's row incompressible (no eq. (17) shift, no
  // memory), so a bubble present at t = 0 starts at the pressure the water around it needs (its hydrostatic
  // pressure), and the memory carries that on: p = P_0 + rho_g c^2 delta (the key's "water", the default). false
  // ("zero"): the bubble starts at the ambient 0 Pa and breathes about its hydrostatic pressure (the runs before the
  // twenty-sixth session). Bubbles that form later take the pressure the gas system gave their gas.
  bool bubble_start_at_water_pressure = true;
  // "stabilised" scheme, a bubble's gas following the liquid (bubble_gas_motion not "own_pressure"): its velocity is
  // no neighbour's velocity in the liquid's divergence (solver_liquid_stabilised.cpp). false ("interface", the
  // default): nor in its own bubble's rows, which then read only the water's velocity across the interface; true
  // ("whole_bubble"): the bubble's rows count each other's velocity, so that their sum is the flux of the extended
  // velocity through the interface, the bubble's volume change (docs/two-phase.md: with the memory term a bubble at
  // rest without gravity rings up from round-off with "interface", e-folding in 0.8 ms, and stays at rest with this).
  bool bubble_divergence_whole = false;
  // "joined" (experimental, 2D, two systems): the empty cavity a bubble's gas leaves in the water is part of the
  // bubble (bubble_cavity.hpp): the water bordering it joins the bubble's pressure unknown with its divergence (not
  // its truncated density term), the cavity's area counts in the bubble's density term, and the gas system's bubble
  // rows are never a free surface and take the whole density term (gamma = 1), so the gas spreads into the cavity.
  // false ("none", the default): the cavity's edge water is a free surface at the surface pressure, and no row sees
  // the cavity (docs/validation.md: the stiff coarse bubble's void +104 % at 0.1 s).
  bool bubble_cavity_joined = false;
  // numerics.bubble_surface_tension = "jump": a bubble's interface carries the Laplace jump P_B - p_l = sigma kappa
  // (physics.surface_tension; kappa from src/mps/interface_curvature.hpp, fitted over surface_tension_fit_radius l0)
  bool bubble_surface_tension = false;
  double surface_tension_fit_radius = 5.0;
  // The collision model (collision_distance, collision_restitution) once more after the gas system's correction, on
  // gas approaching liquid or walls: the correction can carry gas into a spray droplet, which the gas system holds
  // as a wall with its own pressure (solver_gas.cpp). Counted in `collisions`. false: after the prediction only.
  bool gas_collision_after_correction = false;
  // The collision model once more after the liquid correction, on liquid approaching a wall or dummy particle (the
  // water takes the whole reversal). The correction can leave a particle in a corner moving into the walls: the
  // mirrored walls hold its own pressure, so nothing in the next step's pressure pushes it back, and the collision
  // before the correction turns it round only for the correction to turn it in again (traced at 5 mm: a particle crept
  // into the floor/weir corner over 30 ms and was lost, docs/waterfall.md). Counted apart from `collisions`, in
  // `liquid_wall_collisions`.
  bool liquid_collision_after_correction = false;
  // coupling = "one_equation" (experimental): water short of neighbours (n* < surface_threshold n0) next to air holds
  // at least the air's pressure there (gap_water_floor.hpp: the gap is unresolved air, which cannot pull on the water;
  // without it the water going over a brink clings to the bed's face). A guard, counted (gap_water_floors).
  bool gap_water_floor = false;
  // The operators of the gas system (solver_gas.cpp; docs/two-phase.md). false ("paper"): the paper's MPS, wall
  // particles next to gas carry unknowns (their rows short of neighbours) and the gradient is the minimum-neighbour
  // form; still air under gravity drifts. true ("stabilised", experimental): mirrored walls (wall_mirror.hpp), the
  // corrected gradient away from the liquid (corrected_gradient.hpp; the minimum-neighbour form, with the walls
  // mirrored, next to it) and the particle shifting of numerics.particle_shifting on the open gas, so still air
  // is an equilibrium.
  bool gas_stabilised = false;
  // What a vent's gas (gas_vent.hpp) gives its neighbours' divergence. false ("buffer", the default): its column's
  // velocity, as an SPH open boundary's buffer particles (Tafuni et al. 2018). true ("zero_gradient"): nothing, as
  // if each neighbour's own velocity went on into the vent (a pressure outlet's zero normal gradient), so a column
  // cannot draw the air it follows (docs/waterfall.md: measured better at 1 cm, worse at the 5 mm roof vent).
  bool vent_zero_gradient = false;
  // A vent's column drawn inward onto liquid at its mouth is held (gas_vent.hpp; a guard, counted:
  // vent_liquid_stops in diagnostics.csv).
  bool vent_liquid_stop = false;
  // Gas entering a vent's box also leaves crowded where it would lie within l0/2 of the domain's gas just in front of
  // the box's inner face, in its column (gas_vent.cpp placeEnteringGas; counted in vent_crowded_out).
  bool vent_crowding_at_mouth = false;
  // How a bubble's gas moves (docs/two-phase.md). FollowLiquid: with the liquid's velocity extended into the bubble,
  // re-spaced in position by the gas system. OwnPressure: like open gas, by its own pressure gradient from the gas
  // system (the paper's single-phase view of the gas), velocity and position.
  enum class BubbleGasMotion { FollowLiquid, OwnPressure, FollowVoid } bubble_gas_motion = BubbleGasMotion::FollowLiquid;
  // The bubble's rows of the gas system use c = min(c_g, this * l0 / dt) (a regularisation: a bubble and its liquid
  // ring form a block with no free surface, whose pressure level an incompressible gas leaves undetermined); 0 = none
  double bubble_regularisation = 10.0;
  // How water and air share the pressure (docs/two-phase.md). TwoSystems: the paper's coupling as built (a liquid
  // system with one unknown per bubble, then a gas system with the liquid as moving walls). OneEquation: every fluid
  // particle of both phases in one variable-density projection with the interparticle density of
  // interface_density.hpp, on the stabilised scheme; no bubbles, gas system or gas guards.
  enum class Coupling { TwoSystems, OneEquation } coupling = Coupling::TwoSystems;
};

struct OutputConfig {
  double end_time = 1.0;   // [s]
  double interval = 0.01;  // [s] between frames / checkpoints
  double field_spacing = 0.0;  // [m] grid of the flow fields written per frame (fields/*.vti); 0 = none
};

// The sub-particle-scale texture stage (`mistfall texture`, src/texture, docs/texture.md).
struct TextureConfig {
  int seed = 1;                              // seeds every random stream of the texture
  double fine_diameter = 7.5e-5;             // d_m = d_b of mist and micro-bubbles [m]
  int representatives_per_source = 500;      // N, representatives shed per source
  double representative_ratio = 1.0 / 250;   // gamma_rm: each representative stands for 1/gamma_rm fine particles
  double source_diameter = 0.0;              // d_0 of a new source [m]; 0 = numerics.particle_spacing
  double source_lifetime = 0.5;              // [s] over which a source sheds its N representatives
  double added_mass = 0.5;                   // C_M of eq. (18)
  double width = 0.1;                        // extent across the fall [m] (2D runs: z of new sources)
  FluctuationModel fluctuation = FluctuationModel::Redrawn;
  double langevin_time_scale = 0.48;         // C_L in T_L = C_L Ds / (Ce sqrt(k))
  double time_step = 1.0e-3;                 // [s] texture step between frames
  double match_radius = 1.0;                 // [l0] frames without ids: isolated particles this close between frames are the same one
  double birth_grace = 0.02;                 // [s] a particle never yet in its carrying phase is kept this long
  bool run_inline = false;                   // key `inline`: simulate writes RUN_DIR/texture at every frame
  double file_interval = 0.0;                // [s] texture files only at frames nearest its multiples; 0 = every frame
  bool write_vtp = true;                     // key `vtp`: the ParaView copy texture_NNNNN.vtp beside each .bin
};

// The render stage (`mistfall render`, src/render). Positions are in the simulation's coordinates (a 2D run's
// third coordinate is across its extrusion, z in [-extrusion_width/2, extrusion_width/2]). The parser fills in
// every default (docs/case-file.md), so all fields hold the values used.
enum class RenderStyle { Natural, Lab };

struct RenderConfig {
  RenderStyle style = RenderStyle::Natural;  // scenery: render/natural.inc or render/lab.inc
  std::array<double, 3> camera_location{0.0, 0.0, 0.0};
  std::array<double, 3> camera_look_at{0.0, 0.0, 0.0};
  double camera_angle = 40.0;                // horizontal field of view [deg]
  std::array<double, 3> light_location{0.0, 0.0, 0.0};  // the sun (natural) or a point light (lab)
  int image_width = 640, image_height = 480;
  int preview_width = 192, preview_height = 144;
  double antialias = 0.3;                    // povray +A threshold at full size; 0: none
  double frame_interval = 0.0;               // [s] render the frames nearest to multiples of this; default
                                             // output.interval (every frame)
  double extrusion_width = 0.0;              // [m] a 2D run's water is extruded across this; default texture.width
  double sheet_variation = 0.0;              // [m] across-fall variation of a 2D run's outline; default 0.3 l0
  double variation_length = 0.0;             // [m] its length along the section; default 5 l0
  std::vector<std::string> hidden_regions;   // wall regions not drawn (a closed box's lid, an inflow gate)
  double bank_level = 0.0;                   // [m] top of the basin's banks (natural); default: lowest water
                                             // region's top + 2 l0
  double bank_width = 0.0;                   // [m] natural, 2D: rock beside the water across the fall; default
                                             // half the domain's larger extent
  double frame_rate = 25.0;                  // frames per second of the MP4 and GIF
  bool mist = true;                          // mist representatives as a participating medium (lab: spheres)
  double mist_voxel = 0.0;                   // [m] voxel of the mist's density grid; default l0
  bool white_water = true;                   // aerated water as scattering media inside the water
  double white_water_bubble_diameter = 2e-3;  // [m] bubble size of the air the MPS run resolves in the water
  double mist_radius = 0.0;                  // [m] lab style: drawn radius of a mist representative; default l0/4
  double micro_bubble_radius = 0.0;          // [m] lab style: drawn radius of a micro-bubble; default l0 / 4
};

struct CaseConfig {
  std::string name;
  int dimension = 2;
  Box domain;
  std::vector<Region> regions;
  std::vector<Inflow> inflows;
  std::vector<Outflow> outflows;
  std::vector<Vent> vents;
  PhysicsConfig physics;
  NumericsConfig numerics;
  OutputConfig output;
  ClassificationParameters classify;  // [classify]: the six-category classification (src/classify)
  TextureConfig texture;
  RenderConfig render;
};

const char* toString(PressureSolverKind k);
const char* toString(RenderStyle s);

}  // namespace mistfall

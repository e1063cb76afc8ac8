// Gas regions and enclosed bubbles of the gas-liquid model (MODEL.md, coupling (5)-(8)): the liquid ignores gas
// particles except those isolated inside the liquid (flag delta_gl), and the diagnostics report per bubble its
// mean pressure, centroid and area (2D) / volume (3D).
//
// Definitions (R = link_radius, the number-density radius re = 2.1 l0 in the solver):
//  * Gas particle: kind Fluid and phase Gas. Escaped particles (and every other kind) are never gas.
//  * Two gas particles are linked when |r_j - r_i| < J, the join radius (`join_radius`, numerics.gas_region_link;
//    R when 0), unless one of them is dispersed in the water (below). A gas region is a connected component of
//    that graph. With J = R = 2.1 l0 two gas particles with one water particle between them (2 l0 apart) are
//    linked, so a chain of air through aerated water joins the water's air pockets to the air above; J = 1.5 l0
//    links only touching particles (diagonals 1.41 l0). Region ids are 0, 1, ... in the order of the smallest
//    particle index of each component (deterministic).
//  * Dispersed gas (`dispersed_fraction` f > 0, numerics.dispersed_gas_fraction): a gas particle of which at least
//    the fraction f of its active neighbours within R are liquid fluid particles is air mixed into the water (the
//    churned plunge zone, a film of air between water particles). It links to no other gas particle, so it is a
//    region of its own, and a chain of such particles cannot join the water's air to the air above. Air next to a
//    flat water surface has 4 liquid neighbours of 12 (1/3) in 2D, air in a slot one particle wide 8 of 12.
//    With `dispersed_touch` T > 0 (numerics.dispersed_gas_touch) a dispersed particle closer than T to gas that is
//    not dispersed joins the region of the nearest such particle, and only that one (ties: the smallest index), so
//    air in a dip of the water's surface stays the open air it touches, and dispersed gas never bridges two
//    regions.
//  * A region is enclosed (a bubble) when both hold for every one of its particles i:
//      - every active non-gas particle j with |r_j - r_i| < R is a liquid fluid particle (no wall, no dummy);
//      - i has at least kEnclosedMinNeighbourFraction * full_count active neighbours (any kind) within R, where
//        full_count = #{ lattice points k in Z^D : 0 < |k| l0 < R } is the count of an interior lattice
//        particle (12 in 2D and 32 in 3D for R = 2.1 l0). A deficit means open space next to the gas, e.g.
//        the open top of the domain. A particle that was enclosed at the previous step (`was_enclosed`, when
//        given) is exempt from this count: inside a moving bubble the gas opens small gaps next to the liquid,
//        which do not make the bubble open. It is exempt from the first rule too (since the twentieth session): a
//        bubble that drifts onto a wall stays a bubble. As open gas it was invisible to the liquid, and a bubble
//        under waterfall_small's plunge point that came within R of the pool's floor was thrown out at 120 m/s
//        14 ms later (docs/two-phase.md). Gas that joins it unenclosed, or air that reaches the atmosphere, still
//        opens the region.
//    A lone gas particle surrounded by liquid is a bubble of one particle.
//  * In a closed gas domain (numerics.gas_domain = "closed", `closed_small_region` > 0) there is no open space, so
//    a region of fewer than closed_small_region particles that touches liquid is enclosed whatever else it borders
//    (walls, or gaps that leave it short of neighbours): a pocket of air dragged into the pool, against its floor or
//    between sparse water, is entrained gas, not open air. The largest region (the box's air) never is.
//    With `vent_of` (numerics.closed_pockets = "unvented": per particle, the vent holding it, or -1; a vent's gas is
//    the ambient's) the size limit goes: every region touching liquid that holds no vent's gas is a pocket, of any size.
//    An air pocket dragged under against a wall (the weir's face of the 5 mm waterfall, 18-20 particles) is then a
//    bubble with one pressure, where as open gas its rows saw only the water's motion as walls and it was kicked at
//    26-990 m/s (docs/waterfall.md).
//  * delta_gl (enclosed_particle) is 1 for the gas particles of enclosed regions, 0 otherwise.
//  * Bubble statistics (enclosed regions only, by region id): particle count N, mean pressure, centroid
//    (padded with 0 to three components) and size N l0^D (area in 2D, volume in 3D).
//
// The neighbour list must have been built with a radius >= R (pairs farther than R are filtered out here).
// Per-particle work is OpenMP-parallel; the components are joined serially, so the result does not depend on
// the thread count.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mps/neighbour_search.hpp"
#include "mps/particles.hpp"

namespace mistfall {

// A gas particle with fewer active neighbours than this fraction of the full lattice count borders open space.
inline constexpr double kEnclosedMinNeighbourFraction = 0.8;

struct GasRegions {
  std::vector<std::int32_t> region_of;  // per particle: gas-region id, or -1 for non-gas / inactive particles
  std::vector<char> enclosed;           // per region: 1 if the region is isolated inside liquid (a bubble)
  std::vector<char> enclosed_particle;  // per particle: delta_gl (1 for the gas particles of an enclosed region)
  std::size_t dispersed = 0;  // gas particles left out of their region by dispersed_fraction (not joined by touch)

  std::size_t regionCount() const { return enclosed.size(); }
  // The particles of each region.
  std::vector<std::size_t> regionSizes() const {
    std::vector<std::size_t> size(regionCount(), 0);
    for (std::int32_t r : region_of)
      if (r >= 0) ++size[static_cast<std::size_t>(r)];
    return size;
  }
};

struct BubbleStats {
  std::int32_t region = -1;              // id in GasRegions
  std::size_t particles = 0;             // N
  double mean_pressure = 0.0;            // [Pa]
  std::array<double, 3> centroid{0.0, 0.0, 0.0};  // [m], components beyond D are 0
  double size = 0.0;                     // N l0^D: area [m^2] in 2D, volume [m^3] in 3D
};

inline bool isGas(ParticleKind k, Phase ph) { return k == ParticleKind::Fluid && ph == Phase::Gas; }

// Number of lattice points k in Z^dimension with 0 < |k| l0 < link_radius (neighbours of an interior particle).
int latticeNeighbourCount(int dimension, double link_radius, double l0);

// The options of findGasRegions (see the definitions above); the defaults give the plain rule.
struct GasRegionOptions {
  const std::vector<char>* was_enclosed = nullptr;  // delta_gl of the previous step (per particle), if any
  std::size_t closed_small_region = 0;              // closed gas domain: the pocket size limit (0: open domain)
  double join_radius = 0.0;                         // [m]; 0: the link radius
  double dispersed_fraction = 0.0;                  // 0: no gas counts as dispersed
  double dispersed_touch = 0.0;                     // [m]; 0: dispersed gas joins nothing
  const std::vector<int>* vent_of = nullptr;        // closed gas domain: each particle's vent or -1 (pockets of any size)
};

template <int D>
void findGasRegions(const Particles<D>& p, const NeighbourList& nl, double link_radius, double l0, GasRegions& out,
                    const GasRegionOptions& options = {});

template <int D>
std::vector<BubbleStats> bubbleStatistics(const Particles<D>& p, const GasRegions& r, double l0);

}  // namespace mistfall

// Six-category classification, section 3.1 (MODEL.md section 2): every fluid particle is liquid bulk, liquid
// surface, droplet (isolated liquid particle), gas bulk, gas surface or bubble (isolated gas particle), from the
// level of its number density and the spatial rate of change of that density. As the paper says, the liquid
// particles are classified first counting liquid only, then the gas particles counting gas only; each phase
// sees the other as empty space, so the liquid's top row under air is liquid surface and the air's bottom row
// over the liquid is gas surface.
//
// For fluid particle i of phase ph, with w from eq. (14), re = numerics.radius_number_density * l0, sums over
// the neighbours j within re:
//   own phase      O_i: fluid and inflow particles of phase ph
//   own phase+walls A_i: O_i plus wall and dummy particles
//   n_own   = sum_{j in O_i} w(r_ij),   count_own = #O_i
//   n_all   = sum_{j in A_i} w(r_ij)
//   grad n  = sum_{j in A_i} (re / r_ij^3) (r_j - r_i)      the exact gradient at r_i of the number-density
//                                                            field n(x) = sum_j w(|x - r_j|) (w' = -re/r^2)
//   isolated (droplet / bubble)  if n_own < isolated_number_density n0
//                                   or count_own < isolated_neighbour_fraction * (interior lattice count)
//   surface                      else if n_all < surface_number_density n0
//                                   or |grad n| l0 / n0 > surface_gradient
//   bulk                         otherwise.
// Walls count for the surface test, so water lying on a wall is bulk on its wall side rather than surface; they
// do not count for isolation, so a lone particle touching a wall is still a droplet (or bubble).
// Wall, dummy, escaped and inflow particles are not fluid and get None. A point (entrained gas below a bubble's
// resolution, mps/entrained_bubbles.hpp) is a bubble: an isolated gas particle by how it is made.
//
// Per-particle OpenMP loop; each particle's category depends only on the neighbour list, so the result does not
// depend on the thread count.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "classify/classification_parameters.hpp"
#include "mps/neighbour_search.hpp"
#include "mps/particles.hpp"
#include "mps/reference_density.hpp"

namespace mistfall {

enum class Category : std::uint8_t {
  None = 0,  // not fluid: wall, dummy, escaped, inflow
  LiquidBulk = 1,
  LiquidSurface = 2,
  Droplet = 3,  // isolated liquid particle
  GasBulk = 4,
  GasSurface = 5,
  Bubble = 6,  // isolated gas particle
};

inline constexpr int kCategoryCount = 7;  // None and the six fluid categories

// "liquid_bulk", "liquid_surface", "droplet", "gas_bulk", "gas_surface", "bubble" ("none" for None): the
// names of the columns of categories.csv.
std::string_view categoryName(Category c);

// Classifies every particle. The neighbour list must hold every pair within c.re_number_density (a larger
// radius is fine: pairs farther than re are skipped).
template <int D>
std::vector<Category> classifyParticles(const Particles<D>& p, const NeighbourList& nl, const MpsConstants& c,
                                        const ClassificationParameters& params);

// The same with a neighbour list built here over the particles' bounding box (escaped particles ignored).
template <int D>
std::vector<Category> classifyParticles(const Particles<D>& p, const MpsConstants& c,
                                        const ClassificationParameters& params);

// Number of particles in each category, indexed by the category's value (0 = None).
std::array<std::size_t, kCategoryCount> countCategories(const std::vector<Category>& categories);

// The categories as bytes (the `category` point array of the frames).
std::vector<std::uint8_t> categoryBytes(const std::vector<Category>& categories);

}  // namespace mistfall

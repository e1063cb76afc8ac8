// Cell-linked-list neighbour search. Particles are binned into cubic cells of edge (radius + skin) / 3; each
// particle's neighbours (all j != i with |r_j - r_i| < radius + skin) are gathered from the 7^D surrounding cells
// into a compressed list (CSR), each particle's list in ascending index order. OpenMP-parallel over particles; the
// result does not depend on the thread count.
//
// The skin (Verlet list): a list built with a skin holds every pair that is within `radius` now as long as no
// particle has moved more than skin / 2 since the build (covers() checks it). Every operator filters the list by
// its own radius (<= radius) and visits the neighbours in index order, so its result is the same, bit for bit,
// whichever list it is given, as long as the list covers the positions: an older list with a skin and a fresh one
// give identical runs, and a resumed run (which starts with a fresh list) stays bit-identical to an unbroken one.
#pragma once

#include <cstdint>
#include <cmath>
#include <vector>

#include "mps/particles.hpp"

namespace mistfall {

struct NeighbourList {
  std::vector<std::int64_t> offsets;  // size N + 1; neighbours of i are indices[offsets[i] .. offsets[i+1])
  std::vector<std::int32_t> indices;

  std::size_t particleCount() const { return offsets.empty() ? 0 : offsets.size() - 1; }
  std::int64_t begin(std::size_t i) const { return offsets[i]; }
  std::int64_t end(std::size_t i) const { return offsets[i + 1]; }
};

template <int D>
class NeighbourSearch {
 public:
  // lower/upper bound the region where particles may be; particles marked Escaped are ignored.
  NeighbourSearch(const Vec<D>& lower, const Vec<D>& upper, double radius, double skin = 0.0);

  // Rebuilds the cells and the neighbour list for the given positions (and remembers them, for covers()).
  void build(const std::vector<Vec<D>>& position, const std::vector<ParticleKind>& kind, NeighbourList& out);
  // The same, remembering the particles' ids (for carryOver).
  void build(const std::vector<Vec<D>>& position, const std::vector<ParticleKind>& kind,
             const std::vector<std::uint64_t>& id, NeighbourList& out);

  // Whether the last list built still holds every pair within radius() at these positions: the same particles,
  // the same of them active, none moved more than skin / 2 since the build (with skin 0: none moved at all).
  bool covers(const std::vector<Vec<D>>& position, const std::vector<ParticleKind>& kind) const;
  // Carries the last list over particles removed and made since it was built (an outflow's, a vent's, an inflow's),
  // instead of a new build: possible when the particles are the build's survivors in their order (Particles::erase
  // keeps it), none moved more than skin / 2, then the new ones (Particles::add: larger ids, appended). The survivors'
  // lists are renumbered; a new particle's pairs are those within the reach of its position now, which counts as its
  // build position. The list then holds every pair within radius() as a new build would, each particle's in
  // ascending order, so every operator gives the same bits with it. Returns false, changing nothing, otherwise.
  bool carryOver(const std::vector<Vec<D>>& position, const std::vector<ParticleKind>& kind,
                 const std::vector<std::uint64_t>& id, NeighbourList& out);
  // Each particle's position at the build (or, for one made since, at the carry-over that listed it): the positions
  // a list filtered for a smaller reach must be filtered at (filterNeighbours).
  const std::vector<Vec<D>>& builtPositions() const { return built_position_; }

  double radius() const { return radius_; }
  double skin() const { return skin_; }
  // The index of the cell holding x (cells in row-major order, the last axis slowest; positions off the grid in its
  // edge cells, non-finite ones in cell 0): particles in this order make the build's cell lists contiguous.
  std::int64_t cellKey(const Vec<D>& x) const {
    return std::isfinite(x.squaredNorm()) ? cellIndex(cellOf(x)) : 0;
  }
  std::int64_t builds() const { return builds_; }

 private:
  std::int64_t cellIndex(const Eigen::Matrix<std::int64_t, D, 1>& c) const;
  // Bins the listed particles (particle_cell_ >= 0) into cell_start_ / sorted_, each cell in ascending index order.
  void binParticles();
  // Calls visit(j) for every binned particle j in the cells within one reach of x's cell.
  template <class Visit>
  void forEachCandidate(const Vec<D>& x, Visit&& visit) const;
  Eigen::Matrix<std::int64_t, D, 1> cellOf(const Vec<D>& x) const;

  Vec<D> lower_;
  double radius_;
  double skin_;
  double cell_size_;
  Eigen::Matrix<std::int64_t, D, 1> cells_;
  std::vector<std::int64_t> cell_start_;     // size ncells + 1
  std::vector<std::int32_t> sorted_;         // particle indices grouped by cell
  std::vector<std::int64_t> particle_cell_;  // cell of each particle, -1 when ignored
  std::vector<std::vector<std::int32_t>> thread_lists_;  // per thread: the lists of its block of particles
  std::vector<Vec<D>> built_position_;       // positions at the last build
  std::vector<std::uint64_t> built_id_;      // ids at the last build (empty: not known, no carry-over)
  std::uint64_t built_next_id_ = 0;          // above every id of the last build
  std::int64_t builds_ = 0;
};

// The pairs of `list` closer than `reach` at `position`, each particle's in the same (ascending) order: a list built
// with radius R and skin s, filtered at its build positions with reach r + s (r <= R), holds every pair within r
// for as long as the full list covers the positions (NeighbourSearch::covers), so operators of radius r give the same
// bits with it and visit fewer pairs (in 2D, (r + s)^2 / (R + s)^2 of them).
template <int D>
void filterNeighbours(const std::vector<Vec<D>>& position, const NeighbourList& list, double reach, NeighbourList& out);

}  // namespace mistfall

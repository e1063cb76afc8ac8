// Cell-linked-list neighbour search. Particles are binned into cubic cells of edge >= radius; each
// particle's neighbours (all j != i with |r_j - r_i| < radius) are gathered from the 3^D surrounding
// cells into a compressed list (CSR). Rebuilt every step; OpenMP-parallel over particles; the result
// does not depend on the thread count (each particle's list is in cell-then-index order).
#pragma once

#include <cstdint>
#include <vector>

#include "mps/particles.hpp"

namespace mistfall {

struct NeighborList {
  std::vector<std::int64_t> offsets;  // size N + 1; neighbours of i are indices[offsets[i] .. offsets[i+1])
  std::vector<std::int32_t> indices;

  std::size_t particleCount() const { return offsets.empty() ? 0 : offsets.size() - 1; }
  std::int64_t begin(std::size_t i) const { return offsets[i]; }
  std::int64_t end(std::size_t i) const { return offsets[i + 1]; }
};

template <int D>
class NeighborSearch {
 public:
  // lower/upper bound the region where particles may be; particles marked Escaped are ignored.
  NeighborSearch(const Vec<D>& lower, const Vec<D>& upper, double radius);

  // Rebuilds the cells and the neighbour list for the given positions.
  void build(const std::vector<Vec<D>>& position, const std::vector<ParticleKind>& kind, NeighborList& out);

  double radius() const { return radius_; }

 private:
  std::int64_t cellIndex(const Eigen::Matrix<std::int64_t, D, 1>& c) const;
  Eigen::Matrix<std::int64_t, D, 1> cellOf(const Vec<D>& x) const;

  Vec<D> lower_;
  double radius_;
  double cell_size_;
  Eigen::Matrix<std::int64_t, D, 1> cells_;
  std::vector<std::int64_t> cell_start_;     // size ncells + 1
  std::vector<std::int32_t> sorted_;         // particle indices grouped by cell
  std::vector<std::int64_t> particle_cell_;  // cell of each particle, -1 when ignored
};

}  // namespace mistfall

#include "mps/neighbor_search.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mistfall {

template <int D>
NeighborSearch<D>::NeighborSearch(const Vec<D>& lower, const Vec<D>& upper, double radius)
    : radius_(radius), cell_size_(radius) {
  if (!(radius > 0.0)) throw std::invalid_argument("neighbour search radius must be positive");
  // One spare cell on each side so that neighbours of boundary cells never fall off the grid.
  lower_ = lower.array() - cell_size_;
  for (int k = 0; k < D; ++k) {
    cells_[k] = static_cast<std::int64_t>(std::ceil((upper[k] - lower[k]) / cell_size_)) + 2;
    if (cells_[k] < 1) cells_[k] = 1;
  }
}

template <int D>
Eigen::Matrix<std::int64_t, D, 1> NeighborSearch<D>::cellOf(const Vec<D>& x) const {
  Eigen::Matrix<std::int64_t, D, 1> c;
  for (int k = 0; k < D; ++k) {
    const double f = std::floor((x[k] - lower_[k]) / cell_size_);
    c[k] = std::clamp<std::int64_t>(static_cast<std::int64_t>(f), 0, cells_[k] - 1);
  }
  return c;
}

template <int D>
std::int64_t NeighborSearch<D>::cellIndex(const Eigen::Matrix<std::int64_t, D, 1>& c) const {
  std::int64_t idx = 0;
  for (int k = D - 1; k >= 0; --k) idx = idx * cells_[k] + c[k];
  return idx;
}

template <int D>
void NeighborSearch<D>::build(const std::vector<Vec<D>>& position, const std::vector<ParticleKind>& kind,
                              NeighborList& out) {
  const std::int64_t n = static_cast<std::int64_t>(position.size());
  std::int64_t ncells = 1;
  for (int k = 0; k < D; ++k) ncells *= cells_[k];

  // Counting sort of particles into cells.
  particle_cell_.assign(n, -1);
  cell_start_.assign(ncells + 1, 0);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (!std::isfinite(position[i].squaredNorm())) continue;
    if (isActive(kind[i])) particle_cell_[i] = cellIndex(cellOf(position[i]));
  }
  for (std::int64_t i = 0; i < n; ++i)
    if (particle_cell_[i] >= 0) ++cell_start_[particle_cell_[i] + 1];
  for (std::int64_t c = 0; c < ncells; ++c) cell_start_[c + 1] += cell_start_[c];
  sorted_.resize(cell_start_[ncells]);
  {
    std::vector<std::int64_t> fill(cell_start_.begin(), cell_start_.end() - 1);
    for (std::int64_t i = 0; i < n; ++i)
      if (particle_cell_[i] >= 0) sorted_[fill[particle_cell_[i]]++] = static_cast<std::int32_t>(i);
  }

  const double r2 = radius_ * radius_;
  // Visits every j within the radius of particle i.
  auto forEachNeighbour = [&](std::int64_t i, auto&& visit) {
    const auto c = cellOf(position[i]);
    Eigen::Matrix<std::int64_t, D, 1> lo, hi;
    for (int k = 0; k < D; ++k) {
      lo[k] = std::max<std::int64_t>(c[k] - 1, 0);
      hi[k] = std::min<std::int64_t>(c[k] + 1, cells_[k] - 1);
    }
    Eigen::Matrix<std::int64_t, D, 1> cc = lo;
    while (true) {
      const std::int64_t cell = cellIndex(cc);
      for (std::int64_t s = cell_start_[cell]; s < cell_start_[cell + 1]; ++s) {
        const std::int32_t j = sorted_[s];
        if (j != i && (position[j] - position[i]).squaredNorm() < r2) visit(j);
      }
      int k = 0;
      for (; k < D; ++k) {
        if (++cc[k] <= hi[k]) break;
        cc[k] = lo[k];
      }
      if (k == D) break;
    }
  };

  out.offsets.assign(n + 1, 0);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t i = 0; i < n; ++i) {
    if (particle_cell_[i] < 0) continue;
    std::int64_t count = 0;
    forEachNeighbour(i, [&](std::int32_t) { ++count; });
    out.offsets[i + 1] = count;
  }
  for (std::int64_t i = 0; i < n; ++i) out.offsets[i + 1] += out.offsets[i];
  out.indices.resize(out.offsets[n]);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t i = 0; i < n; ++i) {
    if (particle_cell_[i] < 0) continue;
    std::int64_t at = out.offsets[i];
    forEachNeighbour(i, [&](std::int32_t j) { out.indices[at++] = j; });
  }
}

template class NeighborSearch<2>;
template class NeighborSearch<3>;

}  // namespace mistfall

#include "mps/neighbour_search.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mistfall {

namespace {
// Cells per reach (radius + skin): a particle's candidates are the (2k+1)^D cells around its own, a box of
// (2 + 1/k) reaches a side instead of 3. Also the grid the particles are sorted by (spatial_order.hpp). Measured,
// 1 thread: waterfall.toml 5.4-5.5 s 118 (k = 1), 106 (2), 103 ms a step (3); waterfall_small 0-1 s 23.1 -> 21.4 ms;
// the 40k dam break's first steps (idle machine, with the sort) 94.9 -> 88.8 ms.
constexpr int kCellsPerReach = 3;
}  // namespace

template <int D>
NeighbourSearch<D>::NeighbourSearch(const Vec<D>& lower, const Vec<D>& upper, double radius, double skin)
    : radius_(radius), skin_(skin), cell_size_((radius + skin) / kCellsPerReach) {
  if (!(radius > 0.0)) throw std::invalid_argument("neighbour search radius must be positive");
  if (!(skin >= 0.0)) throw std::invalid_argument("neighbour search skin must not be negative");
  // kCellsPerReach spare cells on each side so that neighbours of boundary cells never fall off the grid.
  lower_ = lower.array() - kCellsPerReach * cell_size_;
  for (int k = 0; k < D; ++k) {
    cells_[k] = static_cast<std::int64_t>(std::ceil((upper[k] - lower[k]) / cell_size_)) + 2 * kCellsPerReach;
    if (cells_[k] < 1) cells_[k] = 1;
  }
}

template <int D>
Eigen::Matrix<std::int64_t, D, 1> NeighbourSearch<D>::cellOf(const Vec<D>& x) const {
  Eigen::Matrix<std::int64_t, D, 1> c;
  for (int k = 0; k < D; ++k) {
    const double f = std::floor((x[k] - lower_[k]) / cell_size_);
    c[k] = std::clamp<std::int64_t>(static_cast<std::int64_t>(f), 0, cells_[k] - 1);
  }
  return c;
}

template <int D>
std::int64_t NeighbourSearch<D>::cellIndex(const Eigen::Matrix<std::int64_t, D, 1>& c) const {
  std::int64_t idx = 0;
  for (int k = D - 1; k >= 0; --k) idx = idx * cells_[k] + c[k];
  return idx;
}

template <int D>
void NeighbourSearch<D>::binParticles() {
  const std::int64_t n = static_cast<std::int64_t>(particle_cell_.size());
  std::int64_t ncells = 1;
  for (int k = 0; k < D; ++k) ncells *= cells_[k];
  cell_start_.assign(ncells + 1, 0);
  for (std::int64_t i = 0; i < n; ++i)
    if (particle_cell_[i] >= 0) ++cell_start_[particle_cell_[i] + 1];
  for (std::int64_t c = 0; c < ncells; ++c) cell_start_[c + 1] += cell_start_[c];
  sorted_.resize(cell_start_[ncells]);
  std::vector<std::int64_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::int64_t i = 0; i < n; ++i)
    if (particle_cell_[i] >= 0) sorted_[fill[particle_cell_[i]]++] = static_cast<std::int32_t>(i);
}

template <int D>
template <class Visit>
void NeighbourSearch<D>::forEachCandidate(const Vec<D>& x, Visit&& visit) const {
  const auto c = cellOf(x);
  Eigen::Matrix<std::int64_t, D, 1> lo, hi;
  for (int k = 0; k < D; ++k) {
    lo[k] = std::max<std::int64_t>(c[k] - kCellsPerReach, 0);
    hi[k] = std::min<std::int64_t>(c[k] + kCellsPerReach, cells_[k] - 1);
  }
  // The cells of one row along the first axis are consecutive, so each row is one run of `sorted_`.
  const std::int64_t row_cells = hi[0] - lo[0];
  Eigen::Matrix<std::int64_t, D, 1> cc = lo;
  while (true) {
    const std::int64_t first_cell = cellIndex(cc);
    for (std::int64_t s = cell_start_[first_cell]; s < cell_start_[first_cell + row_cells + 1]; ++s) visit(sorted_[s]);
    int k = 1;
    for (; k < D; ++k) {
      if (++cc[k] <= hi[k]) break;
      cc[k] = lo[k];
    }
    if (k == D) break;
  }
}

template <int D>
void NeighbourSearch<D>::build(const std::vector<Vec<D>>& position, const std::vector<ParticleKind>& kind,
                              const std::vector<std::uint64_t>& id, NeighbourList& out) {
  build(position, kind, out);
  built_id_ = id;
  built_next_id_ = 0;
  for (const std::uint64_t i : id) built_next_id_ = std::max(built_next_id_, i + 1);
}

template <int D>
void NeighbourSearch<D>::build(const std::vector<Vec<D>>& position, const std::vector<ParticleKind>& kind,
                              NeighbourList& out) {
  const std::int64_t n = static_cast<std::int64_t>(position.size());
  ++builds_;
  built_id_.clear();

  // Counting sort of particles into cells (each cell's particles in ascending index order).
  particle_cell_.resize(n);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    particle_cell_[i] = -1;
    if (!std::isfinite(position[i].squaredNorm())) continue;
    if (isActive(kind[i])) particle_cell_[i] = cellIndex(cellOf(position[i]));
  }
  binParticles();

  const double reach = radius_ + skin_;
  const double r2 = reach * reach;
  // Appends every j within the reach of particle i to `list`.
  auto gather = [&](std::int64_t i, std::vector<std::int32_t>& list) {
    const Vec<D> xi = position[i];
    forEachCandidate(xi, [&](std::int32_t j) {
      if (j != i && (position[j] - xi).squaredNorm() < r2) list.push_back(j);
    });
  };

  // One pass: each thread gathers the lists of a contiguous block of particles into its own buffer (each list
  // sorted by index), then the blocks are copied into place in particle order.
  out.offsets.resize(n + 1);
  out.offsets[0] = 0;
  thread_lists_.resize(std::max(1, omp_get_max_threads()));
#pragma omp parallel
  {
    const std::int64_t t = omp_get_thread_num(), nt = omp_get_num_threads();
    const std::int64_t first = n * t / nt, last = n * (t + 1) / nt;
    auto& list = thread_lists_[t];
    list.clear();
    for (std::int64_t i = first; i < last; ++i) {
      const std::size_t start = list.size();
      if (particle_cell_[i] >= 0) {
        gather(i, list);
        // (already in order when the particles are in cell order: spatial_order.hpp)
        if (!std::is_sorted(list.begin() + static_cast<std::ptrdiff_t>(start), list.end()))
          std::sort(list.begin() + static_cast<std::ptrdiff_t>(start), list.end());
      }
      out.offsets[i + 1] = static_cast<std::int64_t>(list.size() - start);
    }
#pragma omp barrier
#pragma omp single
    {
      for (std::int64_t i = 0; i < n; ++i) out.offsets[i + 1] += out.offsets[i];
      out.indices.resize(out.offsets[n]);
    }
    if (first < last) std::copy(list.begin(), list.end(), out.indices.begin() + out.offsets[first]);
  }
  built_position_.assign(position.begin(), position.end());
}

template <int D>
bool NeighbourSearch<D>::covers(const std::vector<Vec<D>>& position, const std::vector<ParticleKind>& kind) const {
  const std::int64_t n = static_cast<std::int64_t>(position.size());
  if (builds_ == 0 || static_cast<std::int64_t>(built_position_.size()) != n ||
      static_cast<std::int64_t>(particle_cell_.size()) != n)
    return false;
  // Strictly below half the skin, with a margin for the round-off of the distances.
  const double limit = 0.5 * skin_ * (1.0 - 1e-9);
  const double limit2 = limit * limit;
  bool ok = true;
#pragma omp parallel for schedule(static) reduction(&& : ok)
  for (std::int64_t i = 0; i < n; ++i) {
    const bool listed = particle_cell_[i] >= 0;
    const bool active = isActive(kind[i]) && std::isfinite(position[i].squaredNorm());
    ok = ok && listed == active && (!active || (position[i] - built_position_[i]).squaredNorm() <= limit2);
  }
  return ok;
}

template <int D>
bool NeighbourSearch<D>::carryOver(const std::vector<Vec<D>>& position, const std::vector<ParticleKind>& kind,
                                  const std::vector<std::uint64_t>& id, NeighbourList& out) {
  const std::int64_t n = static_cast<std::int64_t>(position.size());
  const std::int64_t built = static_cast<std::int64_t>(built_id_.size());
  if (builds_ == 0 || built == 0 || static_cast<std::int64_t>(id.size()) != n ||
      static_cast<std::int64_t>(out.particleCount()) != built)
    return false;
  // The survivors first, in the build's order, then the particles made since (ids from built_next_id_ on).
  std::int64_t survivors = 0;
  while (survivors < n && id[survivors] < built_next_id_) ++survivors;
  for (std::int64_t i = survivors; i < n; ++i)
    if (id[i] < built_next_id_) return false;
  if (survivors == built && n == built) return false;  // nothing removed or made: covers() decides
  std::vector<std::int32_t> new_of(built, -1), old_of(survivors, -1);
  for (std::int64_t i = 0, o = 0; i < survivors; ++i, ++o) {
    while (o < built && built_id_[o] != id[i]) ++o;
    if (o == built) return false;
    new_of[o] = static_cast<std::int32_t>(i);
    old_of[i] = static_cast<std::int32_t>(o);
  }
  // The survivors as covers() wants them; the new particles active where they are.
  const double limit = 0.5 * skin_ * (1.0 - 1e-9);
  bool ok = true;
#pragma omp parallel for schedule(static) reduction(&& : ok)
  for (std::int64_t i = 0; i < n; ++i) {
    const bool active = isActive(kind[i]) && std::isfinite(position[i].squaredNorm());
    if (i >= survivors) {
      ok = ok && active;
      continue;
    }
    const auto o = old_of[i];
    ok = ok && (particle_cell_[o] >= 0) == active &&
         (!active || (position[i] - built_position_[o]).squaredNorm() <= limit * limit);
  }
  if (!ok) return false;

  // The new particles' pairs: the survivors (at their build positions, found through the build's cells) and each
  // other, within the reach of where they are now.
  const double reach2 = (radius_ + skin_) * (radius_ + skin_);
  std::vector<std::vector<std::int32_t>> made(n - survivors);
  std::vector<std::vector<std::int32_t>> extra(survivors);  // new particles to append to a survivor's list
  for (std::int64_t k = survivors; k < n; ++k) {
    auto& list = made[k - survivors];
    forEachCandidate(position[k], [&](std::int32_t o) {
      if (new_of[o] >= 0 && (built_position_[o] - position[k]).squaredNorm() < reach2) list.push_back(new_of[o]);
    });
    std::sort(list.begin(), list.end());
    for (const std::int32_t i : list) extra[i].push_back(static_cast<std::int32_t>(k));
    for (std::int64_t m = survivors; m < n; ++m)
      if (m != k && (position[m] - position[k]).squaredNorm() < reach2) list.push_back(static_cast<std::int32_t>(m));
  }
  // The new list: each survivor's old pairs renumbered (in order: the renumbering keeps it), then the new particles.
  NeighbourList next;
  next.offsets.assign(n + 1, 0);
  for (std::int64_t i = 0; i < n; ++i) {
    std::int64_t count = 0;
    if (i < survivors) {
      for (auto s = out.begin(old_of[i]); s < out.end(old_of[i]); ++s) count += new_of[out.indices[s]] >= 0;
      count += static_cast<std::int64_t>(extra[i].size());
    } else {
      count = static_cast<std::int64_t>(made[i - survivors].size());
    }
    next.offsets[i + 1] = next.offsets[i] + count;
  }
  next.indices.resize(static_cast<std::size_t>(next.offsets[n]));
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    auto at = next.indices.begin() + next.offsets[i];
    if (i < survivors) {
      for (auto s = out.begin(old_of[i]); s < out.end(old_of[i]); ++s)
        if (new_of[out.indices[s]] >= 0) *at++ = new_of[out.indices[s]];
      at = std::copy(extra[i].begin(), extra[i].end(), at);
    } else {
      std::copy(made[i - survivors].begin(), made[i - survivors].end(), at);
    }
  }
  out = std::move(next);
  // The build's record, renumbered: survivors keep their build positions, the new particles take theirs now.
  std::vector<Vec<D>> built_position(n);
  std::vector<std::int64_t> particle_cell(n);
  for (std::int64_t i = 0; i < n; ++i) {
    built_position[i] = i < survivors ? built_position_[old_of[i]] : position[i];
    particle_cell[i] = i < survivors ? particle_cell_[old_of[i]] : cellIndex(cellOf(position[i]));
  }
  built_position_ = std::move(built_position);
  particle_cell_ = std::move(particle_cell);
  binParticles();
  built_id_ = id;
  for (std::int64_t k = survivors; k < n; ++k) built_next_id_ = std::max(built_next_id_, id[k] + 1);
  ++builds_;
  return true;
}

template <int D>
void filterNeighbours(const std::vector<Vec<D>>& position, const NeighbourList& list, double reach, NeighbourList& out) {
  const std::int64_t n = static_cast<std::int64_t>(list.particleCount());
  const double reach2 = reach * reach;
  auto near = [&](std::int64_t i, std::int32_t j) { return (position[j] - position[i]).squaredNorm() < reach2; };
  out.offsets.assign(n + 1, 0);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    std::int64_t count = 0;
    for (auto s = list.begin(i); s < list.end(i); ++s) count += near(i, list.indices[s]);
    out.offsets[i + 1] = count;
  }
  for (std::int64_t i = 0; i < n; ++i) out.offsets[i + 1] += out.offsets[i];
  out.indices.resize(static_cast<std::size_t>(out.offsets[n]));
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    std::int64_t at = out.offsets[i];
    for (auto s = list.begin(i); s < list.end(i); ++s)
      if (near(i, list.indices[s])) out.indices[at++] = list.indices[s];
  }
}

template class NeighbourSearch<2>;
template class NeighbourSearch<3>;
template void filterNeighbours<2>(const std::vector<Vec<2>>&, const NeighbourList&, double, NeighbourList&);
template void filterNeighbours<3>(const std::vector<Vec<3>>&, const NeighbourList&, double, NeighbourList&);

}  // namespace mistfall

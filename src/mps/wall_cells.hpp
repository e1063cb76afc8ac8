// The walls' and dummies' positions binned in cells of edge re, to read the walls near any point, not only near a
// particle's position at the neighbour list's build: a position-only move longer than the list's reach (a bubble gas's
// re-spacing of several spacings, wall_slip.hpp) must see the walls along its whole path. The walls are fixed, so the
// bins hold for as long as no wall particle is added or removed. Dense cells over the walls' bounding box; a point
// outside it reads the cells of the box within one cell of it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "mps/vector.hpp"
#include "mps/weight.hpp"

namespace mistfall {

template <int D>
class WallCells {
 public:
  // Bins position[j] for every j with fixed(j).
  template <class Fixed>
  WallCells(const std::vector<Vec<D>>& position, Fixed&& fixed, double re) : re_(re) {
    lower_ = Vec<D>::Constant(std::numeric_limits<double>::infinity());
    Vec<D> upper = -lower_;
    std::vector<Vec<D>> wall;
    for (std::size_t j = 0; j < position.size(); ++j)
      if (fixed(static_cast<std::int32_t>(j)) && position[j].allFinite()) {
        wall.push_back(position[j]);
        lower_ = lower_.cwiseMin(position[j]);
        upper = upper.cwiseMax(position[j]);
      }
    if (wall.empty()) return;
    std::int64_t cells = 1;
    for (int d = 0; d < D; ++d) {
      count_[d] = static_cast<std::int64_t>(std::floor((upper[d] - lower_[d]) / re_)) + 1;
      cells *= count_[d];
    }
    std::vector<std::int64_t> cell_of(wall.size());
    start_.assign(cells + 1, 0);
    for (std::size_t k = 0; k < wall.size(); ++k) ++start_[(cell_of[k] = cellIndex(cellOf(wall[k]))) + 1];
    for (std::int64_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
    sorted_.resize(wall.size());
    std::vector<std::int64_t> next(start_.begin(), start_.end() - 1);
    for (std::size_t k = 0; k < wall.size(); ++k) sorted_[next[cell_of[k]]++] = wall[k];
  }

  // The first moment of the walls within re of x, sum r w(|r|) / |r|^2 with r = r_wall - x (the form of
  // neighbourhoodFirstMoment, particle_shifting.hpp): it points from x into the walls.
  Vec<D> firstMoment(const Vec<D>& x) const {
    Vec<D> first = Vec<D>::Zero();
    if (sorted_.empty() || !x.allFinite()) return first;
    Eigen::Matrix<std::int64_t, D, 1> c = cellOf(x), lo, hi;
    for (int d = 0; d < D; ++d) {
      lo[d] = std::max<std::int64_t>(c[d] - 1, 0);
      hi[d] = std::min<std::int64_t>(c[d] + 1, count_[d] - 1);
      if (lo[d] > hi[d]) return first;
    }
    Eigen::Matrix<std::int64_t, D, 1> k = lo;
    while (true) {
      const std::int64_t cell = cellIndex(k);
      for (std::int64_t s = start_[cell]; s < start_[cell + 1]; ++s) {
        const Vec<D> r = sorted_[s] - x;
        const double r2 = r.squaredNorm();
        const double w = r2 > 0.0 ? weight(std::sqrt(r2), re_) : 0.0;
        if (w > 0.0) first += r * (w / r2);
      }
      int d = 0;
      while (d < D && ++k[d] > hi[d]) k[d] = lo[d], ++d;
      if (d == D) break;
    }
    return first;
  }

 private:
  Eigen::Matrix<std::int64_t, D, 1> cellOf(const Vec<D>& x) const {
    Eigen::Matrix<std::int64_t, D, 1> c;
    for (int d = 0; d < D; ++d) {
      const double f = std::floor((x[d] - lower_[d]) / re_);
      // a point far off the box reads no cell (clamped just outside it, so that lo > hi above)
      c[d] = static_cast<std::int64_t>(std::clamp(f, -2.0, static_cast<double>(count_[d] + 1)));
    }
    return c;
  }
  std::int64_t cellIndex(const Eigen::Matrix<std::int64_t, D, 1>& c) const {
    std::int64_t index = 0;
    for (int d = D - 1; d >= 0; --d) index = index * count_[d] + c[d];
    return index;
  }

  double re_;
  Vec<D> lower_;
  Eigen::Matrix<std::int64_t, D, 1> count_ = Eigen::Matrix<std::int64_t, D, 1>::Zero();
  std::vector<Vec<D>> sorted_;
  std::vector<std::int64_t> start_;
};

}  // namespace mistfall

// The amg solver's V-cycle: amg_cycle.hpp.
#include "mps/amg_cycle.hpp"

#include <algorithm>

namespace mistfall::amg {

int Level::blocks() const {
  return static_cast<int>(std::clamp<std::int64_t>(a.n / kMinBlockRows, 1, kBlocks));
}

void Level::setBlocks() {
  const std::int64_t n = a.n;
  block.resize(n);
  inside.resize(n);
  const int count = blocks();
  for (int k = 0; k < count; ++k)
    for (std::int64_t i = n * k / count; i < n * (k + 1) / count; ++i) block[i] = k;
#pragma omp parallel for schedule(static) if (n >= kParallelRows)
  for (std::int64_t i = 0; i < n; ++i) {
    bool in = true;
    for (int k = a.start[i]; k < a.start[i + 1]; ++k) in = in && block[a.column[k]] == block[i];
    inside[i] = in;
  }
}

void smooth(Level& level, bool forward) {
  const Rows& a = level.a;
  const std::int64_t n = a.n;
  Eigen::VectorXd& x = level.x;
  level.old = x;
  const Eigen::VectorXd& old = level.old;
  const Eigen::VectorXd& b = level.b;
  const int blocks = level.blocks();
#pragma omp parallel for schedule(static) if (n >= kParallelRows)
  for (int block = 0; block < blocks; ++block) {
    const std::int64_t first = n * block / blocks, last = n * (block + 1) / blocks;
    auto relax = [&](std::int64_t i) {
      const int d = a.diagonal[i];
      double s = b[i];
      if (level.inside[i]) {  // Gauss-Seidel: the newest values
        for (int k = a.start[i]; k < d; ++k) s -= a.value[k] * x[a.column[k]];
        for (int k = d + 1; k < a.start[i + 1]; ++k) s -= a.value[k] * x[a.column[k]];
      } else {  // next to another block: its values from before the sweep (Jacobi between blocks)
        for (int k = a.start[i]; k < a.start[i + 1]; ++k) {
          if (k == d) continue;
          const int j = a.column[k];
          s -= a.value[k] * (level.block[j] == block ? x[j] : old[j]);
        }
      }
      x[i] = s / a.value[d];
    };
    if (forward)
      for (std::int64_t i = first; i < last; ++i) relax(i);
    else
      for (std::int64_t i = last - 1; i >= first; --i) relax(i);
  }
}

void VCycle::factorCoarsest(const Rows& coarsest) {
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(coarsest.n, coarsest.n);
  for (std::int64_t i = 0; i < coarsest.n; ++i)
    for (int k = coarsest.start[i]; k < coarsest.start[i + 1]; ++k) dense(i, coarsest.column[k]) = coarsest.value[k];
  coarse_llt_.compute(dense);
  coarse_ok_ = coarse_llt_.info() == Eigen::Success;
  if (!coarse_ok_) coarse_ldlt_.compute(dense);
}

void VCycle::run(std::size_t l) {
  Level& level = levels[l];
  if (l + 1 == levels.size()) {
    if (coarse_dense) {
      level.x = coarse_ok_ ? Eigen::VectorXd(coarse_llt_.solve(level.b)) : Eigen::VectorXd(coarse_ldlt_.solve(level.b));
    } else {  // a large system hypre did not coarsen: symmetric Gauss-Seidel
      level.x.setZero();
      smooth(level, true);
      smooth(level, false);
    }
    return;
  }
  level.x.setZero();
  smooth(level, true);
  level.a.multiply(level.x, level.r);
  level.r = level.b - level.r;
  Level& next = levels[l + 1];
  level.pt.rows().multiply(level.r, next.b);
  run(l + 1);
  level.p.multiply(next.x, level.old);
  level.x += level.old;
  smooth(level, false);
}

}  // namespace mistfall::amg

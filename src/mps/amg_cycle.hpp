// The amg solver's V-cycle (hypre_amg_solver.cpp): the levels of a hierarchy (operator, interpolation and its
// transpose), the hybrid Gauss-Seidel smoother and the cycle itself, with a dense Cholesky solve on the coarsest
// level. x = V(b) on level l:
//   x = S_fwd(0; b),  r = b - A x,  x += P V_{l+1}(P^T r),  x = S_bwd(x; b)
// a symmetric cycle (forward sweep down, backward sweep up), as the conjugate gradients it preconditions need.
// The bits are the same on any number of threads: the smoother's blocks are fixed (kBlocks at most), Gauss-Seidel
// inside a block and Jacobi between blocks, what hypre does with kBlocks threads.
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <vector>

#include "mps/amg_rows.hpp"

namespace mistfall::amg {

constexpr int kBlocks = 8;                    // smoother blocks at most (the results do not depend on the thread count)
constexpr std::int64_t kMinBlockRows = 2048;  // rows per block at least (thin blocks smooth worse, and slower)

struct Level {
  Rows a;                    // the level's operator (level 0: the system being solved, set per solve)
  Rows p;                    // interpolation from the next level (not on the coarsest)
  OwnedRows pt;              // P^T
  std::vector<int> block;    // per row: its smoother block
  std::vector<char> inside;  // per row: every column in the row's block
  Eigen::VectorXd x, b, r, old;

  int blocks() const;
  // The blocks: consecutive stretches of rows, each smoothed in row order. Rows are numbered in particle order,
  // which the spatial sort keeps by place (spatial_order.hpp), and hypre numbers a coarse level's points in the
  // order of the fine rows, so a stretch of rows is a region of space on every level.
  void setBlocks();
};

// One hybrid Gauss-Seidel sweep of level.x for level.a x = level.b (forward or backward through the rows): in
// parallel over the blocks, each block's rows in turn, the other blocks' values from before the sweep.
void smooth(Level& level, bool forward);

struct VCycle {
  std::vector<Level> levels;
  bool coarse_dense = true;  // the coarsest level is solved densely (else by a symmetric Gauss-Seidel sweep pair)

  // Factors the coarsest level's operator (dense Cholesky; LDLT if round-off leaves it semi-definite).
  void factorCoarsest(const Rows& coarsest);
  // levels[l].x = V-cycle(levels[l].b) (x starts from 0).
  void run(std::size_t l);

 private:
  Eigen::LLT<Eigen::MatrixXd> coarse_llt_;
  Eigen::LDLT<Eigen::MatrixXd> coarse_ldlt_;
  bool coarse_ok_ = true;
};

}  // namespace mistfall::amg

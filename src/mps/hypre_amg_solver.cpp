// The "amg" pressure solver: conjugate gradients preconditioned with one V-cycle of algebraic multigrid. The
// hierarchy (coarse grids, interpolation, coarse operators) is built by hypre's BoomerAMG on one process; the
// iterations are mistfall's own, OpenMP-parallel (Debian's hypre has no OpenMP, so its solve would run on one
// core). Every operation of the iterations gives the same bits whatever the number of threads:
//  * matrix-vector products, restriction (with P^T stored as rows) and interpolation: one row per thread at a time;
//  * the smoother: hybrid Gauss-Seidel in kBlocks fixed blocks of consecutive rows (Gauss-Seidel inside a block,
//    Jacobi between blocks: what hypre does with kBlocks threads), a forward sweep down the cycle and a backward
//    sweep up (the cycle is symmetric, as CG needs), a dense Cholesky solve on the coarsest level (amg_cycle.hpp);
//  * dot products: partial sums over kChunks fixed chunks of rows, added in order.
// The hierarchy may be kept for the next systems (PreconditionerReuse, linear_solver.hpp): the cycle smooths with
// the new matrix, only its coarse levels are old.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>
#include <_hypre_parcsr_ls.h>
#pragma GCC diagnostic pop
#include <mpi.h>
#include <omp.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "mps/amg_cycle.hpp"
#include "mps/amg_rows.hpp"
#include "mps/linear_solver.hpp"
#include "mps/mpi_environment.hpp"

namespace mistfall {

namespace {

using amg::dot;
using amg::kParallelRows;
using amg::Level;
using amg::OwnedRows;
using amg::Rows;
using amg::rowsOf;
using amg::transposeOf;

constexpr std::int64_t kMaxDense = 2000;  // largest coarsest level solved densely

// A ParCSR copy of `a` on MPI_COMM_SELF for hypre's setup: one diagonal block, each row's diagonal entry first.
hypre_ParCSRMatrix* parCsrCopy(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a) {
  const HYPRE_BigInt rows = static_cast<HYPRE_BigInt>(a.rows());
  const HYPRE_Int nnz = static_cast<HYPRE_Int>(a.nonZeros());
  HYPRE_BigInt starts[2] = {0, rows};
  hypre_ParCSRMatrix* m = hypre_ParCSRMatrixCreate(MPI_COMM_SELF, rows, rows, starts, starts, 0, nnz, 0);
  hypre_CSRMatrix* diag = hypre_ParCSRMatrixDiag(m);
  // Arrays allocated here (not zeroed: every entry is written below) are kept by Initialize.
  hypre_CSRMatrixI(diag) = hypre_TAlloc(HYPRE_Int, rows + 1, HYPRE_MEMORY_HOST);
  hypre_CSRMatrixJ(diag) = hypre_TAlloc(HYPRE_Int, nnz, HYPRE_MEMORY_HOST);
  hypre_CSRMatrixData(diag) = hypre_TAlloc(HYPRE_Real, nnz, HYPRE_MEMORY_HOST);
  hypre_ParCSRMatrixInitialize(m);
  HYPRE_Int* row_start = hypre_CSRMatrixI(diag);
  HYPRE_Int* column = hypre_CSRMatrixJ(diag);
  HYPRE_Real* value = hypre_CSRMatrixData(diag);
  const int* outer = a.outerIndexPtr();
  const int* inner = a.innerIndexPtr();
  const double* data = a.valuePtr();
  const std::int64_t n = rows;
#pragma omp parallel for schedule(static) if (n >= kParallelRows)
  for (std::int64_t r = 0; r <= n; ++r) row_start[r] = outer[r];
#pragma omp parallel for schedule(static) if (n >= kParallelRows)
  for (std::int64_t r = 0; r < n; ++r) {
    HYPRE_Int at = outer[r] + 1;
    column[outer[r]] = static_cast<HYPRE_Int>(r);
    value[outer[r]] = 0.0;  // a structurally missing diagonal stays 0 (the system never has one)
    for (int k = outer[r]; k < outer[r + 1]; ++k) {
      if (inner[k] == r) {
        value[outer[r]] = data[k];
      } else if (at < outer[r + 1]) {
        column[at] = inner[k];
        value[at] = data[k];
        ++at;
      }
    }
  }
  hypre_ParCSRMatrixSetNumNonzeros(m);
  return m;
}

Rows rowsOf(hypre_ParCSRMatrix* m) {
  hypre_CSRMatrix* d = hypre_ParCSRMatrixDiag(m);
  Rows r;
  r.n = hypre_CSRMatrixNumRows(d);
  r.start = hypre_CSRMatrixI(d);
  r.column = hypre_CSRMatrixJ(d);
  r.value = hypre_CSRMatrixData(d);
  return r;
}

class HypreAmgSolver final : public LinearSolver {
 public:
  HypreAmgSolver(double tolerance, int max_iterations, PreconditionerReuse reuse)
      : tolerance_(tolerance), max_iterations_(max_iterations), reuse_(reuse) {
    ensureMpiInitialized();
    static bool hypre_started = [] { HYPRE_Init(); return true; }();
    (void)hypre_started;
  }
  ~HypreAmgSolver() override { forget(); }

  LinearSolveResult solve(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b,
                          Eigen::VectorXd& x, const std::vector<std::int64_t>* row_keys) override {
    LinearSolveResult result;
    const std::int64_t rows = a.rows();
    if (rows == 0) {
      result.converged = true;
      return result;
    }
    if (b.norm() == 0.0) {
      x.setZero(rows);
      result.converged = true;
      return result;
    }
    if (!a.isCompressed()) throw std::logic_error("the amg solver needs a compressed matrix");
    const double t0 = omp_get_wtime();
    if (x.size() != rows) x.setZero(rows);
    const bool reuse = amg_ && reuse_.max_reuse > 0 && row_keys && uses_ < reuse_.max_reuse &&
                       last_iterations_ <= setup_iterations_ + reuse_.slack && followRows(a, *row_keys);
    const Eigen::VectorXd guess = x;
    if (reuse) {
      ++uses_;
      useFine(a);
    } else {
      setUp(a, row_keys);
    }
    double t1 = omp_get_wtime();
    int iterations = iterate(b, x);
    double setup_seconds = t1 - t0;
    bool converged = relativeResidual(a, b, x) <= tolerance_ * 10.0;
    if (reuse && !converged) {  // the kept hierarchy did not do: afresh
      x = guess;
      const double t2 = omp_get_wtime();
      setUp(a, row_keys);
      t1 = omp_get_wtime();
      setup_seconds += t1 - t2;
      iterations = iterate(b, x);
      result.reused = false;
    } else {
      result.reused = reuse;
    }
    if (uses_ == 0) setup_iterations_ = iterations;
    last_iterations_ = iterations;
    result.iterations = iterations;
    result.relative_residual = relativeResidual(a, b, x);
    result.converged = result.relative_residual <= tolerance_ * 10.0;
    result.setup_seconds = setup_seconds;
    result.solve_seconds = omp_get_wtime() - t1;
    return result;
  }

  void forget() override {
    if (amg_) HYPRE_BoomerAMGDestroy(amg_);
    amg_ = nullptr;
    if (setup_matrix_) hypre_ParCSRMatrixDestroy(setup_matrix_);
    setup_matrix_ = nullptr;
    cycle_.levels.clear();
    setup_p0_ = Rows{};  // hypre's arrays are gone
    setup_row_of_.clear();
    keys_.clear();
    uses_ = 0;
  }

  const char* name() const override { return "amg"; }

 private:
  // BoomerAMG's hierarchy for `a` (hypre's setup on one process), taken apart into levels.
  void setUp(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const std::vector<std::int64_t>* row_keys) {
    forget();
    setup_matrix_ = parCsrCopy(a);
    HYPRE_BoomerAMGCreate(&amg_);
    HYPRE_BoomerAMGSetPrintLevel(amg_, 0);
    // Settings chosen by measurement on the 2D dam break at 40k particles (ms per step, 2 threads): PMIS +
    // extended+i interpolation + one level of aggressive coarsening, theta 0.25: 120 ms (16 CG iterations);
    // HMIS + classical interpolation, no aggressive coarsening, theta 0.35: 83 ms (6 iterations).
    HYPRE_BoomerAMGSetCoarsenType(amg_, 10);  // HMIS
    HYPRE_BoomerAMGSetInterpType(amg_, 0);    // classical modified interpolation
    HYPRE_BoomerAMGSetPMaxElmts(amg_, 4);
    HYPRE_BoomerAMGSetAggNumLevels(amg_, 0);
    HYPRE_BoomerAMGSetStrongThreshold(amg_, 0.35);
    HYPRE_BoomerAMGSetMaxIter(amg_, 1);
    HYPRE_BoomerAMGSetTol(amg_, 0.0);
    const HYPRE_ParCSRMatrix m = reinterpret_cast<HYPRE_ParCSRMatrix>(setup_matrix_);
    HYPRE_BoomerAMGSetup(amg_, m, nullptr, nullptr);
    auto* data = reinterpret_cast<hypre_ParAMGData*>(amg_);
    const int count = std::max(1, static_cast<int>(hypre_ParAMGDataNumLevels(data)));
    cycle_.levels.resize(count);
    for (int l = 0; l < count; ++l) {
      Level& level = cycle_.levels[l];
      if (l > 0) {
        level.a = rowsOf(hypre_ParAMGDataAArray(data)[l]);
        level.a.findDiagonal();
      }
      if (l + 1 < count) {
        level.p = rowsOf(hypre_ParAMGDataPArray(data)[l]);
        if (l == 0) setup_p0_ = level.p;
        const auto coarse_rows = hypre_CSRMatrixNumRows(hypre_ParCSRMatrixDiag(hypre_ParAMGDataAArray(data)[l + 1]));
        level.pt = transposeOf(level.p, coarse_rows);
      }
      const std::int64_t n = l == 0 ? a.rows() : level.a.n;
      level.x.setZero(n);
      level.b.setZero(n);
      level.r.setZero(n);
      level.old.setZero(n);
    }
    useFine(a);
    for (int l = 1; l < count; ++l) cycle_.levels[l].setBlocks();
    // The coarsest level is solved exactly (dense Cholesky; LDLT if round-off leaves it semi-definite).
    const Rows coarsest = count == 1 ? rowsOf(a) : cycle_.levels.back().a;
    cycle_.coarse_dense = coarsest.n <= kMaxDense;
    if (cycle_.coarse_dense) cycle_.factorCoarsest(coarsest);
    if (row_keys) {
      keys_ = *row_keys;
      setup_row_of_.reserve(keys_.size());
      for (std::size_t r = 0; r < keys_.size(); ++r) setup_row_of_.emplace(keys_[r], static_cast<int>(r));
    }
    uses_ = 0;
  }

  // Makes the kept hierarchy fit a system of rows `keys` (PreconditionerReuse): the same rows, or rows of which at
  // least kept_rows (of the larger of the two systems) have a row of the same key in the set-up system. Level 0's
  // interpolation is then the set-up one's rows at their new places, and for a new row the mean of its kept
  // neighbours' rows weighted by its couplings to them (|a_rj|). False: a new setup.
  bool followRows(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const std::vector<std::int64_t>& keys) {
    if (keys == keys_) return true;
    if (cycle_.levels.size() < 2 || setup_row_of_.empty() || reuse_.kept_rows >= 1.0) return false;
    const auto& setup_p = setup_p0_;
    const std::int64_t n = static_cast<std::int64_t>(keys.size());
    std::vector<int> setup_row(n, -1);
    std::int64_t kept = 0;
    for (std::int64_t r = 0; r < n; ++r) {
      const auto found = setup_row_of_.find(keys[r]);
      if (found == setup_row_of_.end() || found->second >= setup_p.n) continue;
      setup_row[r] = found->second;
      ++kept;
    }
    if (static_cast<double>(kept) < reuse_.kept_rows * static_cast<double>(std::max<std::int64_t>(n, setup_p.n)))
      return false;
    OwnedRows& p = followed_p0_;
    p.start.assign(n + 1, 0);
    p.column.clear();
    p.value.clear();
    // A new row interpolates as its kept neighbours do, weighted by its couplings to them (|a_rj|).
    const Rows fine_rows = rowsOf(a);
    std::vector<double> row_sum;  // the new row's interpolation, dense over the coarse points it touches
    std::vector<int> touched;
    row_sum.assign(cycle_.levels[1].a.n, 0.0);
    for (std::int64_t r = 0; r < n; ++r) {
      if (setup_row[r] >= 0) {
        for (int k = setup_p.start[setup_row[r]]; k < setup_p.start[setup_row[r] + 1]; ++k) {
          p.column.push_back(setup_p.column[k]);
          p.value.push_back(setup_p.value[k]);
        }
      } else {
        double weight = 0.0;
        for (int k = fine_rows.start[r]; k < fine_rows.start[r + 1]; ++k) {
          const int j = fine_rows.column[k];
          if (j == r || setup_row[j] < 0) continue;
          const double w = std::abs(fine_rows.value[k]);
          weight += w;
          for (int q = setup_p.start[setup_row[j]]; q < setup_p.start[setup_row[j] + 1]; ++q) {
            if (row_sum[setup_p.column[q]] == 0.0) touched.push_back(setup_p.column[q]);
            row_sum[setup_p.column[q]] += w * setup_p.value[q];
          }
        }
        std::sort(touched.begin(), touched.end());
        for (int c : touched) {
          if (row_sum[c] != 0.0) p.column.push_back(c), p.value.push_back(row_sum[c] / weight);
          row_sum[c] = 0.0;
        }
        touched.clear();
      }
      p.start[r + 1] = static_cast<int>(p.column.size());
    }
    Level& fine = cycle_.levels[0];
    fine.p = p.rows();
    fine.pt = transposeOf(fine.p, cycle_.levels[1].a.n);
    fine.x.setZero(n);
    fine.b.setZero(n);
    fine.r.setZero(n);
    fine.old.setZero(n);
    keys_ = keys;
    return true;
  }

  // Level 0 is the system being solved.
  void useFine(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a) {
    fine_ = rowsOf(a);
    fine_.findDiagonal();
    cycle_.levels[0].a = fine_;
    cycle_.levels[0].setBlocks();
  }

  // Preconditioned conjugate gradients from x; stops at |r| <= tolerance |b|. Returns the iterations.
  int iterate(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
    const std::int64_t n = b.size();
    r_.resize(n);
    q_.resize(n);
    fine_.multiply(x, q_);
    r_ = b - q_;
    const double bb = dot(b, b);
    const double goal = tolerance_ * tolerance_ * bb;
    double rr = dot(r_, r_);
    auto precondition = [&] {
      cycle_.levels[0].b = r_;
      cycle_.run(0);
      z_ = cycle_.levels[0].x;
    };
    int iterations = 0;
    if (rr <= goal) return iterations;
    precondition();
    p_ = z_;
    double rz = dot(r_, z_);
    while (iterations < max_iterations_) {
      fine_.multiply(p_, q_);
      const double alpha = rz / dot(p_, q_);
#pragma omp parallel for schedule(static) if (n >= kParallelRows)
      for (std::int64_t i = 0; i < n; ++i) {
        x[i] += alpha * p_[i];
        r_[i] -= alpha * q_[i];
      }
      ++iterations;
      rr = dot(r_, r_);
      if (rr <= goal || !std::isfinite(rr)) break;
      precondition();
      const double rz_next = dot(r_, z_);
      const double beta = rz_next / rz;
      rz = rz_next;
#pragma omp parallel for schedule(static) if (n >= kParallelRows)
      for (std::int64_t i = 0; i < n; ++i) p_[i] = z_[i] + beta * p_[i];
    }
    return iterations;
  }

  double tolerance_;
  int max_iterations_;
  PreconditionerReuse reuse_;
  HYPRE_Solver amg_ = nullptr;
  hypre_ParCSRMatrix* setup_matrix_ = nullptr;  // the matrix the hierarchy was built for (hypre's level 0)
  amg::VCycle cycle_;
  Rows fine_;
  Eigen::VectorXd r_, z_, p_, q_;
  std::vector<std::int64_t> keys_;  // the rows of the system the kept hierarchy was last fitted to
  std::unordered_map<std::int64_t, int> setup_row_of_;  // key -> row of the set-up system
  Rows setup_p0_;           // level 0's interpolation as set up (hypre's)
  OwnedRows followed_p0_;   // ... fitted to the rows of a later system (followRows)
  int uses_ = 0;  // systems solved with the kept hierarchy since its setup
  int setup_iterations_ = 0, last_iterations_ = 0;
};

}  // namespace

std::unique_ptr<LinearSolver> makeHypreAmgSolver(double tolerance, int max_iterations, PreconditionerReuse reuse) {
  return std::make_unique<HypreAmgSolver>(tolerance, max_iterations, reuse);
}

}  // namespace mistfall

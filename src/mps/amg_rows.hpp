// Sparse rows for the amg solver's own V-cycle (hypre_amg_solver.cpp, amg_cycle.hpp): compressed rows borrowed from
// hypre or Eigen, or owned; the transpose; dot products. Every operation gives the same bits on any number of
// threads: a row is computed by one thread, in a fixed order, and sums are added in fixed chunks.
#pragma once

#include <Eigen/Sparse>
#include <array>
#include <cstdint>
#include <vector>

namespace mistfall::amg {

// Loops over fewer rows run on one thread (a parallel region costs more than they do; the bits are the same).
// 2048 rather than 8192: the waterfall's liquid system (6,500 rows at l0 = 5 mm) and the coarse levels then use
// both cores; 2 threads, waterfall.toml 8.50-8.55 s 20.8 -> 19.0-19.5 s, waterfall_small 0-0.5 s 15.2-16.9 ->
// 13.7-14.5 s; 1024 and 512 gave no more (README, "Where the time goes").
constexpr std::int64_t kParallelRows = 2048;
constexpr int kChunks = 64;  // dot-product chunks

// Rows of a sparse matrix (borrowed arrays) and where each row's diagonal entry is.
struct Rows {
  std::int64_t n = 0;
  const int* start = nullptr;
  const int* column = nullptr;
  const double* value = nullptr;
  std::vector<int> diagonal;  // index of a_ii in column/value (square matrices)

  void findDiagonal() {
    diagonal.resize(n);
#pragma omp parallel for schedule(static) if (n >= kParallelRows)
    for (std::int64_t i = 0; i < n; ++i) {
      diagonal[i] = -1;
      for (int k = start[i]; k < start[i + 1]; ++k)
        if (column[k] == i) {
          diagonal[i] = k;
          break;
        }
    }
  }
  // out = M v
  void multiply(const Eigen::VectorXd& v, Eigen::VectorXd& out) const {
#pragma omp parallel for schedule(static) if (n >= kParallelRows)
    for (std::int64_t i = 0; i < n; ++i) {
      double s = 0.0;
      for (int k = start[i]; k < start[i + 1]; ++k) s += value[k] * v[column[k]];
      out[i] = s;
    }
  }
};

inline Rows rowsOf(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a) {
  Rows r;
  r.n = a.rows();
  r.start = a.outerIndexPtr();
  r.column = a.innerIndexPtr();
  r.value = a.valuePtr();
  return r;
}

// A sparse matrix stored by rows that owns its arrays (P^T for the restriction, coarse operators).
struct OwnedRows {
  std::vector<int> start, column;
  std::vector<double> value;
  Rows rows() const {
    Rows r;
    r.n = static_cast<std::int64_t>(start.size()) - 1;
    r.start = start.data();
    r.column = column.data();
    r.value = value.data();
    return r;
  }
};

// The transpose of a rows x cols matrix, stored by rows.
inline OwnedRows transposeOf(const Rows& p, std::int64_t cols) {
  OwnedRows t;
  const int nnz = p.start[p.n];
  t.start.assign(cols + 1, 0);
  for (int k = 0; k < nnz; ++k) ++t.start[p.column[k] + 1];
  for (std::int64_t c = 0; c < cols; ++c) t.start[c + 1] += t.start[c];
  t.column.resize(nnz);
  t.value.resize(nnz);
  std::vector<int> fill(t.start.begin(), t.start.end() - 1);
  for (std::int64_t r = 0; r < p.n; ++r)
    for (int k = p.start[r]; k < p.start[r + 1]; ++k) {
      const int at = fill[p.column[k]]++;
      t.column[at] = static_cast<int>(r);
      t.value[at] = p.value[k];
    }
  return t;
}

// sum_i a_i b_i over fixed chunks of rows, added in order (the same bits on any number of threads).
inline double dot(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  std::array<double, kChunks> part{};
  const std::int64_t n = a.size();
#pragma omp parallel for schedule(static) if (n >= kParallelRows)
  for (int c = 0; c < kChunks; ++c) {
    double s = 0.0;
    for (std::int64_t i = n * c / kChunks; i < n * (c + 1) / kChunks; ++i) s += a[i] * b[i];
    part[c] = s;
  }
  double s = 0.0;
  for (double v : part) s += v;
  return s;
}

}  // namespace mistfall::amg

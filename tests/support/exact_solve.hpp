// Test helper: solve an assembled pressure system directly (sparse LDL^T), so that comparisons between
// systems are not blurred by an iterative solver's tolerance.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>

#include "mps/pressure_poisson.hpp"

namespace mistfall::test_support {

inline Eigen::VectorXd solveExactly(const Eigen::SparseMatrix<double, Eigen::RowMajor>& matrix,
                                    const Eigen::VectorXd& rhs) {
  const Eigen::SparseMatrix<double> a = matrix;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(a);
  EXPECT_EQ(ldlt.info(), Eigen::Success);
  return ldlt.solve(rhs);
}

inline Eigen::VectorXd solveExactly(const PressureSystem& sys) { return solveExactly(sys.matrix, sys.rhs); }

}  // namespace mistfall::test_support

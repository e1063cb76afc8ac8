#include "mps/bubble_pressure.hpp"

namespace mistfall {

void lumpPressureGroups(const PressureSystem& sys, const std::vector<std::int32_t>& group_of,
                        const std::vector<double>& group_shift, LumpedPressureSystem& out) {
  const auto rows = static_cast<std::int32_t>(sys.particle_of.size());
  const auto groups = static_cast<std::int32_t>(group_shift.size());
  out.column_of_row.assign(rows, -1);
  std::int32_t kept = 0;
  for (std::int32_t r = 0; r < rows; ++r)
    if (group_of[sys.particle_of[r]] < 0) out.column_of_row[r] = kept++;
  out.first_group_row = kept;
  if (groups == 0) {  // nothing to merge (no bubble): the system as it is
    out.matrix = sys.matrix;
    out.rhs = sys.rhs;
    return;
  }
  for (std::int32_t r = 0; r < rows; ++r)
    if (group_of[sys.particle_of[r]] >= 0) out.column_of_row[r] = kept + group_of[sys.particle_of[r]];

  Eigen::SparseMatrix<double, Eigen::RowMajor> t(rows, kept + groups);
  t.reserve(Eigen::VectorXi::Constant(rows, 1));
  for (std::int32_t r = 0; r < rows; ++r) t.insert(r, out.column_of_row[r]) = 1.0;
  t.makeCompressed();
  const Eigen::SparseMatrix<double, Eigen::RowMajor> tt = t.transpose();
  out.matrix = tt * sys.matrix * t;
  out.rhs = tt * sys.rhs;
  for (std::int32_t g = 0; g < groups; ++g) {
    const auto row = kept + g;
    out.matrix.coeffRef(row, row) += group_shift[g];
    // A bubble touching no liquid unknown and holding its volume has an empty row: P_B = 0 there.
    if (out.matrix.coeff(row, row) == 0.0) out.matrix.coeffRef(row, row) = 1.0, out.rhs[row] = 0.0;
  }
  out.matrix.makeCompressed();
}

}  // namespace mistfall

// Fixed-size vectors for a D-dimensional particle method (D = 2 or 3, a compile-time parameter).
#pragma once

#include <Eigen/Core>

namespace mistfall {

template <int D>
using Vec = Eigen::Matrix<double, D, 1>;

}  // namespace mistfall

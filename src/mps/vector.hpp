// Fixed-size vectors for a D-dimensional particle method (D = 2 or 3, a compile-time parameter).
#pragma once

#include <Eigen/Core>

namespace mistfall {

template <int D>
using Vec = Eigen::Matrix<double, D, 1>;

// x in three dimensions: z = 0 for a 2D vector (the renderer's scene, the texture's and the points' eq. (18)).
template <int D>
Vec<3> padded(const Vec<D>& x) {
  Vec<3> v = Vec<3>::Zero();
  v.template head<D>() = x;
  return v;
}

}  // namespace mistfall

// MPS weight function, eq. (14):  w(r) = re / r - 1  for 0 < r <= re,  0 otherwise.
#pragma once

namespace mistfall {

inline double weight(double r, double re) {
  if (r >= re || r <= 0.0) return 0.0;
  return re / r - 1.0;
}

}  // namespace mistfall

// Test helper: visits every integer lattice point k with lo <= k <= hi (per axis), axis 0 fastest.
#pragma once

namespace mistfall::test_support {

// `Index` is any D-component integer vector with operator[] (Eigen::Matrix<int, D, 1>, std::array<int, D>).
template <int D, class Index, class Visit>
void forEachLatticePoint(const Index& lo, const Index& hi, Visit&& visit) {
  for (int a = 0; a < D; ++a)
    if (hi[a] < lo[a]) return;
  Index k = lo;
  while (true) {
    visit(static_cast<const Index&>(k));
    int a = 0;
    for (; a < D; ++a) {
      if (++k[a] <= hi[a]) break;
      k[a] = lo[a];
    }
    if (a == D) return;
  }
}

}  // namespace mistfall::test_support

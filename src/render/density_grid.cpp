// Points splatted into a voxel grid, and POV-Ray's df3 file (see density_grid.hpp).
#include "render/density_grid.hpp"

#include <algorithm>
#include <cmath>

#include "io/atomic_file.hpp"

namespace mistfall {

namespace {

// Quadratic B-spline weights of the voxels i0 - 1, i0, i0 + 1 around coordinate u (in voxels, centres at + 0.5).
void weights(double u, int& i0, double w[3]) {
  i0 = static_cast<int>(std::floor(u));
  const double d = u - (i0 + 0.5);  // in [-0.5, 0.5)
  w[0] = 0.5 * (0.5 - d) * (0.5 - d);
  w[1] = 0.75 - d * d;
  w[2] = 0.5 * (0.5 + d) * (0.5 + d);
}

}  // namespace

double DensityGrid::integral() const {
  double s = 0.0;
  for (float v : value) s += v;
  return s * h * h * h;
}

float DensityGrid::maximum() const {
  float m = 0.0f;
  for (float v : value) m = std::max(m, v);
  return m;
}

DensityGrid emptyGrid(const Box& b, double h) {
  DensityGrid g;
  g.h = h;
  for (int k = 0; k < 3; ++k)
    if (!(b.max[k] > b.min[k])) return g;
  for (int k = 0; k < 3; ++k) {
    g.origin[k] = std::floor(b.min[k] / h) * h;
    g.n[k] = std::max(1, static_cast<int>(std::ceil(b.max[k] / h - std::floor(b.min[k] / h) - 1e-9)));
  }
  g.value.assign(static_cast<std::size_t>(g.n[0]) * g.n[1] * g.n[2], 0.0f);
  return g;
}

Box boundsOf(const std::vector<Vec<3>>& points, double margin, const Box& clip) {
  Box b;
  b.min = {1.0, 1.0, 1.0}, b.max = {-1.0, -1.0, -1.0};
  if (points.empty()) return b;
  for (int k = 0; k < 3; ++k) b.min[k] = b.max[k] = points.front()[k];
  for (const auto& p : points)
    for (int k = 0; k < 3; ++k) b.min[k] = std::min(b.min[k], p[k]), b.max[k] = std::max(b.max[k], p[k]);
  for (int k = 0; k < 3; ++k)
    b.min[k] = std::max(b.min[k] - margin, clip.min[k]), b.max[k] = std::min(b.max[k] + margin, clip.max[k]);
  return b;
}

// Calls f(i, j, a, b) for the cells (i, j) = i0 - 1 + (a, b) of the 3 x 3 stencil in x and y inside the grid.
template <class F>
void forEachStencilCellXY(const DensityGrid& g, const int* i0, F&& f) {
  for (int b = 0; b < 3; ++b) {
    const int j = i0[1] - 1 + b;
    if (j < 0 || j >= g.n[1]) continue;
    for (int a = 0; a < 3; ++a) {
      const int i = i0[0] - 1 + a;
      if (i < 0 || i >= g.n[0]) continue;
      f(i, j, a, b);
    }
  }
}

void splat(DensityGrid& g, const std::vector<Vec<3>>& points, double amount) {
  if (g.empty()) return;
  const double scale = amount / (g.h * g.h * g.h);
  for (const auto& p : points) {
    int i0[3];
    double w[3][3];
    for (int k = 0; k < 3; ++k) weights((p[k] - g.origin[k]) / g.h, i0[k], w[k]);
    for (int c = 0; c < 3; ++c) {
      const int k = i0[2] - 1 + c;
      if (k < 0 || k >= g.n[2]) continue;
      forEachStencilCellXY(g, i0, [&](int i, int j, int a, int b) {
        g.at(i, j, k) += static_cast<float>(scale * w[0][a] * w[1][b] * w[2][c]);
      });
    }
  }
}

void splatAcross(DensityGrid& g, const std::vector<Vec<2>>& points, double amount_per_metre) {
  if (g.empty()) return;
  const double scale = amount_per_metre / (g.h * g.h);  // per voxel area across every z
  for (const auto& p : points) {
    int i0[2];
    double w[2][3];
    for (int k = 0; k < 2; ++k) weights((p[k] - g.origin[k]) / g.h, i0[k], w[k]);
    forEachStencilCellXY(g, i0, [&](int i, int j, int a, int b) {
      for (int k = 0; k < g.n[2]; ++k) g.at(i, j, k) += static_cast<float>(scale * w[0][a] * w[1][b]);
    });
  }
}

double writeDf3(const std::filesystem::path& file, const DensityGrid& g) {
  const double top = g.maximum();
  const double scale = top > 0.0 ? top : 1.0;
  writeFileAtomically(file, [&](std::ostream& out) {
    auto put16 = [&out](unsigned v) {
      const char bytes[2] = {static_cast<char>((v >> 8) & 0xff), static_cast<char>(v & 0xff)};
      out.write(bytes, 2);
    };
    for (int k = 0; k < 3; ++k) put16(static_cast<unsigned>(g.n[k]));
    std::vector<char> data(2 * g.value.size());
    for (std::size_t i = 0; i < g.value.size(); ++i) {
      const auto v = static_cast<unsigned>(std::lround(std::clamp(g.value[i] / scale, 0.0, 1.0) * 65535.0));
      data[2 * i] = static_cast<char>((v >> 8) & 0xff);
      data[2 * i + 1] = static_cast<char>(v & 0xff);
    }
    out.write(data.data(), static_cast<std::streamsize>(data.size()));
  });
  return scale;
}

}  // namespace mistfall

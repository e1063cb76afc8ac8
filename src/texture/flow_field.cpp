// GridFlow: coverage-weighted multilinear interpolation of the per-frame flow grids (see flow_field.hpp).
#include "texture/flow_field.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace mistfall {

namespace {

constexpr const char* kArrays[] = {"gas_velocity", "liquid_velocity", "gas_sps_k", "liquid_sps_k",
                                   "gas_coverage", "liquid_coverage"};

void checkGrid(const ImageData& a, const ImageData& b) {
  for (const char* name : kArrays) {
    if (!a.find(name) || !b.find(name))
      throw std::runtime_error(std::string("flow grid lacks the array '") + name + "' (written by simulate)");
  }
  if (a.dims != b.dims || a.origin != b.origin || a.spacing != b.spacing)
    throw std::runtime_error("flow grids of consecutive frames differ in origin, spacing or size");
}

}  // namespace

struct GridFlow::Weights {
  std::size_t node[8];
  double weight[8];
  int count = 0;
};

GridFlow::GridFlow(std::shared_ptr<const ImageData> earlier, std::shared_ptr<const ImageData> later, int dimension)
    : frames_{std::move(earlier), std::move(later)}, dimension_(dimension) {
  checkGrid(*frames_[0], *frames_[1]);
  for (int f = 0; f < 2; ++f) {
    const ImageData& g = *frames_[f];
    auto values = [&](const char* name) { return &g.find(name)->values; };
    arrays_[f][0] = {values("gas_velocity"), values("gas_sps_k"), values("gas_coverage"), values("liquid_coverage")};
    arrays_[f][1] = {values("liquid_velocity"), values("liquid_sps_k"), values("liquid_coverage"),
                     values("gas_coverage")};
  }
  std::vector<double> filled;
  for (std::size_t n = 0; n < frames_[0]->nodeCount(); ++n)
    if (const double c = (*arrays_[0][0].coverage)[n] + (*arrays_[0][0].other_coverage)[n]; c > 0.0)
      filled.push_back(c);
  if (!filled.empty()) {
    std::nth_element(filled.begin(), filled.begin() + filled.size() / 2, filled.end());
    full_coverage_ = filled[filled.size() / 2];
  }
}

// Corner nodes and multilinear weights of the cell holding x; false outside the grid.
bool GridFlow::weights(const Vec3& x, Weights& w) const {
  const ImageData& g = *frames_[0];
  std::int64_t base[3] = {0, 0, 0};
  double frac[3] = {0.0, 0.0, 0.0};
  for (int a = 0; a < dimension_; ++a) {
    const double s = (x[a] - g.origin[a]) / g.spacing[a];
    const std::int64_t last = g.dims[a] - 1;
    if (!(s >= 0.0) || s > static_cast<double>(last)) return false;
    base[a] = std::min<std::int64_t>(static_cast<std::int64_t>(s), std::max<std::int64_t>(last - 1, 0));
    frac[a] = last > 0 ? s - static_cast<double>(base[a]) : 0.0;
  }
  w.count = 0;
  const int corners = 1 << dimension_;
  for (int c = 0; c < corners; ++c) {
    double weight = 1.0;
    std::int64_t index[3] = {0, 0, 0};
    for (int a = 0; a < dimension_; ++a) {
      const int up = (c >> a) & 1;
      weight *= up ? frac[a] : 1.0 - frac[a];
      index[a] = std::min(base[a] + up, g.dims[a] - 1);
    }
    w.node[w.count] = static_cast<std::size_t>(index[0] + g.dims[0] * (index[1] + g.dims[1] * index[2]));
    w.weight[w.count++] = weight;
  }
  return true;
}

FlowSample GridFlow::sample(bool liquid, const Vec3& x, double t) const {
  FlowSample out;
  Weights w;
  if (!weights(x, w)) {
    out.inside = false;
    return out;
  }
  const double t0 = frames_[0]->time, t1 = frames_[1]->time;
  const double later = t1 > t0 ? std::clamp((t - t0) / (t1 - t0), 0.0, 1.0) : 0.0;
  double own = 0.0, opposite = 0.0, k = 0.0;
  Vec3 u = Vec3::Zero();
  for (int f = 0; f < 2; ++f) {
    const double tw = f == 0 ? 1.0 - later : later;
    if (tw == 0.0) continue;
    const PhaseArrays& a = arrays_[f][liquid ? 1 : 0];
    const auto &uv = *a.velocity, &kv = *a.k, &cv = *a.coverage, &ov = *a.other_coverage;
    for (int c = 0; c < w.count; ++c) {
      const std::size_t n = w.node[c];
      const double cw = tw * w.weight[c] * cv[n];
      own += cw;
      opposite += tw * w.weight[c] * ov[n];
      k += cw * kv[n];
      for (int a = 0; a < dimension_; ++a) u[a] += cw * uv[3 * n + a];
    }
  }
  if (own > 0.0) {
    out.mean_velocity = u / own;
    out.k = k / own;
  }
  const double liquid_cov = liquid ? own : opposite, total = own + opposite;
  const double reference = std::max(total, full_coverage_);
  out.liquid_fraction = reference > 0.0 ? liquid_cov / reference : 0.0;
  return out;
}

}  // namespace mistfall

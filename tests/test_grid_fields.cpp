// Particle fields on a uniform grid (MPS-weighted means) and the .vti writer/reader.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/grid_fields.hpp"
#include "support/scratch.hpp"

using namespace mistfall;
using mistfall::test_support::freshDir;
using mistfall::test_support::slurp;

namespace {

constexpr double kL0 = 0.01;

// n^D liquid fluid particles of spacing l0 from the origin.
template <int D>
Particles<D> lattice(int n) {
  Particles<D> p;
  Eigen::Matrix<int, D, 1> k = Eigen::Matrix<int, D, 1>::Zero();
  while (true) {
    p.add(kL0 * k.template cast<double>(), Vec<D>::Zero(), ParticleKind::Fluid, Phase::Liquid);
    int a = 0;
    for (; a < D; ++a) {
      if (++k[a] < n) break;
      k[a] = 0;
    }
    if (a == D) break;
  }
  return p;
}

template <int D>
GridSpec<D> spec(double lower, double upper, double h) {
  GridSpec<D> g;
  g.lower = Vec<D>::Constant(lower);
  g.upper = Vec<D>::Constant(upper);
  g.cell_size = h;
  g.radius = kGridSamplingRadiusRatio * kL0;
  return g;
}

// f = 2 + b.x sampled with `h`; every node of [lower, upper] must get f(node) to 1e-12 relative.
// The nodes lie on lattice points, edge midpoints or cell centres: centres of point symmetry of the lattice,
// around which the weighted sum of (x_j - x) vanishes, so the weighted mean of a linear field is exact there
// (when the whole influence circle lies inside the lattice).
template <int D>
void expectLinearFieldReproduced(int n, double lower, double upper, double h) {
  const auto p = lattice<D>(n);
  const Vec<D> b = Vec<D>::LinSpaced(-3.0, 5.0);
  std::vector<double> f(p.size());
  for (std::size_t j = 0; j < p.size(); ++j) f[j] = 2.0 + b.dot(p.position[j]);
  const auto g = spec<D>(lower, upper, h);
  const auto dims = gridNodeCounts<D>(g);
  const GridSamples s = sampleOnGrid<D>(g, p.position, std::vector<char>(p.size(), 1), f, 1);
  ASSERT_EQ(s.mean.size(), static_cast<std::size_t>(dims[0] * dims[1] * dims[2]));
  for (std::size_t node = 0; node < s.mean.size(); ++node) {
    Vec<D> x;
    std::size_t rest = node;
    for (int a = 0; a < D; ++a) {
      x[a] = lower + h * static_cast<double>(rest % dims[a]);
      rest /= dims[a];
    }
    const double expected = 2.0 + b.dot(x);
    EXPECT_NEAR(s.mean[node], expected, 1e-12 * std::abs(expected)) << "node " << node;
    EXPECT_GT(s.coverage[node], 0.0);
  }
}

ImageData sampleImage() {
  ImageData image;
  image.origin = {0.1, -0.25, 0.0};
  image.spacing = {0.003, 0.003, 0.003};
  image.dims = {5, 4, 1};
  image.time = 1.0 / 3.0;
  GridArray v{"gas_velocity", 3, {}}, c{"gas_coverage", 1, {}};
  for (std::size_t i = 0; i < 20; ++i) {
    for (int a = 0; a < 3; ++a) v.values.push_back(std::sin(double(i) + a) * 1e-3 / 7.0);
    c.values.push_back(i % 3 ? 0.0 : std::exp(double(i)) / 3.0);
  }
  image.arrays = {v, c};
  return image;
}

void expectSameImage(const ImageData& a, const ImageData& b, double rel) {
  EXPECT_EQ(a.dims, b.dims);
  EXPECT_EQ(a.origin, b.origin);
  EXPECT_EQ(a.spacing, b.spacing);
  EXPECT_EQ(a.time, b.time);
  ASSERT_EQ(a.arrays.size(), b.arrays.size());
  for (std::size_t k = 0; k < a.arrays.size(); ++k) {
    EXPECT_EQ(a.arrays[k].name, b.arrays[k].name);
    EXPECT_EQ(a.arrays[k].components, b.arrays[k].components);
    ASSERT_EQ(a.arrays[k].values.size(), b.arrays[k].values.size());
    for (std::size_t i = 0; i < a.arrays[k].values.size(); ++i)
      EXPECT_NEAR(a.arrays[k].values[i], b.arrays[k].values[i], rel * std::abs(a.arrays[k].values[i]));
  }
}

}  // namespace

TEST(GridFields, LinearFieldIsReproducedAtLatticeNodes2D) {
  expectLinearFieldReproduced<2>(21, 5 * kL0, 15 * kL0, kL0);        // nodes on particles (w capped at 3)
  expectLinearFieldReproduced<2>(21, 5 * kL0, 15 * kL0, 0.5 * kL0);  // also edge midpoints and cell centres
}

TEST(GridFields, LinearFieldIsReproducedAtLatticeNodes3D) {
  expectLinearFieldReproduced<3>(11, 4 * kL0, 6 * kL0, 0.5 * kL0);
}

TEST(GridFields, NodesFarFromParticlesHaveNoCoverage) {
  auto p = lattice<2>(5);  // particles in [0, 0.04]^2
  std::vector<double> f(p.size(), 4.0);
  const auto g = spec<2>(-0.1, 0.2, kL0);
  const auto dims = gridNodeCounts<2>(g);
  EXPECT_EQ(dims[0], 31);
  EXPECT_EQ(dims[1], 31);
  EXPECT_EQ(dims[2], 1);
  std::vector<char> selected(p.size(), 1);
  const GridSamples s = sampleOnGrid<2>(g, p.position, selected, f, 1);
  std::size_t covered = 0;
  for (std::size_t node = 0; node < s.coverage.size(); ++node) {
    const double x = -0.1 + kL0 * double(node % 31), y = -0.1 + kL0 * double(node / 31);
    const bool far = x < -g.radius || y < -g.radius || x > 0.04 + g.radius || y > 0.04 + g.radius;
    if (far) {
      EXPECT_EQ(s.coverage[node], 0.0);
      EXPECT_EQ(s.mean[node], 0.0);
    }
    if (s.coverage[node] > 0.0) {
      ++covered;
      EXPECT_NEAR(s.mean[node], 4.0, 1e-14);
    }
  }
  EXPECT_GT(covered, 25u);
  // Unselected particles do not count.
  const GridSamples none = sampleOnGrid<2>(g, p.position, std::vector<char>(p.size(), 0), f, 1);
  for (double c : none.coverage) EXPECT_EQ(c, 0.0);
}

TEST(GridFields, WeightIsCappedOnAndNextToNodes) {
  // One particle on a node, one a rounding error off another: both weigh R/(R/4) - 1 = 3, not 0 or ~1e16.
  std::vector<Vec<2>> x = {Vec<2>(0.0, 0.0), Vec<2>(0.1 + 1e-17, 0.0)};
  const auto g = spec<2>(0.0, 0.1, 0.1);
  const GridSamples s = sampleOnGrid<2>(g, x, {1, 1}, {5.0, 7.0}, 1);
  ASSERT_EQ(s.coverage.size(), 4u);
  EXPECT_NEAR(s.coverage[0], 3.0, 1e-12);
  EXPECT_NEAR(s.coverage[1], 3.0, 1e-12);
  EXPECT_EQ(s.mean[0], 5.0);
  EXPECT_EQ(s.mean[1], 7.0);
  EXPECT_EQ(s.coverage[2], 0.0);
  // Just outside the core the weight is eq. (14)'s: w(R/2) = 1.
  const GridSamples half = sampleOnGrid<2>(g, {Vec<2>(0.5 * g.radius, 0.0)}, {1}, {1.0}, 1);
  EXPECT_NEAR(half.coverage[0], 1.0, 1e-12);
}

TEST(GridFields, FlowFieldsSplitByPhaseAndSkipWalls) {
  auto p = lattice<2>(21);
  std::vector<double> k(p.size());
  for (std::size_t j = 0; j < p.size(); ++j) {
    const bool gas = p.position[j][0] > 0.105;  // x index >= 11
    p.phase[j] = gas ? Phase::Gas : Phase::Liquid;
    p.velocity[j] = gas ? Vec<2>(0.5, -1.5) : Vec<2>(0.0, 2.0);
    k[j] = gas ? 0.02 : 0.001;
    if (p.position[j][1] < 0.015) {  // bottom two rows: a wall moving nowhere, with a k that must not show
      p.kind[j] = ParticleKind::Wall;
      k[j] = 1e6;
    }
  }
  const auto g = spec<2>(0.0, 0.2, kL0);
  const ImageData image =
      sampleFlowFields<2>(g, p, k, 0.75, [&](std::int32_t j) { return p.kind[j] == ParticleKind::Fluid; });
  EXPECT_EQ(image.time, 0.75);
  EXPECT_EQ(image.dims, (std::array<std::int64_t, 3>{21, 21, 1}));
  for (const char* name : {"gas_velocity", "liquid_velocity", "gas_sps_k", "liquid_sps_k", "gas_coverage",
                           "liquid_coverage"})
    ASSERT_NE(image.find(name), nullptr) << name;
  const auto& ug = image.find("gas_velocity")->values;
  const auto& kg = image.find("gas_sps_k")->values;
  const auto& cl = image.find("liquid_coverage")->values;
  const auto& cg = image.find("gas_coverage")->values;
  const std::size_t deep_gas = 10 * 21 + 17, deep_liquid = 10 * 21 + 3, wall_row = 0 * 21 + 3;
  EXPECT_NEAR(ug[3 * deep_gas + 0], 0.5, 1e-14);
  EXPECT_NEAR(ug[3 * deep_gas + 1], -1.5, 1e-14);
  EXPECT_EQ(ug[3 * deep_gas + 2], 0.0);
  EXPECT_NEAR(kg[deep_gas], 0.02, 1e-15);
  EXPECT_EQ(cl[deep_gas], 0.0);
  EXPECT_EQ(cg[deep_liquid], 0.0);
  EXPECT_NEAR(image.find("liquid_velocity")->values[3 * deep_liquid + 1], 2.0, 1e-14);
  EXPECT_NEAR(image.find("liquid_sps_k")->values[deep_liquid], 0.001, 1e-16);
  EXPECT_LT(image.find("liquid_sps_k")->values[wall_row], 0.0011);  // walls excluded by the predicate
  EXPECT_THROW(sampleFlowFields<2>(g, p, std::vector<double>(3), 0.0, [](std::int32_t) { return true; }),
               std::invalid_argument);
}

TEST(GridFields, BadGridsThrow) {
  auto p = lattice<2>(3);
  std::vector<double> f(p.size());
  std::vector<char> sel(p.size(), 1);
  auto g = spec<2>(0.0, 0.1, 0.0);
  EXPECT_THROW(sampleOnGrid<2>(g, p.position, sel, f, 1), std::invalid_argument);
  g = spec<2>(0.1, 0.0, kL0);
  EXPECT_THROW(sampleOnGrid<2>(g, p.position, sel, f, 1), std::invalid_argument);
  g = spec<2>(0.0, 1.0, 1e-6);  // 1e12 nodes
  EXPECT_THROW(gridNodeCounts<2>(g), std::invalid_argument);
  g = spec<2>(0.0, 0.1, kL0);
  EXPECT_THROW(sampleOnGrid<2>(g, p.position, sel, f, 2), std::invalid_argument);
}

TEST(GridFields, VtiRoundTripBinaryIsExact) {
  const auto dir = freshDir("grid_fields_binary");
  const ImageData image = sampleImage();
  writeVti(dir / "f.vti", image, false);
  EXPECT_FALSE(std::filesystem::exists(dir / "f.vti.tmp"));
  expectSameImage(image, readVti(dir / "f.vti"), 0.0);
}

TEST(GridFields, VtiRoundTripAsciiWithinPrintedPrecision) {
  const auto dir = freshDir("grid_fields_ascii");
  const ImageData image = sampleImage();
  writeVti(dir / "f.vti", image, true);
  const std::string text = slurp(dir / "f.vti");
  EXPECT_NE(text.find("type=\"ImageData\""), std::string::npos);
  EXPECT_NE(text.find("WholeExtent=\"0 4 0 3 0 0\""), std::string::npos);
  EXPECT_NE(text.find("Name=\"TimeValue\""), std::string::npos);
  EXPECT_EQ(text.find("AppendedData"), std::string::npos);
  expectSameImage(image, readVti(dir / "f.vti"), 1e-16);  // 17 significant digits
}

TEST(GridFields, BadVtiFilesThrowNamingThePath) {
  const auto dir = freshDir("grid_fields_bad");
  const ImageData image = sampleImage();
  for (bool ascii : {false, true}) {
    writeVti(dir / "f.vti", image, ascii);
    const std::string text = slurp(dir / "f.vti");
    const auto cut = dir / "cut.vti";
    std::ofstream(cut, std::ios::binary) << text.substr(0, text.size() * 2 / 3);
    try {
      readVti(cut);
      ADD_FAILURE() << "a truncated file was read";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(cut.string()), std::string::npos) << e.what();
    }
  }
  std::ofstream(dir / "poly.vti") << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\">\n</VTKFile>\n";
  EXPECT_THROW(readVti(dir / "poly.vti"), std::runtime_error);
  EXPECT_THROW(readVti(dir / "missing.vti"), std::runtime_error);
  ImageData wrong = image;
  wrong.arrays[0].values.pop_back();
  EXPECT_THROW(writeVti(dir / "w.vti", wrong), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(dir / "w.vti"));
}

// The water surface mesh (src/render/surface_mesh, mesh_files): closed, the right volume, outward normals, 2D
// extrusion, and the PLY / POV-Ray files.
#include <gtest/gtest.h>

#include <cmath>

#include "render/mesh_files.hpp"
#include "render/surface_mesh.hpp"
#include "support/scratch.hpp"

using namespace mistfall;

namespace {

constexpr double kL0 = 0.01;

std::vector<Vec<3>> block(int nx, int ny, int nz, double l0) {
  std::vector<Vec<3>> p;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) p.emplace_back(i * l0, j * l0, k * l0);
  return p;
}

}  // namespace

TEST(RenderSurface, LatticeBlockGivesAClosedMeshOfTheBlocksVolume) {
  const auto centres = block(20, 10, 8, kL0);
  const TriangleMesh mesh = liquidSurface(centres, {kL0});
  ASSERT_GT(mesh.triangles.size(), 1000u);
  EXPECT_EQ(openEdgeCount(mesh), 0u);
  const double block_volume = centres.size() * std::pow(kL0, 3);
  EXPECT_NEAR(enclosedVolume(mesh) / block_volume, 1.0, 0.05);
  // The faces lie l0/2 outside the outer centres (x from -l0/2 to 19.5 l0), within a quarter of l0.
  double xmin = 1e9, xmax = -1e9;
  for (const auto& v : mesh.vertices) xmin = std::min(xmin, v.x()), xmax = std::max(xmax, v.x());
  EXPECT_NEAR(xmin, -0.5 * kL0, 0.25 * kL0);
  EXPECT_NEAR(xmax, 19.5 * kL0, 0.25 * kL0);
}

TEST(RenderSurface, NormalsPointOutOfTheWater) {
  const auto centres = block(10, 10, 10, kL0);
  const TriangleMesh mesh = liquidSurface(centres, {kL0});
  const Vec<3> centre(4.5 * kL0, 4.5 * kL0, 4.5 * kL0);
  ASSERT_EQ(mesh.normals.size(), mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    EXPECT_NEAR(mesh.normals[i].norm(), 1.0, 1e-9);
    EXPECT_GT(mesh.normals[i].dot(mesh.vertices[i] - centre), 0.0) << "vertex " << i;
  }
}

TEST(RenderSurface, TwoDimensionalFrameIsExtrudedToASlab) {
  std::vector<Vec<2>> column;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 10; ++j) column.emplace_back(i * kL0, j * kL0);
  const double width = 0.08;
  const auto centres = extrudeAcross(column, kL0, width);
  ASSERT_EQ(centres.size(), 8u * column.size());
  EXPECT_NEAR(centres.front().z(), -0.035, 1e-12);
  EXPECT_NEAR(centres.back().z(), 0.035, 1e-12);
  const TriangleMesh mesh = liquidSurface(centres, {kL0});
  EXPECT_EQ(openEdgeCount(mesh), 0u);
  EXPECT_NEAR(enclosedVolume(mesh) / (column.size() * kL0 * kL0 * width), 1.0, 0.05);
}

TEST(RenderSurface, AdaptiveMeshIsClosedWithFewerTriangles) {
  const auto centres = block(20, 10, 8, kL0);
  SurfaceParameters uniform_parameters{kL0};
  uniform_parameters.adaptivity = 0.0;
  const TriangleMesh uniform = liquidSurface(centres, uniform_parameters);
  const TriangleMesh adaptive = liquidSurface(centres, {kL0});  // the default, 0.1
  EXPECT_EQ(openEdgeCount(uniform), 0u);
  EXPECT_EQ(openEdgeCount(adaptive), 0u);
  EXPECT_LT(adaptive.triangles.size() * 5, uniform.triangles.size());
  EXPECT_NEAR(enclosedVolume(adaptive) / enclosedVolume(uniform), 1.0, 0.02);
}

TEST(RenderSurface, NoParticlesGiveAnEmptyMeshAndABadSpacingThrows) {
  EXPECT_TRUE(liquidSurface({}, {kL0}).triangles.empty());
  EXPECT_THROW(liquidSurface(block(2, 2, 2, kL0), {0.0}), std::invalid_argument);
}

TEST(RenderSurface, PlyRoundTripsAndPovMeshDeclaresTheMesh) {
  const auto dir = test_support::freshDir("render_surface_files");
  const TriangleMesh mesh = liquidSurface(block(4, 4, 4, kL0), {kL0});
  writePly(dir / "m.ply", mesh);
  const TriangleMesh back = readPly(dir / "m.ply");
  ASSERT_EQ(back.vertices.size(), mesh.vertices.size());
  ASSERT_EQ(back.triangles, mesh.triangles);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) EXPECT_LT((back.vertices[i] - mesh.vertices[i]).norm(), 1e-6);
  writePovMesh(dir / "m.inc", mesh, "Water_Surface");
  const std::string pov = test_support::slurp(dir / "m.inc");
  EXPECT_NE(pov.find("#declare Water_Surface = mesh2 {"), std::string::npos);
  EXPECT_NE(pov.find("face_indices { " + std::to_string(mesh.triangles.size())), std::string::npos);
  EXPECT_NE(pov.find("normal_vectors { " + std::to_string(mesh.vertices.size())), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "m.inc.tmp"));
}

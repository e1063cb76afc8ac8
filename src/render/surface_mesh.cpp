// Liquid particles to a closed triangle mesh through an OpenVDB level set (see surface_mesh.hpp).
#include "render/surface_mesh.hpp"

#include <Eigen/Geometry>
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetFilter.h>
#include <openvdb/tools/ParticlesToLevelSet.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>

namespace mistfall {

namespace {

// Sphere radius and erosion in units of l0. A sphere of l0 per particle closes the gaps of a lattice; eroding the
// smoothed union by 0.4 l0 puts a lattice block's faces l0/2 outside its outer particle centres (measured: a
// 20 x 10 x 8 block's mesh holds 1.001 times its count * l0^3; tests/test_render_surface.cpp).
constexpr double kSphereRadius = 1.0;
constexpr double kErosion = 0.4;
constexpr int kHalfWidthVoxels = 4;  // narrow band; wider than the erosion (1.2 voxels at l0/3)

// The particle list ParticlesToLevelSet reads.
struct SphereList {
  using PosType = openvdb::Vec3R;
  const std::vector<Vec<3>>* centres;
  double radius;
  std::size_t size() const { return centres->size(); }
  void getPos(std::size_t n, openvdb::Vec3R& x) const {
    const Vec<3>& c = (*centres)[n];
    x = openvdb::Vec3R(c.x(), c.y(), c.z());
  }
  void getPosRad(std::size_t n, openvdb::Vec3R& x, openvdb::Real& r) const {
    getPos(n, x);
    r = radius;
  }
};

void initialiseOpenVdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

Vec<3> toVec(const openvdb::Vec3s& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

TriangleMesh liquidSurface(const std::vector<Vec<3>>& centres, const SurfaceParameters& parameters) {
  const double l0 = parameters.spacing;
  if (!(l0 > 0.0)) throw std::invalid_argument("liquidSurface: particle spacing must be > 0");
  TriangleMesh mesh;
  if (centres.empty()) return mesh;
  initialiseOpenVdb();
  const double h = parameters.voxel_fraction * l0;
  auto grid = openvdb::FloatGrid::create(static_cast<float>(kHalfWidthVoxels * h));
  grid->setTransform(openvdb::math::Transform::createLinearTransform(h));
  grid->setGridClass(openvdb::GRID_LEVEL_SET);
  openvdb::tools::ParticlesToLevelSet<openvdb::FloatGrid> raster(*grid);
  raster.setRmin(0.5);  // voxels; the spheres are 3 voxels across
  raster.rasterizeSpheres(SphereList{&centres, kSphereRadius * l0});
  raster.finalize(true);
  openvdb::tools::LevelSetFilter<openvdb::FloatGrid> filter(*grid);
  for (int s = 0; s < parameters.smoothing_passes; ++s) filter.meanCurvature();
  filter.offset(static_cast<float>(kErosion * l0));  // > 0 shrinks

  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> tris;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*grid, points, tris, quads, 0.0, parameters.adaptivity);
  mesh.vertices.reserve(points.size());
  for (const auto& p : points) mesh.vertices.push_back(toVec(p));
  // volumeToMesh winds its polygons clockwise seen from outside: reverse them.
  for (const auto& t : tris) mesh.triangles.push_back({int(t[2]), int(t[1]), int(t[0])});
  for (const auto& q : quads) {
    mesh.triangles.push_back({int(q[2]), int(q[1]), int(q[0])});
    mesh.triangles.push_back({int(q[3]), int(q[2]), int(q[0])});
  }
  mesh.normals.assign(mesh.vertices.size(), Vec<3>::Zero());
  for (const auto& t : mesh.triangles) {
    const Vec<3>& a = mesh.vertices[t[0]];
    const Vec<3> n = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);  // |n| = 2 area
    for (int v : t) mesh.normals[v] += n;
  }
  for (auto& n : mesh.normals) {
    const double len = n.norm();
    n = len > 0.0 ? Vec<3>(n / len) : Vec<3>(0.0, 0.0, 1.0);
  }
  return mesh;
}

std::vector<Vec<3>> extrudeAcross(const std::vector<Vec<2>>& centres, double spacing, double width) {
  const int layers = std::max(1, static_cast<int>(std::lround(width / spacing)));
  std::vector<Vec<3>> out;
  out.reserve(centres.size() * layers);
  for (int k = 0; k < layers; ++k) {
    const double z = (k + 0.5 - 0.5 * layers) * spacing;
    for (const auto& c : centres) out.emplace_back(c.x(), c.y(), z);
  }
  return out;
}

double enclosedVolume(const TriangleMesh& mesh) {
  double v = 0.0;
  for (const auto& t : mesh.triangles)
    v += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]]));
  return v / 6.0;
}

std::size_t openEdgeCount(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : mesh.triangles)
    for (int e = 0; e < 3; ++e) {
      const int a = t[e], b = t[(e + 1) % 3];
      uses[{std::min(a, b), std::max(a, b)}] += 1;
    }
  std::size_t open = 0;
  for (const auto& [edge, n] : uses) open += (n != 2);
  return open;
}

}  // namespace mistfall

// The water surface of a frame (section 4 of the paper): the liquid particles become one closed, smooth triangle
// mesh. Each particle is a sphere of radius l0 rasterised into an OpenVDB narrow-band level set (voxel l0/3), the
// set is smoothed by mean-curvature flow and eroded so that a block of particles on a lattice of spacing l0 gets
// its own volume (count * l0^3: the surface lies l0/2 outside the outermost particle centres), and the zero level
// set becomes triangles (OpenVDB volumeToMesh, larger ones where the surface is flat) with area-weighted vertex
// normals pointing out.
// A 2D frame is extruded first: every particle is copied across z in [-width/2, width/2] at spacing l0.
#pragma once

#include <array>
#include <vector>

#include "mps/vector.hpp"

namespace mistfall {

struct TriangleMesh {
  std::vector<Vec<3>> vertices;
  std::vector<Vec<3>> normals;                   // one unit normal per vertex, pointing out of the water
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from outside (right-handed)
};

struct SurfaceParameters {
  double spacing = 0.0;           // l0 [m]
  double voxel_fraction = 1.0 / 3.0;  // voxel size / l0
  int smoothing_passes = 2;       // mean-curvature flow passes on the level set
  // OpenVDB volumeToMesh adaptivity in [0, 1]: 0 = uniform triangles of voxel size; 0.1 merges them on flat
  // parts (a lattice block: a tenth of the triangles, still closed, volume 0.7 % lower).
  double adaptivity = 0.1;
};

// The surface around `centres` (3D particle centres). Empty centres give an empty mesh.
// Throws std::invalid_argument for a spacing <= 0.
TriangleMesh liquidSurface(const std::vector<Vec<3>>& centres, const SurfaceParameters& parameters);

// 2D centres (x, y) copied to z = -width/2 + (k + 1/2) l0, k = 0 .. round(width / l0) - 1 (at least one layer).
std::vector<Vec<3>> extrudeAcross(const std::vector<Vec<2>>& centres, double spacing, double width);

// Volume enclosed by a closed mesh (divergence theorem; positive for outward-facing triangles).
double enclosedVolume(const TriangleMesh& mesh);

// Number of edges not shared by exactly two triangles (0 for a closed mesh).
std::size_t openEdgeCount(const TriangleMesh& mesh);

}  // namespace mistfall

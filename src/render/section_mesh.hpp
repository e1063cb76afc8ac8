// The water of a 2D run as a mesh: the 2D section is meshed and extruded across the fall (README, "Rendering a
// run"; docs/render.md). Exact for a 2D run and far cheaper than extruding particles into layers:
//  1. field: each liquid particle is a disc of radius `radius` l0 (and each jet link a capsule, jet_links.hpp) on a
//     grid of cell `cell_fraction` l0; the signed
//     distance to the union of the discs is smoothed by `smoothing_passes` binomial (1 2 1) passes, which rounds
//     the scallops between neighbours but keeps a sheet one particle thick (a distance field is linear across a
//     flat face, so the smoothing hardly moves a face), then moved in by `erosion` l0 so that a block of
//     particles covers its own area (count * l0^2);
//  2. pockets: regions outside the water but enclosed by it and smaller than `pocket_area` l0^2 (air between
//     particles, entrained air of the plunge zone) are filled: across the fall they would be tunnels; the area
//     they cover is returned (SectionField::pocket) so that it can be drawn as aerated water;
//  3. marching squares: the cells inside the zero level give the section's triangles (filled cells as two
//     triangles, cut cells as their inside polygon; a saddle is joined when its centre is inside), and the cut
//     edges its outline, oriented with the water on the left;
//  4. extrusion: the section becomes the caps at z = +-width/2, the outline the side walls, in `rings` + 1 rings
//     across z. The outline's vertices move along the outline's normal by `variation` * n(x, y, z), n a smooth
//     value noise in [-1, 1] with lengths `variation_length` along the section and a quarter of it across
//     (streaks along the flow: the sheet's thickness varies across the fall), drifting with `time`; the rings
//     next to the caps are l0/4 in from them and the caps' rim normals lean halfway out (a rounded edge).
// The mesh is closed and its triangles face out (surface_mesh.hpp's TriangleMesh).
#pragma once

#include <cstdint>
#include <vector>

#include "mps/vector.hpp"
#include "render/jet_links.hpp"
#include "render/surface_mesh.hpp"

namespace mistfall {

struct SectionParameters {
  double spacing = 0.0;              // l0 [m]
  double cell_fraction = 1.0 / 3.0;  // grid cell / l0
  double radius = 0.75;              // disc radius / l0 (> 1/sqrt 2: no gaps inside a square lattice)
  int smoothing_passes = 3;
  double erosion = 0.1;              // [l0] the smoothed level moves in by this (a block keeps its area)
  double pocket_area = 12.0;         // [l0^2] smaller enclosed air regions are filled
};

// The smoothed signed distance (negative in the water) on a grid of nx x ny nodes, node (i, j) at
// origin + h (i, j); `pocket` is 1 at nodes of filled pockets.
struct SectionField {
  Vec<2> origin = Vec<2>::Zero();
  double h = 0.0;
  int nx = 0, ny = 0;
  std::vector<float> phi;
  std::vector<std::uint8_t> pocket;
  float at(int i, int j) const { return phi[static_cast<std::size_t>(j) * nx + i]; }
};

struct SectionMesh {
  std::vector<Vec<2>> vertices;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise
  std::vector<std::array<int, 2>> outline;    // segments with the water on their left
};

struct ExtrusionParameters {
  double width = 0.0;             // [m] across the fall, z in [-width/2, width/2]
  int rings = 12;                 // segments of the side walls across z (at least 3)
  double variation = 0.0;         // [m] amplitude of the across-fall variation of the outline
  double variation_length = 0.05;  // [m]
  double time = 0.0;              // [s] the noise drifts with time
  double drift_speed = 1.0;       // [m/s] down y: the streaks move with the falling water
  double bevel = 0.0;             // [m] distance of the rings next to the caps from them
};

// `links`: capsules joined to the discs (jet_links.hpp).
SectionField sectionField(const std::vector<Vec<2>>& centres, const SectionParameters& parameters,
                          const std::vector<SectionLink>& links = {});
SectionMesh marchingSquares(const SectionField& field);
TriangleMesh extrudeSection(const SectionMesh& section, const ExtrusionParameters& parameters);

// The area of the section's triangles.
double sectionArea(const SectionMesh& section);

// The smooth value noise of the extrusion in [-1, 1] (tests, and the scene's documentation).
double valueNoise(double x, double y, double z);

}  // namespace mistfall

// The volumes of one frame (docs/render.md, "Mist and white water"), from what frame_scene.hpp collected:
//  * mist (natural style; the lab style draws spheres): every mist representative of the texture stands for
//    1 / texture.representative_ratio droplets of texture.fine_diameter (the paper: 250 of 0.075 mm); splatted
//    into a grid of voxel render.mist_voxel, the value is the volume fraction of water in the air, and its
//    integral the represented mist volume. Light meets droplets much larger than its wavelength with an
//    extinction efficiency of 2, so the extinction coefficient is 2 x (pi d^2 / 4) x number density
//    = 3 x fraction / d [1/m] (40,000 per unit fraction at 0.075 mm).
//  * white water: the air inside the water, as extinction [1/m] on a grid of voxel l0: the run's air in the
//    water (gas particles the solver marked enclosed, bubbles), each of volume l0^D (2D: l0^2 per metre across,
//    spread evenly across the fall), and foam (frame_scene.hpp) as half air, taken as bubbles of
//    render.white_water_bubble_diameter; the texture's micro-bubble representatives as bubbles of
//    texture.fine_diameter; each 3 x air fraction / bubble diameter.
#pragma once

#include "case/case_config.hpp"
#include "render/density_grid.hpp"
#include "render/frame_scene.hpp"

namespace mistfall {

struct FrameVolumes {
  DensityGrid mist;         // volume fraction of water; empty without mist (render.mist = false, lab style)
  double mist_extinction = 0.0;  // [1/m] per unit of mist's value: 3 / fine_diameter
  DensityGrid white_water;  // extinction [1/m]; empty when there is no air in the water (or white_water = false)
};

// The volume [m^3] of the droplets one representative stands for.
double representedVolume(const TextureConfig& texture);

FrameVolumes frameVolumes(const FrameScene& scene, const CaseConfig& config);

}  // namespace mistfall

// What one frame puts into its scene: the liquid particles to mesh, and the spheres and walls.
//  * water mesh: fluid liquid particles, except droplets (category 3) when the frame is classified; a 2D frame is
//    extruded across render.extrusion_width (surface_mesh.hpp);
//  * droplets: category-3 particles as water spheres of diameter l0; bubbles: category-6 particles (isolated gas)
//    as air spheres of diameter l0 (larger gas regions are cavities of the water mesh already); a 2D frame's
//    droplets and bubbles sit at z = 0;
//  * mist and micro-bubbles: the representatives of the texture stage (texture_NNNNN.bin) when there is one, drawn
//    with render.mist_radius and render.micro_bubble_radius (the texture's droplet and bubble sources are the
//    frame's own droplets and bubbles, drawn from the frame);
//  * walls: the case's box-shaped wall regions (2D: across the extrusion width), except those the line of sight
//    from render.camera_location to camera_look_at passes through (a tank's front wall: cut away so that the
//    water shows); circle-shaped walls are not drawn;
//  * the ground plane at the bottom of the domain.
#pragma once

#include <cstdint>
#include <vector>

#include "case/case_config.hpp"
#include "io/texture_files.hpp"
#include "mps/particles.hpp"
#include "render/scene_writer.hpp"

namespace mistfall {

struct FrameScene {
  std::vector<Vec<3>> liquid;  // centres to mesh
  SceneContent content;        // everything but content.mesh_include
};

// `category`: the frame's category array, or empty when it has none; `texture`: the frame's texture or null.
template <int D>
FrameScene frameScene(const Particles<D>& particles, const std::vector<std::uint8_t>& category,
                      const CaseConfig& config, const TextureSnapshot* texture);

}  // namespace mistfall

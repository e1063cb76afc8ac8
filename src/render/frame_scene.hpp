// What one frame puts into its scene (docs/render.md):
//  * water: the fluid liquid particles except droplets (category 3) when the frame is classified: a 2D frame's
//    section (section_mesh.hpp, extruded across render.extrusion_width) with the links of its jets
//    (jet_links.hpp; only links with a droplet at one end at least; a chain of 6 or more linked droplets is a
//    sheet: its links' capsules draw it; shorter chains are spray, drawn as droplets), a 3D frame's centres
//    (surface_mesh.hpp);
//  * air in the water, for the white water: gas particles the solver marked enclosed in liquid and bubbles
//    (category 6); foam: liquid surface particles (category 2) within 1.5 l0 of such air; and the texture's
//    micro-bubble representatives;
//  * mist: the texture's mist representatives (a medium, or spheres in the lab style);
//  * droplets as spheres of diameter l0: the frame's category-3 particles not in a sheet; in 2D at the z of the
//    texture's nearest droplet source within 2 l0 (a place across the fall that stays from frame to frame), else
//    z = 0; bubbles: the texture's bubble sources when there is a texture, else the frame's category 6;
//  * walls: the case's box-shaped wall regions (2D: across the extrusion width), except render.hidden_regions and
//    those the line of sight from render.camera_location to camera_look_at passes through (a tank's front wall:
//    cut away so that the water shows); circle-shaped walls are not drawn;
//  * the scene box (the domain, 2D: across the extrusion) and the ground at its bottom.
#pragma once

#include <cstdint>
#include <vector>

#include "case/case_config.hpp"
#include "io/texture_files.hpp"
#include "mps/particles.hpp"
#include "render/jet_links.hpp"
#include "render/scene_writer.hpp"

namespace mistfall {

struct FrameScene {
  std::vector<Vec<2>> section;        // 2D: liquid centres of the section
  std::vector<SectionLink> links;     // 2D: links of the jets
  std::vector<Vec<3>> liquid;         // 3D: liquid centres to mesh
  std::vector<Vec<2>> air_across;     // 2D: air in the water, each a row across the fall
  std::vector<Vec<3>> air;            // 3D: air in the water
  std::vector<Vec<2>> foam_across;    // 2D: foam, each a row across the fall
  std::vector<Vec<3>> foam;           // 3D: foam
  std::vector<Vec<3>> micro_bubbles;  // texture: micro-bubble representatives
  std::vector<Vec<3>> mist;           // texture: mist representatives
  SceneContent content;               // everything but the mesh include and the volumes
};

// `category`: the frame's category array, or empty when it has none; `texture`: the frame's texture or null.
template <int D>
FrameScene frameScene(const Particles<D>& particles, const std::vector<std::uint8_t>& category,
                      const CaseConfig& config, const TextureSnapshot* texture, double time = 0.0);

}  // namespace mistfall

// One POV-Ray 3.7 scene per frame (section 4: scenes are generated from the simulation output, no hand work).
// The scene is in the simulation's coordinates: the camera's `sky` is the up axis and its `right` vector is
// negated, which makes POV-Ray's frame right-handed like the simulation's. Materials come from materials.inc
// (materials.hpp) in the same folder; the water surface from the frame's mesh include (mesh_files.hpp).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "case/case_config.hpp"
#include "mps/vector.hpp"

namespace mistfall {

struct SceneContent {
  int up_axis = 1;                   // 1 (y) in 2D, 2 (z) in 3D
  std::string mesh_include;          // e.g. "mesh_00012.inc", declaring Water_Surface; empty: no water mesh
  std::vector<Box> walls;            // 3D boxes (M: T_Wall)
  double ground = 0.0;               // height of the ground plane along the up axis
  std::vector<Vec<3>> droplets;      // isolated liquid particles
  double droplet_radius = 0.0;
  std::vector<Vec<3>> bubbles;       // isolated gas particles (under water)
  double bubble_radius = 0.0;
  std::vector<Vec<3>> mist;          // texture: mist representatives
  double mist_radius = 0.0;
  std::vector<Vec<3>> micro_bubbles;  // texture: micro-bubble representatives
  double micro_bubble_radius = 0.0;
};

// The scene text. Image size is POV-Ray's (+W +H); the aspect ratio follows it.
std::string sceneText(const RenderConfig& render, const SceneContent& content, const std::string& title);

// Writes sceneText atomically.
void writeScene(const std::filesystem::path& file, const RenderConfig& render, const SceneContent& content,
                const std::string& title);

}  // namespace mistfall

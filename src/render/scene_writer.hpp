// One POV-Ray 3.7 scene per frame (section 4: scenes are generated from the simulation output, no hand work).
// The scene file holds only what the frame and the case give: the camera, the numbers the scenery is built from
// (`#declare`d: Frame_Time, Up, Sun_Location, Scene_Min/Max, Ground_Level, Water_Width, Bank_Level, Bank_Width and
// the wall boxes Wall_Min/Wall_Max/Wall_Name), the water mesh, droplets and bubbles, and the volumes (df3 files with
// their boxes and extinction). Everything that makes the look is in editable include files installed into the
// run's render folder (materials.hpp): materials.inc (water, white water, mist, droplets, bubbles) and the style's
// scenery, natural.inc (sky, sun, haze, rock, basin) or lab.inc (the grey flume on a checkerboard).
// The scene is in the simulation's coordinates: the camera's `sky` is the up axis and its `right` vector is
// negated, which makes POV-Ray's frame right-handed like the simulation's.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "case/case_config.hpp"
#include "mps/vector.hpp"

namespace mistfall {

// A density file and where it sits: density 1 in the file is `extinction` [1/m].
struct VolumeFile {
  std::string file;
  Vec<3> min = Vec<3>::Zero(), max = Vec<3>::Zero();
  double extinction = 0.0;
};

struct SceneContent {
  int up_axis = 1;                   // 1 (y) in 2D, 2 (z) in 3D
  double time = 0.0;                 // [s] of the frame
  Box scene_box;                     // the domain (2D: times [-water_width/2, water_width/2] in z)
  double water_width = 0.0;          // a 2D run's extrusion width; 0 in 3D
  std::string mesh_include;          // e.g. "mesh_00012.inc", declaring Water_Surface; empty: no water mesh
  std::vector<Box> walls;            // 3D boxes of the drawn wall regions
  std::vector<std::string> wall_names;
  double ground = 0.0;               // height of the ground along the up axis
  std::vector<Vec<3>> droplets;      // isolated liquid particles
  double droplet_radius = 0.0;
  std::vector<Vec<3>> bubbles;       // isolated gas particles (under water)
  double bubble_radius = 0.0;
  std::vector<Vec<3>> mist;          // lab style: mist representatives drawn as spheres
  double mist_radius = 0.0;
  std::vector<Vec<3>> micro_bubbles;  // lab style: micro-bubble representatives drawn as spheres
  double micro_bubble_radius = 0.0;
  std::optional<VolumeFile> mist_volume;  // mist as a participating medium
  std::optional<VolumeFile> white_water;  // aerated water: scattering media inside the water
};

// The include file of the style: "natural.inc" or "lab.inc".
std::string styleInclude(RenderStyle style);

// The scene text. Image size is POV-Ray's (+W +H); the aspect ratio follows it.
std::string sceneText(const RenderConfig& render, const SceneContent& content, const std::string& title);

// Writes sceneText atomically.
void writeScene(const std::filesystem::path& file, const RenderConfig& render, const SceneContent& content,
                const std::string& title);

}  // namespace mistfall

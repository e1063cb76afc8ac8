// `mistfall render RUN_DIR`: the render stage (section 4). For every frame RUN_DIR/frames/frame_NNNNN.vtp whose
// image is not there yet it writes, under RUN_DIR/render/, the water surface (mesh_NNNNN.inc, a POV-Ray mesh2, and
// mesh_NNNNN.ply) and the scene scene_NNNNN.pov (src/render), and runs povray on it, several frames at a time
// (--jobs); then ffmpeg joins the images into RUN_DIR/render/<case>.mp4 and <case>.gif. --preview renders smaller
// images with less quality into RUN_DIR/render/preview/. Camera, light and sizes: [render] of RUN_DIR/case.toml.
// Uses the frames' category array (droplets, bubbles) and RUN_DIR/texture/texture_NNNNN.bin (mist,
// micro-bubbles) when they are there. Images are rendered under a temporary name and renamed when complete, so
// an interrupted render resumes where it stopped.
#pragma once

#include <filesystem>

namespace mistfall {

struct RenderOptions {
  std::filesystem::path run_dir;
  bool preview = false;               // small, quick images into render/preview
  int jobs = 0;                       // povray processes at once; 0: the number of cores
  bool force_plain_progress = false;  // log lines instead of a redrawn bar
};

// Exit codes: cli/exit_codes.hpp. 1 bad input or povray/ffmpeg missing (the message names the Debian package;
// nothing written: the frames to render and their texture files are read first); 2 a file could not be written or
// povray/ffmpeg failed (the message names the log file).
int runRender(const RenderOptions& options);

}  // namespace mistfall

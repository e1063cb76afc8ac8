// `mistfall render RUN_DIR`: the render stage (section 4; docs/render.md). For every frame
// RUN_DIR/frames/frame_NNNNN.vtp nearest to a multiple of render.frame_interval whose image is not there yet it
// writes, under RUN_DIR/render/, the water surface (mesh_NNNNN.inc), the mist's and white water's densities
// (mist_/white_NNNNN.df3) and the scene (scene_NNNNN.pov) (src/render/frame_files.hpp), runs povray on it,
// several frames at a time (--jobs), and deletes those intermediates when the image is complete (unless
// --keep-intermediates); with --export it also writes export/water_NNNNN.ply and export/volumes_NNNNN.vdb for
// other renderers. Then ffmpeg joins the images into RUN_DIR/render/<case>.mp4 and <case>.gif. --preview renders
// smaller images with less quality into RUN_DIR/render/preview/. Style, camera, sun and sizes: [render] of
// RUN_DIR/case.toml. Uses the frames' category array and RUN_DIR/texture/texture_NNNNN.bin (mist,
// micro-bubbles, droplet and bubble sources) when they are there. Images are rendered under a temporary name and
// renamed when complete, so an interrupted render resumes where it stopped. Seconds per step and frame go to
// RUN_DIR/render/timings.csv.
#pragma once

#include <filesystem>

namespace mistfall {

struct RenderOptions {
  std::filesystem::path run_dir;
  bool preview = false;               // small, quick images into render/preview
  int jobs = 0;                       // povray processes at once; 0: the number of cores
  int povray_threads = 1;             // render threads of each povray process (+WT)
  bool keep_intermediates = false;    // keep scene_NNNNN.pov, mesh_NNNNN.inc and the .df3 files
  bool export_files = false;          // also export/water_NNNNN.ply and export/volumes_NNNNN.vdb
  bool force_plain_progress = false;  // log lines instead of a redrawn bar
};

// Exit codes: cli/exit_codes.hpp. 1 bad input or povray/ffmpeg missing (the message names the Debian package;
// nothing written: the frames to render and their texture files are read first); 2 a file could not be written or
// povray/ffmpeg failed (the message names the log file).
int runRender(const RenderOptions& options);

}  // namespace mistfall

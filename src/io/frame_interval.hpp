// Which frames a coarser interval keeps (render.frame_interval, texture.file_interval): the frame at `time` is kept
// when it is the output frame nearest a multiple of `every` (output frames are `output_interval` apart); an
// interval no longer than the output interval keeps every frame.
#pragma once

#include <cmath>

namespace mistfall {

inline bool atFrameInterval(double time, double output_interval, double every) {
  if (every <= output_interval * (1.0 + 1e-9)) return true;
  return std::abs(time - std::round(time / every) * every) < 0.5 * output_interval * (1.0 - 1e-9);
}

}  // namespace mistfall

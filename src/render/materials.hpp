// The default POV-Ray include files of the scenes (render/*.inc, compiled in) and their installation into a run's
// render folder, where users edit them: materials.inc (water, white water, mist, droplets, bubbles), natural.inc
// (the natural scenery: sky, sun, haze, rock, basin) and lab.inc (today's grey flume on a checkerboard).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace mistfall {

// The names of the include files: materials.inc, natural.inc, lab.inc.
const std::vector<std::string>& renderFileNames();

// The default text of one of them (std::out_of_range for another name).
const std::string& defaultRenderFile(const std::string& name);
inline const std::string& defaultMaterials() { return defaultRenderFile("materials.inc"); }

// The text a new run gets for include file `name`: <data directory>/render/<name> of an installed mistfall
// (io/data_files.hpp; users may edit it there), else defaultRenderFile(name).
std::string renderFileText(const std::string& name);
inline std::string materialsText() { return renderFileText("materials.inc"); }

// Writes each include file into DIR (atomically, from renderFileText) unless it exists: an edited copy is kept.
// Returns true when materials.inc was written.
bool installMaterials(const std::filesystem::path& dir);

}  // namespace mistfall

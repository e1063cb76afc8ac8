// The default POV-Ray materials of the scenes (render/materials.inc, compiled in) and their installation into a
// run's render folder, where users edit them.
#pragma once

#include <filesystem>
#include <string>

namespace mistfall {

// The text of render/materials.inc.
const std::string& defaultMaterials();

// The materials a new run gets: <data directory>/render/materials.inc of an installed mistfall (io/data_files.hpp;
// users may edit it), else defaultMaterials().
std::string materialsText();

// Writes DIR/materials.inc (atomically) from materialsText() unless it exists: an edited copy is kept. Returns true
// when written.
bool installMaterials(const std::filesystem::path& dir);

}  // namespace mistfall

// Default materials of the rendered scenes (see materials.hpp).
#include "render/materials.hpp"

#include <fstream>
#include <sstream>

#include "io/atomic_file.hpp"
#include "io/data_files.hpp"
#include "io/errors.hpp"
#include "render/materials_inc.hpp"  // generated into the build tree

namespace mistfall {

const std::string& defaultMaterials() {
  static const std::string text = generated::kMaterialsInc;
  return text;
}

std::string materialsText() {
  const auto data = dataDirectory();
  if (!data) return defaultMaterials();
  const std::filesystem::path file = *data / "render" / "materials.inc";  // an installed mistfall: editable there
  std::ifstream in(file, std::ios::binary);
  if (!in) throwCannotOpen(file, "materials file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool installMaterials(const std::filesystem::path& dir) {
  const auto file = dir / "materials.inc";
  if (std::filesystem::exists(file)) return false;
  const std::string text = materialsText();
  writeFileAtomically(file, [&](std::ostream& out) { out << text; });
  return true;
}

}  // namespace mistfall

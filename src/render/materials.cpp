// Default materials of the rendered scenes (see materials.hpp).
#include "render/materials.hpp"

#include "io/atomic_file.hpp"
#include "render/materials_inc.hpp"  // generated into the build tree

namespace mistfall {

const std::string& defaultMaterials() {
  static const std::string text = generated::kMaterialsInc;
  return text;
}

bool installMaterials(const std::filesystem::path& dir) {
  const auto file = dir / "materials.inc";
  if (std::filesystem::exists(file)) return false;
  writeFileAtomically(file, [](std::ostream& out) { out << defaultMaterials(); });
  return true;
}

}  // namespace mistfall

// Default include files of the rendered scenes (see materials.hpp).
#include "render/materials.hpp"

#include <map>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "render/render_files.hpp"  // generated into the build tree

namespace mistfall {

const std::vector<std::string>& renderFileNames() {
  static const std::vector<std::string> names{"materials.inc", "natural.inc", "lab.inc"};
  return names;
}

const std::string& defaultRenderFile(const std::string& name) {
  static const std::map<std::string, std::string> files{{"materials.inc", generated::kMaterialsInc},
                                                        {"natural.inc", generated::kNaturalInc},
                                                        {"lab.inc", generated::kLabInc}};
  const auto it = files.find(name);
  if (it == files.end()) throw std::out_of_range("no render include file named " + name);
  return it->second;
}

bool installMaterials(const std::filesystem::path& dir) {
  bool materials = false;
  for (const std::string& name : renderFileNames()) {
    const auto file = dir / name;
    if (std::filesystem::exists(file)) continue;
    writeFileAtomically(file, [&](std::ostream& out) { out << defaultRenderFile(name); });
    materials = materials || name == "materials.inc";
  }
  return materials;
}

}  // namespace mistfall

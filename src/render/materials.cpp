// Default include files of the rendered scenes (see materials.hpp).
#include "render/materials.hpp"

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/data_files.hpp"
#include "io/errors.hpp"
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

std::string renderFileText(const std::string& name) {
  const auto data = dataDirectory();
  if (!data) return defaultRenderFile(name);
  const std::filesystem::path file = *data / "render" / name;  // an installed mistfall: editable there
  std::ifstream in(file, std::ios::binary);
  if (!in) throwCannotOpen(file, "render include file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool installMaterials(const std::filesystem::path& dir) {
  bool materials = false;
  for (const std::string& name : renderFileNames()) {
    const auto file = dir / name;
    if (std::filesystem::exists(file)) continue;
    const std::string text = renderFileText(name);
    writeFileAtomically(file, [&](std::ostream& out) { out << text; });
    materials = materials || name == "materials.inc";
  }
  return materials;
}

}  // namespace mistfall

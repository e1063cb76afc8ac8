// mistfall's data files: the editable render includes (render/*.inc) and the example cases (cases/*.toml).
// `cmake --install` puts them in <prefix>/share/mistfall/ next to <prefix>/bin/mistfall; an installed mistfall
// finds them from its own path, so it needs no source tree. A binary that is not installed (build/mistfall) has
// none and uses the copies compiled into it.
#pragma once

#include <filesystem>
#include <optional>

namespace mistfall {

// $MISTFALL_DATA_DIR when set, else <directory of the executable>/../share/mistfall when it holds render/;
// nullopt otherwise.
std::optional<std::filesystem::path> dataDirectory();

}  // namespace mistfall

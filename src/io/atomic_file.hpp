// Atomic file writing: content goes to "path.tmp" first and is renamed over "path" only when complete,
// so a crash or error never leaves a half-written output file behind.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>

namespace mistfall {

// Calls `writer` with a binary ofstream on `file + ".tmp"`, flushes and closes it, then renames it to `file`.
// The parent directory must exist. Throws std::runtime_error naming the path on any failure; on failure
// the temporary file is removed and any existing `file` is left untouched.
void writeFileAtomically(const std::filesystem::path& file, const std::function<void(std::ostream&)>& writer);

// The temporary path used by writeFileAtomically ("file.tmp").
std::filesystem::path temporaryPathFor(const std::filesystem::path& file);

}  // namespace mistfall

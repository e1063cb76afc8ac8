// What a run directory holds and how a new run takes one over: the names of everything mistfall writes into it
// (simulate, classify, texture, render and the plotting tools), the check of an --out path before anything is
// written, and the clearing `--overwrite` does.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace mistfall {

// Files and folders a run directory may hold, all written by mistfall: simulate's case.toml, checkpoint.bin,
// diagnostics.csv, frames.pvd, bubbles.csv, vents.csv, diverged.txt, frames/, fields/ and traces/ (--trace); classify's categories.csv;
// texture/; render/; the tools' plots/.
const std::vector<std::string>& runDirectoryEntries();

// An --out path for a new run: refused (InputError) when it, or a folder on the way to it, exists and is not a
// directory. Writes nothing.
void checkOutputPath(const std::filesystem::path& out);

// Whether `dir` holds nothing but the lock file (a missing directory is empty).
bool isEmptyRunDirectory(const std::filesystem::path& dir);

// Removes everything of runDirectoryEntries() from `dir` (and their .tmp files); returns the names of the entries
// it kept because mistfall did not write them (the lock file aside), for the caller to report.
std::vector<std::string> clearRunDirectory(const std::filesystem::path& dir);

}  // namespace mistfall

// Reading a case file: TOML text -> validated CaseConfig. Every problem is reported as a CaseError whose
// message names the file, the full key path, the offending value and what is allowed.
// The layout and every key are documented in docs/case-file.md. Parsing never touches the file system
// except for reading the one file passed to loadCaseFile and the memory available (case_size.hpp: a case that
// cannot fit is a ResourceError, before the region checks, whose cost grows with the particle count).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include "case/case_config.hpp"
#include "io/errors.hpp"

namespace mistfall {

struct CaseError : InputError {  // bad input: exit code 1
  using InputError::InputError;
};

// Parses and validates a case from TOML text; `source_name` prefixes every error message.
CaseConfig parseCase(std::string_view toml_text, const std::string& source_name);

// Reads `path` and calls parseCase; a missing or unreadable file is a CaseError too.
CaseConfig loadCaseFile(const std::filesystem::path& path);

namespace detail {
// Region geometry checks run by parseCase (bounds, inside domain, non-empty lattice, water overlaps, every
// water or gas region keeping a point after overlaps are resolved, a water region exists); implemented in
// case_regions.cpp. Throws CaseError prefixed with `source_name`.
void validateRegions(const CaseConfig& c, const std::string& source_name);
// Why `name` (a case-file value that becomes a file name) is not usable as one ("contains a path separator"), or ""
// when it is; kFileNameAllowed says what is allowed. Implemented in case_names.cpp.
std::string fileNameProblem(const std::string& name);
extern const char* const kFileNameAllowed;
// Shortest round-trip text of a number for messages: fixed notation for 1e-4 <= |v| < 1e6, else "1e-8".
std::string formatNumber(double v);
}  // namespace detail

}  // namespace mistfall

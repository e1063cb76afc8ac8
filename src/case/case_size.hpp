// The size of a case before any lattice is filled: its particle count and memory estimated from the regions'
// volumes, and the refusal of a case that cannot fit in the memory available (ResourceError, exit code 4), which
// parseCase applies before its region checks (their cost grows with the particle count).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "case/case_config.hpp"

namespace mistfall {

struct CaseSize {
  double fluid = 0.0;  // water and gas particles (regions' lattice points; overlaps counted twice, capped at the
                       // domain's lattice)
  double solid = 0.0;  // wall and dummy particles (likewise)
  double bytes = 0.0;  // peak memory of `simulate` for them (per-particle costs measured, see case_size.cpp)
};

// From the regions' boxes (exact lattice counts) and circles (area or volume / l0^D); touches no lattice.
CaseSize estimateCaseSize(const CaseConfig& c);

// Bytes of memory available now: MemAvailable of /proc/meminfo, lowered to the cgroup's memory.max less its
// memory.current when that is less; nullopt when not known.
std::optional<double> availableMemory();

// Throws ResourceError (prefixed with `source_name`) when estimateCaseSize(c).bytes exceeds availableMemory():
// the message gives the particle count, the estimate and the memory available.
void checkCaseFitsInMemory(const CaseConfig& c, const std::string& source_name);

// "1.5 GB", "820 MB": a byte count for messages.
std::string formatBytes(double bytes);

}  // namespace mistfall

// Names from a case file that become file names (case.name: render/<name>.mp4 and .gif): checked as names, so
// that no case can make mistfall write outside its run directory.
#include <string>

#include "case/case_file.hpp"

namespace mistfall::detail {

const char* const kFileNameAllowed =
    "a non-empty string usable as a file name (at most 200 bytes, without '/', '\\', '..' or control characters)";

std::string fileNameProblem(const std::string& name) {
  if (name.empty()) return "is empty";
  if (name.size() > 200) return "is " + std::to_string(name.size()) + " bytes long";
  if (name.find('/') != std::string::npos || name.find('\\') != std::string::npos)
    return "contains a path separator";
  if (name.find("..") != std::string::npos) return "contains '..'";
  if (name == ".") return "is '.'";
  for (unsigned char ch : name)
    if (ch < 0x20 || ch == 0x7f) return "contains a control character";
  return "";
}

}  // namespace mistfall::detail

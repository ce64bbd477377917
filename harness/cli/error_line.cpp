#include "harness/cli/error_line.h"

#include <cstdio>

namespace vob {

std::string error_line(const std::string& message) {
  std::string out;
  for (const char ch : message) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    } else {
      out += ch;
    }
    if (out.size() > kMaxErrorLine) {
      out.resize(kMaxErrorLine);
      out += " [...]";
      break;
    }
  }
  return out;
}

}  // namespace vob

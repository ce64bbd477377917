#include "harness/cli/error_line.h"

#include <cstdio>

namespace vob {

namespace {
// Length of the well-formed UTF-8 sequence starting at s[i], or 0 if there is none.
size_t utf8_length(const std::string& s, size_t i) {
  const auto c = static_cast<unsigned char>(s[i]);
  const size_t n = c >= 0xF0 && c <= 0xF4 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 && c <= 0xDF ? 2 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  for (size_t k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return 0;
  return n;
}
}  // namespace

std::string error_line(const std::string& message) {
  std::string out;
  for (size_t i = 0; i < message.size() && out.size() <= kMaxErrorLine;) {
    const auto c = static_cast<unsigned char>(message[i]);
    const size_t n = c >= 0x80 ? utf8_length(message, i) : 1;
    if (c < 0x20 || c == 0x7f || n == 0) {  // control byte or a byte that is not UTF-8
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
      ++i;
    } else {
      out.append(message, i, n);
      i += n;
    }
  }
  if (out.size() > kMaxErrorLine) {
    size_t cut = kMaxErrorLine;
    while (cut > 0 && (static_cast<unsigned char>(out[cut]) & 0xC0) == 0x80) --cut;  // whole characters
    out.resize(cut);
    out += " [...]";
  }
  return out;
}

}  // namespace vob

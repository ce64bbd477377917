#include "harness/scene/input_error.h"

#include <sstream>

namespace vob {

std::string short_number(double v) {
  std::ostringstream s;
  s.precision(3);
  s << v;
  return s.str();
}

std::string printable_message(const std::string& text) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  size_t i = 0;
  while (i < text.size()) {
    if (text[i] == ' ') {
      out += ' ';
      ++i;
      continue;
    }
    size_t end = text.find(' ', i);
    if (end == std::string::npos) end = text.size();
    const bool path = text.find('/', i) < end;
    const size_t limit = path ? kMaxInputErrorPath : kMaxInputErrorToken;
    for (size_t k = i; k < end && k < i + limit; ++k) {
      const auto c = static_cast<unsigned char>(text[k]);
      if (c < 0x20 || c >= 0x7f) {
        out += "\\x";
        out += hex[c >> 4];
        out += hex[c & 15];
      } else {
        out += static_cast<char>(c);
      }
    }
    if (end - i > limit) out += "...";
    i = end;
    if (out.size() > kMaxInputErrorChars) {
      out.resize(kMaxInputErrorChars);
      out += "...";
      break;
    }
  }
  return out;
}

}  // namespace vob

// One printable line for an error message: messages can quote bytes of a bad file, so
// control bytes and bytes that are not UTF-8 are shown as \xNN, and a message longer than
// kMaxErrorLine bytes is cut (at a character boundary) and marked " [...]".
#pragma once
#include <string>

namespace vob {

constexpr size_t kMaxErrorLine = 900;

std::string error_line(const std::string& message);

}  // namespace vob

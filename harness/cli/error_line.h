// One printable line for an error message: messages can quote bytes of a bad file, so
// control bytes are shown as \xNN and a very long message is cut, keeping the line readable
// and a single line.
#pragma once
#include <string>

namespace vob {

constexpr size_t kMaxErrorLine = 900;

std::string error_line(const std::string& message);

}  // namespace vob

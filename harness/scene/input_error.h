// Bad input (malformed file, NaN coordinate, inverted cell, impossible parameter) is thrown
// as InputError with one line naming the source, the element and the reason; the CLI
// prints it and exits with code 2. Nothing is repaired silently.
// Messages often quote bytes from the file, so every message is made printable here, once:
// control and non-ASCII bytes become \xNN, tokens longer than 80 characters are cut with
// "...", and the whole line stays within kMaxInputErrorChars.
#pragma once
#include <stdexcept>
#include <string>

namespace vob {

inline constexpr size_t kMaxInputErrorToken = 80;
inline constexpr size_t kMaxInputErrorChars = 900;

// The printable form of `text` described above. Tokens holding a '/' are paths and may run
// to kMaxInputErrorPath characters before they are cut.
inline constexpr size_t kMaxInputErrorPath = 300;
std::string printable_message(const std::string& text);
// A number quoted in a message, to three significant digits.
std::string short_number(double v);

class InputError : public std::runtime_error {
 public:
  InputError(const std::string& source, const std::string& element, const std::string& reason)
      : std::runtime_error(printable_message(source + ": " + element + ": " + reason)) {}
  explicit InputError(const std::string& line) : std::runtime_error(printable_message(line)) {}
};

}  // namespace vob

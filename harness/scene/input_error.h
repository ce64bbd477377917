// Bad input (malformed file, NaN coordinate, inverted cell, impossible parameter) is thrown
// as InputError with one line naming the source, the element and the reason; the CLI
// prints it and exits with code 2. Nothing is repaired silently.
#pragma once
#include <stdexcept>
#include <string>

namespace vob {

class InputError : public std::runtime_error {
 public:
  InputError(const std::string& source, const std::string& element, const std::string& reason)
      : std::runtime_error(source + ": " + element + ": " + reason) {}
  explicit InputError(const std::string& line) : std::runtime_error(line) {}
};

}  // namespace vob

// JSON that comes from outside (suite files, results lines, order files) is parsed through
// here: nlohmann's parser recurses once per nesting level, so a file of a million '[' would
// overflow the stack. The depth is counted first, outside strings, and a file nested deeper
// than max_depth is refused with one line, like any other bad input.
#pragma once
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace vob {

constexpr int kMaxJsonDepth = 64;

// Throws InputError(source, element, reason) when the text is nested deeper than max_depth
// or is not valid JSON. `element` names what is being read ("suite", "line 12", ...).
nlohmann::json parse_json_input(std::string_view text, const std::string& source,
                                const std::string& element, int max_depth = kMaxJsonDepth);

// The deepest nesting of arrays and objects in `text`, counted outside strings (a malformed
// text gives the depth reached before the scan ends).
int json_nesting_depth(std::string_view text);

}  // namespace vob

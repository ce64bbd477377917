#include "harness/bench/json_input.h"

#include <algorithm>

#include "harness/scene/input_error.h"

namespace vob {

int json_nesting_depth(std::string_view text) {
  int depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') in_string = true;
    else if (c == '[' || c == '{') deepest = std::max(deepest, ++depth);
    else if ((c == ']' || c == '}') && depth > 0) --depth;
  }
  return deepest;
}

nlohmann::json parse_json_input(std::string_view text, const std::string& source,
                                const std::string& element, int max_depth) {
  const int depth = json_nesting_depth(text);
  if (depth > max_depth)
    throw InputError(source, element,
                     "nested " + std::to_string(depth) + " levels deep (at most " +
                         std::to_string(max_depth) + " are read)");
  try {
    return nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::exception& e) {
    throw InputError(source, element, std::string("is not valid JSON: ") + e.what());
  }
}

}  // namespace vob

// Messages for an unknown name (orderer, dataset, probe, parameter, reproduction): the
// closest known name, if one is close, and the known names.
#pragma once
#include <string>
#include <vector>

namespace vob {

// The known name nearest `name` by edit distance (case-insensitive) when it is within a
// third of the name's length (at least 1; prefixes count as close), else "".
std::string closest_name(const std::string& name, const std::vector<std::string>& known);
// "did you mean 'helix'? known: gap, helix, zoo" (without the first part when none is close).
std::string known_names_hint(const std::string& name, const std::vector<std::string>& known);

}  // namespace vob

// The prescans' way in: a .msh file read whole, but only when its first bytes say it is
// the version the prescan checks (a file of another version costs a 64-byte read).
#pragma once
#include <string>
#include <string_view>

namespace vob {

// True and the whole file in `out` when it starts with `prefix` (at most 64 bytes);
// false when it does not, or cannot be read (gmsh then says why).
bool read_msh_if_starts_with(const std::string& path, std::string_view prefix, std::string& out);

}  // namespace vob

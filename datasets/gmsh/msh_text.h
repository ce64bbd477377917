// The prescans' way in: a .msh file read whole, but only when its first bytes say it is
// the version the prescan checks (a file of another version costs a 64-byte read).
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

namespace vob {

// The largest node or element tag read exactly. gmsh 4.8 narrows tags to 32-bit ints on
// the way (MSH 4.1 too): 2^32 + 1 became tag 1, and a tag whose low 32 bits are 2^31 or
// more crashed it (SIGSEGV).
inline constexpr uint64_t kMaxGmshTag = 2147483647;
inline const char* const kGmshTagLimit = "is beyond 2147483647 (gmsh reads tags as 32-bit integers)";

// True and the whole file in `out` when it starts with `prefix` (at most 64 bytes);
// false when it does not, or cannot be read (gmsh then says why).
bool read_msh_if_starts_with(const std::string& path, std::string_view prefix, std::string& out);

}  // namespace vob

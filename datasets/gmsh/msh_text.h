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

// gmsh reads lines with fgets and numbers with fscanf, so a file with CRLF line ends (as
// written on Windows) reads as with LF: the prescans take "\r\n" wherever they look for "\n".

// The byte after a line end ("\n" or "\r\n") at `at`, or npos when there is none.
inline size_t after_line_end(std::string_view s, size_t at) {
  if (at < s.size() && s[at] == '\r') ++at;
  return at < s.size() && s[at] == '\n' ? at + 1 : std::string_view::npos;
}

// The first line at or after `from` that is exactly `line` ("$Nodes"): the offset of its
// first byte, or npos.
inline size_t find_line(std::string_view s, std::string_view line, size_t from) {
  for (size_t at = s.find(line, from); at != std::string_view::npos; at = s.find(line, at + 1))
    if ((at == 0 || s[at - 1] == '\n') && after_line_end(s, at + line.size()) != std::string_view::npos) return at;
  return std::string_view::npos;
}

// True and the whole file in `out` when it starts with the line "$MeshFormat" and the next
// line with `version` (at most 48 bytes), `version_at` then the offset of that next line;
// false when it does not, or cannot be read (gmsh then says why).
bool read_msh_if_version(const std::string& path, std::string_view version, std::string& out, size_t& version_at);

}  // namespace vob

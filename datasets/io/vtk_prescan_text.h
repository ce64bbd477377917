// Words and numbers the VTK prescans (vtk_xml_prescan.cpp, vtk_legacy_prescan.cpp) read
// alike: counts a file promises are checked against its size the same way in both.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vob::vtk_prescan {

// The file's size in bytes; InputError when it cannot be read.
uint64_t file_size(const std::string& path);
// Words separated by spaces, tabs and line ends.
std::vector<std::string_view> split(std::string_view s);
// The whole of `s` as an integer or a finite number (a leading '+' allowed).
bool parse_int(std::string_view s, int64_t& v);
bool parse_finite(std::string_view s, double& v);
// A count promised by the file: a non-negative integer no larger than `budget` values.
uint64_t count(const std::string& path, const std::string& element, std::string_view text, double budget,
               const char* what);

}  // namespace vob::vtk_prescan

#include "datasets/io/vtk_prescan_text.h"

#include <charconv>
#include <cmath>
#include <filesystem>

#include "harness/scene/input_error.h"

namespace vob::vtk_prescan {

uint64_t file_size(const std::string& path) {
  std::error_code ec;
  const auto n = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(path, "file", "size cannot be read: " + ec.message());
  return n;
}

std::vector<std::string_view> split(std::string_view s) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r' || s[i] == '\n')) ++i;
    const size_t b = i;
    while (i < s.size() && !(s[i] == ' ' || s[i] == '\t' || s[i] == '\r' || s[i] == '\n')) ++i;
    if (i > b) out.push_back(s.substr(b, i - b));
  }
  return out;
}

bool parse_int(std::string_view s, int64_t& v) {
  const char* b = s.data();
  if (!s.empty() && *b == '+') ++b;
  const auto [p, ec] = std::from_chars(b, s.data() + s.size(), v);
  return ec == std::errc() && p == s.data() + s.size() && b != s.data() + s.size();
}

bool parse_finite(std::string_view s, double& v) {
  const char* b = s.data();
  if (!s.empty() && *b == '+') ++b;
  const auto [p, ec] = std::from_chars(b, s.data() + s.size(), v);
  return ec == std::errc() && p == s.data() + s.size() && b != s.data() + s.size() && std::isfinite(v);
}

uint64_t count(const std::string& path, const std::string& element, std::string_view text,
               double budget, const char* what) {
  int64_t v = 0;
  if (!parse_int(text, v) || v < 0)
    throw InputError(path, element, "'" + std::string(text) + "' is not a valid " + what);
  if (static_cast<double>(v) > budget)
    throw InputError(path, element, std::string(what) + " " + std::to_string(v) +
                                        " cannot fit in a file of this size (" +
                                        std::to_string(static_cast<uint64_t>(budget)) +
                                        " values at most)");
  return static_cast<uint64_t>(v);
}

}  // namespace vob::vtk_prescan

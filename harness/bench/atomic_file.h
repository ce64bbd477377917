// Results, orders and reports are never left half-written: write to a temporary file in
// the same folder, flush, then rename over the target.
#pragma once
#include <string>

namespace vob {
// Creates missing parent folders. Throws std::runtime_error naming the path on failure.
void write_file_atomically(const std::string& path, const std::string& content);
}

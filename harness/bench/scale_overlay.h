// The "tiny" and "full" overlays of reproduction files and suites (docs/pipeline.md,
// "Scales"): any JSON object may carry {"tiny": {...}, "full": {...}}; at that scale the
// overlay's keys replace the object's keys (recursively for objects) before the suite is
// read; at the other scales the overlay is dropped.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace vob {

// "tiny", "default" or "full"; anything else is an InputError naming `source`.
void check_scale(const std::string& scale, const std::string& source);

// `j` with every overlay applied for `scale` and removed. An overlay that is not a JSON
// object is an InputError naming `source` and the entry ("x.json: suites[0].tiny: ...").
nlohmann::json apply_scale(const nlohmann::json& j, const std::string& scale,
                           const std::string& source);

}  // namespace vob

#include "harness/bench/scale_overlay.h"

#include "harness/scene/input_error.h"

namespace vob {
namespace {

// Overlay keys replace the object's; objects meet objects key by key.
void merge_into(nlohmann::json& base, const nlohmann::json& overlay) {
  for (const auto& [k, v] : overlay.items()) {
    if (v.is_object() && base.contains(k) && base[k].is_object() && k != "tiny" && k != "full")
      merge_into(base[k], v);
    else
      base[k] = v;
  }
}

nlohmann::json apply(const nlohmann::json& j, const std::string& scale, const std::string& source,
                     const std::string& where) {
  const auto child = [&](const std::string& k) { return where.empty() ? k : where + "." + k; };
  if (j.is_array()) {
    nlohmann::json out = nlohmann::json::array();
    for (size_t i = 0; i < j.size(); ++i)
      out.push_back(apply(j[i], scale, source, where + "[" + std::to_string(i) + "]"));
    return out;
  }
  if (!j.is_object()) return j;
  nlohmann::json base = nlohmann::json::object();
  for (const auto& [k, v] : j.items()) {
    if (k == "tiny" || k == "full") {
      if (!v.is_object()) throw InputError(source, child(k), "must be a JSON object of keys to replace");
      continue;
    }
    base[k] = v;
  }
  if (j.contains(scale) && scale != "default") merge_into(base, j[scale]);
  // Overlays may themselves hold objects with overlays: resolve children after merging.
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [k, v] : base.items()) out[k] = apply(v, scale, source, child(k));
  return out;
}

}  // namespace

void check_scale(const std::string& scale, const std::string& source) {
  if (scale != "tiny" && scale != "default" && scale != "full")
    throw InputError(source, "scale", "'" + scale + "' is not tiny, default or full");
}

nlohmann::json apply_scale(const nlohmann::json& j, const std::string& scale,
                           const std::string& source) {
  check_scale(scale, source);
  return apply(j, scale, source, "");
}

}  // namespace vob

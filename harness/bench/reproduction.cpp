#include "harness/bench/reproduction.h"

#include <algorithm>
#include <filesystem>

#include "harness/bench/scale_overlay.h"
#include "harness/bench/suite_reader.h"
#include "harness/scene/input_error.h"

namespace vob {

std::vector<ReproductionEntry> list_reproductions(const std::string& suites_dir) {
  namespace fs = std::filesystem;
  std::vector<std::string> files;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(suites_dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file() && it->path().extension() == ".json") files.push_back(it->path().string());
  if (ec) throw InputError(suites_dir, "folder", "cannot be listed: " + ec.message());
  std::sort(files.begin(), files.end());
  std::vector<ReproductionEntry> out;
  for (const auto& f : files) {
    const nlohmann::json j = read_json_file(f, "reproduction");
    if (!j.is_object() || !j.contains("reproduction")) continue;  // a plain suite
    const SuiteReader r(f);
    ReproductionEntry e{r.string(j["reproduction"], "reproduction"),
                        j.contains("summary") ? r.string(j["summary"], "summary") : "", "", f};
    e.title = j.contains("title") ? r.string(j["title"], "title") : "vobench " + e.name + " report";
    for (const auto& o : out)
      if (o.name == e.name) throw InputError(f, "reproduction", "'" + e.name + "' is also in " + o.path);
    out.push_back(e);
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return out;
}

std::string find_reproduction(const std::string& suites_dir, const std::string& name) {
  for (const auto& e : list_reproductions(suites_dir))
    if (e.name == name) return e.path;
  return "";
}

Reproduction load_reproduction(const std::string& path, const std::string& scale,
                               const std::string& suites_dir) {
  const SuiteReader r(path);
  const nlohmann::json j = apply_scale(read_json_file(path, "reproduction"), scale, path);
  r.only_keys(j, "", {"reproduction", "paper", "summary", "title", "suites", "comment"});
  Reproduction rep;
  rep.path = path;
  rep.scale = scale;
  rep.name = r.string(j.value("reproduction", nlohmann::json()), "reproduction");
  if (rep.name.find_first_of("|/ ") != std::string::npos) r.fail("reproduction", "must not contain '|', '/' or spaces");
  if (!j.contains("paper")) r.fail("paper", "is missing (a paper name, or null for the generic report)");
  if (!j["paper"].is_null()) rep.paper = r.string(j["paper"], "paper");
  if (j.contains("summary")) rep.summary = r.string(j["summary"], "summary");
  rep.title = j.contains("title") ? r.string(j["title"], "title") : "vobench " + rep.name + " report";
  if (!j.contains("suites")) r.fail("suites", "is missing");
  const auto& suites = r.array(j["suites"], "suites");
  for (size_t i = 0; i < suites.size(); ++i) {
    const std::string where = "suites[" + std::to_string(i) + "]";
    if (suites[i].is_string()) {
      // A suite file: its own overlays apply at this scale too.
      const std::string file = (std::filesystem::path(suites_dir) / r.string(suites[i], where)).string();
      rep.suites.push_back(SuiteSpec::from_json(apply_scale(read_json_file(file, "suite"), scale, file), file));
    } else {
      rep.suites.push_back(SuiteSpec::from_json(suites[i], path + ": " + where));
    }
  }
  for (size_t a = 0; a < rep.suites.size(); ++a)
    for (size_t b = 0; b < a; ++b)
      if (rep.suites[a].name == rep.suites[b].name)
        r.fail("suites[" + std::to_string(a) + "].name", "'" + rep.suites[a].name + "' names two suites (keys would collide)");
  return rep;
}

}  // namespace vob

#include "harness/cli/experiment_table.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "harness/bench/atomic_file.h"
#include "harness/bench/context.h"

namespace vob {

std::string format_cell(const nlohmann::json& v) {
  if (v.is_null()) return "-";
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
  if (v.is_number_integer() || v.is_number_unsigned()) return v.dump();
  const double d = v.get<double>();
  if (d == std::floor(d) && std::fabs(d) < 1e15) return std::to_string(static_cast<long long>(d));
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g", d);
  return buf;
}

std::string write_experiment_doc(const ExperimentContext& ctx, const ExperimentDoc& doc) {
  namespace fs = std::filesystem;
  std::string md = "# " + doc.title + "\n\n" + doc.intro + "\n\n";
  nlohmann::json j{{"experiment", doc.name}, {"title", doc.title}, {"context", run_context()},
                   {"tables", nlohmann::json::array()}, {"claims", doc.claims}};
  for (const auto& t : doc.tables) {
    md += "## " + t.title + "\n\n|";
    for (const auto& c : t.columns) md += " " + c + " |";
    md += "\n|";
    for (size_t i = 0; i < t.columns.size(); ++i) md += "---|";
    md += "\n";
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& r : t.rows) {
      md += "|";
      nlohmann::json row = nlohmann::json::object();
      for (size_t i = 0; i < r.size(); ++i) {
        md += " " + format_cell(r[i]) + " |";
        row[i < t.columns.size() ? t.columns[i] : std::to_string(i)] = r[i];
      }
      md += "\n";
      rows.push_back(row);
    }
    if (!t.notes.empty()) md += "\n" + t.notes + "\n";
    md += "\n";
    j["tables"].push_back({{"title", t.title}, {"columns", t.columns}, {"rows", rows}, {"notes", t.notes}});
  }
  for (const auto& f : doc.figures) md += "![" + f + "](" + f + ")\n\n";
  if (!doc.claims.empty()) {
    md += "## Shape claims\n\n";
    for (const auto& c : doc.claims) md += "- " + c + "\n";
    md += "\n";
  }
  const std::string md_path = (fs::path(ctx.out_dir) / (doc.name + ".md")).string();
  write_file_atomically(md_path, md);
  write_file_atomically((fs::path(ctx.out_dir) / (doc.name + ".json")).string(), j.dump(1) + "\n");
  return md_path;
}

}  // namespace vob

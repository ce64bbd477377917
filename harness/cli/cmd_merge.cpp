// vobench merge A.jsonl B.jsonl ... -o ALL.jsonl: the records of several results files (the
// shards of a run, farms, runs on other machines) in one file, every key once, each run's
// context line before the first of its records (docs/pipeline.md "Shards, merge and the MPI
// farm"). Two records with one key are duplicates: the first (in argument order) is kept.
// A duplicate that differs in settings, source revision, host or oracle verdict is a
// conflict: each is named on stderr and the exit code is 1 (the merged file is still
// written). Another host's measurement of the same job cannot share the file (every key
// once), and dropping it silently lost a machine's results; `report A B` or `compare A B`
// keep both. A duplicate from another run on the same host is counted as measured again.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "harness/bench/atomic_file.h"
#include "harness/bench/context.h"
#include "harness/bench/job_plan.h"
#include "harness/bench/json_input.h"
#include "harness/cli/commands.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
struct Line {
  nlohmann::json j;
  std::string text, where;  // the line as written; "FILE line N"
};

// The lines of one results file; an incomplete last line (a writer killed mid-line) is
// left out with a note, as every reader of results files does.
std::vector<Line> read_lines(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "results", "cannot be read");
  std::stringstream buf;
  buf << in.rdbuf();
  const std::string all = buf.str();
  std::vector<Line> out;
  size_t start = 0, n = 0;
  while (start < all.size()) {
    size_t nl = all.find('\n', start);
    const bool last_open = nl == std::string::npos;
    if (last_open) nl = all.size();
    const std::string text = all.substr(start, nl - start);
    start = nl + 1;
    ++n;
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string where = "line " + std::to_string(n);
    if (last_open && !nlohmann::json::accept(text)) {
      std::cerr << "vobench: note: " << path << ": " << where << ": an incomplete last line left out\n";
      break;
    }
    nlohmann::json j = parse_json_input(text, path, where);
    if (!j.is_object() || !j.contains("key") || !j["key"].is_string())
      throw InputError(path, where, "is not a results record (no string \"key\")");
    out.push_back({std::move(j), text, path + " " + where});
  }
  return out;
}

const char* const kSettings[] = {"suite",  "algorithm", "parameters", "probe", "dataset_spec", "repeats",
                                 "warmup", "threads",   "w",          "h",     "view_index",   "views",
                                 "camera", "scale",     "claims"};

std::string shown(const nlohmann::json& v) {
  std::string s = v.is_null() ? "absent" : v.dump();
  return s.size() > 60 ? s.substr(0, 57) + "..." : s;
}

// What makes two records with one key disagree: settings, revision, verdict; "" if nothing.
std::string difference(const nlohmann::json& a, const nlohmann::json& b, const std::string& rev_a,
                       const std::string& rev_b) {
  std::string why;
  const auto add = [&](const std::string& what, const nlohmann::json& x, const nlohmann::json& y) {
    why += (why.empty() ? "" : "; ") + what + " " + shown(x) + " against " + shown(y);
  };
  for (const char* k : kSettings) {
    const nlohmann::json x = a.value(k, nlohmann::json()), y = b.value(k, nlohmann::json());
    if (x != y) add(std::string("settings: ") + k, x, y);
  }
  if (rev_a != rev_b) add("revision", rev_a, rev_b);
  if (a.value("host", nlohmann::json()) != b.value("host", nlohmann::json()))
    add("host", a.value("host", nlohmann::json()), b.value("host", nlohmann::json()));
  const nlohmann::json oa = a.value("oracle", nlohmann::json()), ob = b.value("oracle", nlohmann::json());
  for (const char* k : {"supersample", "covered_pixels", "violating_pixels", "violating_fragments"}) {
    const nlohmann::json x = oa.is_object() ? oa.value(k, nlohmann::json()) : nlohmann::json();
    const nlohmann::json y = ob.is_object() ? ob.value(k, nlohmann::json()) : nlohmann::json();
    if (x != y) add(std::string("verdict: oracle.") + k, x, y);
  }
  if (a.contains("input_fault") != b.contains("input_fault")) add("verdict: input_fault", a.contains("input_fault"), b.contains("input_fault"));
  return why;
}
}  // namespace

Command add_merge_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("merge", "merge results files (shards, farms, machines) into one: every key once");
  auto inputs = std::make_shared<std::vector<std::string>>();
  auto out = std::make_shared<std::string>();
  cmd->add_option("results", *inputs, "results files (JSONL)")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", *out, "the merged results file (must not exist yet)")->required();
  return [=]() {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::exists(*out, ec)) throw InputError("--output", "'" + *out + "'", "exists (merge writes a new file)");
    std::vector<std::vector<Line>> files;
    std::map<std::string, const Line*> contexts;  // run_id -> its context line (the first seen)
    for (const std::string& path : *inputs) files.push_back(read_lines(path));
    for (const auto& f : files)
      for (const Line& l : f)
        if (is_context_line(l.j) && l.j.contains("run_id") && l.j["run_id"].is_string())
          contexts.emplace(l.j["run_id"].get<std::string>(), &l);
    const auto revision = [&](const nlohmann::json& r) -> std::string {
      const auto it = contexts.find(r.value("run_id", ""));
      if (it == contexts.end()) return r.contains("context") ? r["context"].value("git_sha", "") : "";
      return it->second->j["context"].value("git_sha", "");
    };
    std::map<std::string, const Line*> first;  // key -> the record kept
    std::vector<const Line*> kept;
    size_t duplicates = 0, conflicts = 0, measured_again = 0, plan_lines = 0;
    for (const auto& f : files)
      for (const Line& l : f) {
        if (is_context_line(l.j)) continue;
        const std::string key = l.j["key"].get<std::string>();
        const auto [it, fresh] = first.emplace(key, &l);
        if (fresh) {
          kept.push_back(&l);
          if (is_plan_line(l.j)) ++plan_lines;
          continue;
        }
        if (is_plan_line(l.j)) continue;  // a suite's plan line (job_plan.h), in two files: kept once
        ++duplicates;
        const nlohmann::json& a = it->second->j;
        if (a.value("run_id", "") == l.j.value("run_id", "") && a == l.j) continue;  // the same record twice
        const std::string why = difference(a, l.j, revision(a), revision(l.j));
        if (why.empty()) {
          measured_again += a.value("run_id", "") != l.j.value("run_id", "");
          continue;
        }
        if (++conflicts <= 20)
          std::cerr << "vobench: merge: conflict: " << key << ": " << l.where << " differs from " << it->second->where
                    << " (kept): " << why << "\n";
      }
    if (conflicts > 20) std::cerr << "vobench: merge: ... and " << conflicts - 20 << " more conflicts\n";
    std::string text;
    std::map<std::string, bool> written;  // run_ids whose context line is out
    size_t context_lines = 0;
    for (const Line* l : kept) {
      const std::string run = l->j.value("run_id", "");
      const auto ctx = contexts.find(run);
      if (ctx != contexts.end() && !written[run]) {
        written[run] = true;
        text += ctx->second->text + "\n";
        ++context_lines;
      }
      text += l->text + "\n";
    }
    write_file_atomically(*out, text);
    std::cerr << "merge: " << kept.size() - plan_lines << " records and " << plan_lines << " suite plans from " << inputs->size() << " files, " << duplicates
              << " duplicate keys dropped (" << conflicts << " conflicting), " << measured_again
              << " measured again by another run on the same host (the first kept), " << context_lines
              << " run contexts -> " << *out << "\n";
    return conflicts > 0 ? 1 : 0;
  };
}

}  // namespace vob

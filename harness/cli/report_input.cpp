#include "harness/cli/report_input.h"

#include <fstream>
#include <iostream>

#include "harness/bench/context.h"
#include "harness/bench/job_plan.h"
#include "harness/bench/json_input.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
enum class Want { String, Integer, Number, Object };

const char* want_name(Want w) {
  switch (w) {
    case Want::String: return "a string";
    case Want::Integer: return "an integer";
    case Want::Number: return "a number";
    case Want::Object: return "an object";
  }
  return "?";
}

bool fits(const nlohmann::json& v, Want w) {
  switch (w) {
    case Want::String: return v.is_string();
    case Want::Integer: return v.is_number_integer();
    case Want::Number: return v.is_number();
    case Want::Object: return v.is_object();
  }
  return false;
}

struct Field {
  const char* path;  // JSON pointer
  Want want;
  bool required;
};

// What reports/report.py reads from a record (keep in step with it).
const Field kFields[] = {
    {"/algorithm", Want::String, true},        {"/dataset", Want::String, true},
    {"/w", Want::Integer, true},               {"/h", Want::Integer, true},
    {"/n", Want::Integer, true},               {"/total", Want::Object, true},
    {"/total/median", Want::Number, true},     {"/phases", Want::Object, true},
    {"/prepare", Want::Object, true},          {"/prepare/seconds", Want::Number, true},
    {"/cycles", Want::Object, true},           {"/cycles/count", Want::Integer, true},
    {"/bytes", Want::Object, true},            {"/bytes/orderer", Want::Integer, true},
    {"/bytes/derived", Want::Integer, true},   {"/claims", Want::Object, false},
    {"/context", Want::Object, false},         {"/counters", Want::Object, false},
    {"/counters/havs_violating_pixels", Want::Number, false},
    {"/oracle", Want::Object, false},          {"/oracle/covered_pixels", Want::Number, false},
    {"/oracle/violating_pixels", Want::Number, false},
    {"/oracle/max_k", Want::Number, false},    {"/image_error", Want::Object, false},
    {"/images", Want::Object, false},
};

std::string field_name(const char* pointer) {
  std::string s = pointer + 1;
  for (char& c : s)
    if (c == '/') c = '.';
  return s;
}
}  // namespace

std::string report_record_problem(const nlohmann::json& r) {
  if (!r.is_object()) return "is not a JSON object (a results record)";
  // Probe records feed the table scripts; the generic report leaves them out.
  if (r.contains("probe")) return r["probe"].is_string() ? "" : "field 'probe' must be a string";
  for (const Field& f : kFields) {
    const nlohmann::json::json_pointer p(f.path);
    // A parent that is absent was reported already (required) or makes its children moot.
    if (!r.contains(p.parent_pointer())) continue;
    if (!r.contains(p)) {
      if (f.required) return "field '" + field_name(f.path) + "' is missing";
      continue;
    }
    if (!fits(r.at(p), f.want))
      return "field '" + field_name(f.path) + "' must be " + want_name(f.want);
  }
  for (const auto& [name, v] : r.at("phases").items())
    if (!v.is_object() || !v.contains("median") || !v["median"].is_number())
      return "field 'phases." + name + "' must be an object with a number 'median'";
  if (r.contains("image_error") && !(r["image_error"].contains("rmse") && r["image_error"]["rmse"].is_number()))
    return "field 'image_error.rmse' must be a number";
  if (r.contains("images")) {
    for (const char* k : {"order", "exact", "diff"})
      if (!r["images"].contains(k) || !r["images"][k].is_string())
        return std::string("field 'images.") + k + "' must be a string";
    if (!r.contains("view_index") || !r["view_index"].is_number_integer())
      return "field 'view_index' must be an integer";
  }
  return {};
}

void check_report_inputs(const std::vector<std::string>& paths, bool plans_suffice) {
  size_t records = 0, plans = 0;
  for (const auto& path : paths) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "results", "cannot be read");
    std::string line;
    size_t n = 0;
    bool seen_line = false;  // a complete non-blank line before this one
    while (std::getline(in, line)) {
      ++n;
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      const std::string where = "line " + std::to_string(n);
      // A last line without its newline that is not JSON, after complete lines, was torn by
      // a writer killed mid-write: left out, as the table scripts and the next run do
      // (results.h). Alone in its file it is just a bad file.
      if (in.eof() && seen_line && !nlohmann::json::accept(line)) {
        std::cerr << "vobench: note: " << path << ": " << where << ": an incomplete last line (" << line.size()
                  << " bytes, left by an interrupted writer) left out\n";
        break;
      }
      const nlohmann::json r = parse_json_input(line, path, where);
      seen_line = true;
      if (is_context_line(r)) {  // a run's context (docs/pipeline.md "Records"), not a record
        if (!r.contains("context") || !r["context"].is_object() || !r.contains("run_id") || !r["run_id"].is_string())
          throw InputError(path, where, "context line needs a string 'run_id' and an object 'context'");
        continue;
      }
      if (is_plan_line(r)) {  // a suite's plan (job_plan.h): the jobs it meant to measure
        if (!r.contains("suite") || !r["suite"].is_string() || !r.contains("jobs") || !r["jobs"].is_array())
          throw InputError(path, where, "plan line needs a string 'suite' and an array 'jobs'");
        ++plans;
        continue;
      }
      const std::string problem = report_record_problem(r);
      if (!problem.empty()) throw InputError(path, where, problem);
      ++records;
    }
  }
  if (records == 0 && !(plans_suffice && plans > 0))
    throw InputError(paths.empty() ? std::string("results") : paths.back(), "results",
                     "holds no records");
}

}  // namespace vob

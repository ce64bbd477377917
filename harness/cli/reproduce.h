// `vobench reproduce NAME` and `vobench report DIR`: running a reproduction's suites and
// probes into DIR/results.jsonl (resumable) and building its tables from the records.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/bench/jobs.h"
#include "harness/bench/progress.h"
#include "harness/bench/reproduction.h"

namespace vob {

// Part of the jobs only (`--shard I/N`): the groups `take_group` accepts, records placed
// so; tables are left to `vobench report` on the merged folder. Null take_group: all.
struct RunPart {
  std::function<bool(const std::string&)> take_group;
  nlohmann::json placement;
};

// Runs the suites into out_dir/results.jsonl, keeping the records already there unless
// `force` (which drops the records of reproduction `name` and the images they name; other
// reproductions' records in the folder stay), printing progress: [k/N] over all the suites
// (and over `all`, reproduce all's tracker, when given); after each suite its vtk_render
// entry (vtk_render_child.h; not in a shard). Returns 0, 130 / 143 when SIGINT / SIGTERM
// stopped the run (every finished record is on disk), or vobench-vtk's failing status.
int run_suites_into(const std::vector<SuiteSpec>& suites, const std::string& name,
                    const std::string& out_dir, bool force, const RunTags& tags,
                    ProgressTracker* all = nullptr, const RunPart* part = nullptr);

// The whole reproduction: its suites, then its tables (build_tables.py --only NAME when it
// has a paper, else the generic report as NAME.md). Refuses (InputError) a folder holding
// this reproduction's records at another scale. Returns the exit status.
int reproduce(const Reproduction& rep, const std::string& out_dir, bool force, ProgressTracker* all = nullptr,
              const RunPart* part = nullptr);
// What reproduce does around its runs, for the MPI farm (rank 0): the folder checked (scale)
// and, with `force`, rid of these reproductions' records; and the tables once the records are in.
void prepare_folder(const std::vector<Reproduction>& reps, const std::string& out_dir, bool force);
int build_tables(const Reproduction& rep, const std::string& out_dir);

// `--dry-run`: the jobs of the reproductions (dry_run.h) against out_dir/results.jsonl, a
// total per reproduction and, for more than one, over all. Makes no scene, writes nothing.
// `costs_path` (--costs): a results file whose records calibrate the estimates instead.
void dry_run_reproductions(const std::vector<Reproduction>& reps, const std::string& out_dir, bool force,
                           const std::string& costs_path = "");

// `vobench reproduce all`: every reproduction with a paper, validated first, run in name
// order into the one folder out_dir/results.jsonl (record keys carry the reproduction), each
// with its tables; then build_tables.py out_dir, which also writes the claims summary
// (claims-summary.md / .json / .html). `force` drops the folder's records once, before the first.
// A reproduction that fails is reported and the others still run; a stop signal ends the
// run. Returns the exit status (the first failure's, or 128 + signal).
int reproduce_all(const std::vector<Reproduction>& reps, const std::string& out_dir, bool force,
                  const RunPart* part = nullptr);

// Every table of every reproduction whose records are in DIR/results.jsonl, and the
// generic report of its orderer records (NAME.md too when they belong to one reproduction
// without a paper). Returns the exit status.
int report_folder(const std::string& dir, const std::string& suites_dir);

// The generic report (reports/report.py) of results files into out_dir; `name` adds
// NAME.md / NAME.json. Returns the script's exit status.
int run_report(const std::vector<std::string>& results, const std::string& out_dir,
               const std::string& title, const std::string& name);

}  // namespace vob

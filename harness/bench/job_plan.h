// The jobs of a suite counted and costed before any scene is made (docs/pipeline.md
// "Progress and --dry-run"): what `[k/N]` and `--dry-run` print. Keys come from
// dataset_jobs() itself, run on a stand-in scene of the dataset's kind (a few cells), so
// they are the keys the run will use; a dataset's size comes from records of it already in
// the results file, else from its generator parameters, else it is a guess (said so).
#pragma once
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/bench/jobs.h"
#include "harness/bench/suite.h"

namespace vob {

// What a results file already says: finished keys, the size of every dataset it has
// records of, and frame times to calibrate seconds per cost unit.
struct KnownRecords {
  std::set<std::string> keys;
  std::map<std::string, double> primitives;  // dataset label -> n
  double seconds = 0, cost = 0;              // calibration: measured seconds and their cost
  size_t timed = 0;                          // records that gave both
  // key -> the source revision (context git_sha) of the run that wrote it ("" unknown)
  std::map<std::string, std::string> revision;
  // Nothing when the file does not exist; never creates or writes it.
  static KnownRecords read(const std::string& results_path);
  double seconds_per_unit() const { return cost > 0 ? seconds / cost : 0; }
};

// The cost model: the work of one job in "units". An orderer job runs repeats + warmup
// frames, each touching every primitive (projecting, sorting, traversing); the pixels are
// touched once per job (the oracle's samples, or the image and its set-up), not per frame,
// since most orderers do not rasterize at all. A sum, not a product: a sorting orderer does
// not slow down with a larger window. The first version charged pixels per frame, and on
// `reproduce all --tiny` its estimate stayed twice the real time (512x512 views of small
// meshes dominated the cost and ran fast). What the model misses (prepare, compositing
// orderers, scene generation) is absorbed by the measured seconds per unit, which is why
// the estimate calibrates from the run's own jobs.
// `oracle_samples`: the oracle's samples per pixel (supersample^2), 0 without the oracle.
double orderer_job_cost(double primitives, double pixels, int repeats, int warmup, int oracle_samples);
// A probe: repeats + warmup passes over its scene (1e5 primitives when it has none).
double probe_job_cost(double primitives, int repeats, int warmup);

struct PlannedJob {
  std::string key, line;  // line: "mpvo view 3 512x512" or the probe's label
  std::string unit;       // what is prepared once per dataset: the orderer spec or the probe's label
  double pixels = 0;      // orderer jobs; 0 for probes
  bool probe = false, done = false;  // done: its key is in the results file
  double cost = 0;
  // What the plan line (plan_line) says of it: orderer spec or probe label, size, view, and
  // the effective thread count its key and record carry.
  std::string algorithm, probe_label;
  int w = 0, h = 0, view_index = 0, threads = 0;
};

struct PlannedDataset {
  std::string label;         // empty: the probes without a scene
  SceneKind kind = SceneKind::Cells;
  double primitives = 0;
  std::string size_from;     // "records", "parameters", "file size (a guess)", "unknown (1e5 assumed)"
  std::string views_note;    // non-empty: how the view count was found
  std::string row;              // the records' "row" (DatasetSpec::row_label)
  nlohmann::json dataset_spec;  // the records' "dataset_spec"; null for the sceneless probes
  std::vector<PlannedJob> jobs;
  size_t to_do() const;
  double cost_to_do() const;
};

struct RunPlan {
  std::vector<PlannedDataset> datasets;  // plan_datasets() order, then the sceneless probes
  size_t jobs() const;
  size_t to_do() const;
  double cost_to_do() const;
};

RunPlan plan_run(const SuiteSpec& suite, const RunTags& tags, const KnownRecords& known);
// Of the jobs the plans find done, those written by a build of another source revision
// than `current`, counted per revision: a rerun keeps them, so the user is told whose
// numbers they are.
// `take` (if set) limits it to the jobs of one part of the run.
using PlannedJobFilter = std::function<bool(const PlannedDataset&, const PlannedJob&)>;
std::map<std::string, size_t> done_by_other_revisions(const RunPlan& plan, const KnownRecords& known,
                                                      const std::string& current, const PlannedJobFilter& take = {});
// One line for them ("" when there are none): how many, by which revisions, and how to
// measure them again (`to_measure_again`: "--force", "another -o").
std::string other_revisions_note(const std::map<std::string, size_t>& others, const std::string& current,
                                 const std::string& to_measure_again);
// The suite's plan line of the results file (docs/pipeline.md "Incomplete data"):
// {"key": "plan|RUN_ID|SUITE", "type": "plan", "run_id", "schema_version", "suite", "reproduction" (when any),
// "scale", "jobs": [{"key", "dataset", "dataset_spec", "algorithm" or "probe", "w", "h",
// "view_index", "threads"}, ...]}: every job of the suite, done or not, so a report can say
// which planned jobs have no record.
nlohmann::json plan_line(const std::string& run_id, const std::string& suite_name, const RunTags& tags,
                         const RunPlan& plan);
bool is_plan_line(const nlohmann::json& j);
// A context or a plan line: a line of the results file that is not a record.
bool is_meta_line(const nlohmann::json& j);
// A dataset's part of the plan again once its scene is made: its real jobs and size.
PlannedDataset plan_made(const SuiteSpec& suite, const std::string& label, const std::vector<Job>& jobs,
                         double primitives, const KnownRecords& known);
// The cost of a job of the run, with the scene's real size.
double job_cost(const SuiteSpec& suite, const Job& job, double primitives);
// The kind of scene a dataset makes, without making it (an input file's from its extension).
SceneKind dataset_kind(const DatasetSpec& ds);
// The job's unit on its dataset (job_partition.h groups jobs by it): spec or probe label.
std::string job_unit(const Job& job);
// A guess at a dataset's primitives from its parameters, without generating it; 0 if none.
double estimated_primitives(const DatasetSpec& ds, std::string* from);

}  // namespace vob

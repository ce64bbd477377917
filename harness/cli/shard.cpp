#include "harness/cli/shard.h"

#include <dlfcn.h>

#include <cstdio>
#include <filesystem>
#include <regex>
#include <set>

#include "harness/bench/progress.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
std::string amount(double cost, bool seconds) {
  char buf[64];
  if (seconds && cost >= 60) return ProgressTracker::clock_text(cost);
  std::snprintf(buf, sizeof buf, seconds ? "%.3g s" : "%.3g units", cost);
  return buf;
}
}  // namespace

void SpreadOptions::add_to(CLI::App& cmd) {
  cmd.add_option("--shard", shard,
                 "run shard I of N (1 <= I <= N): a deterministic partition of the job groups "
                 "(orderer or probe x dataset, never split) balanced by estimated cost")
      ->type_name("I/N");
  cmd.add_option("--costs", costs,
                 "a results file whose recorded times weigh the groups (--shard, --mpi, --ranks); "
                 "every shard must be given the same one")
      ->check(CLI::ExistingFile);
  cmd.add_option("--ranks", ranks, "with --dry-run: the estimated makespan on R ranks (list scheduling, largest first)")
      ->check(CLI::Range(1, 1 << 20));
  cmd.add_flag("--mpi", mpi,
               "run as an MPI task farm under mpirun (rank 0 hands out job groups and writes the "
               "records; needs the libvobench-mpi.so module, built when MPI is found)");
  cmd.add_flag("--pin", pin, "with --mpi: pin each rank to one core of its host");
}

void SpreadOptions::check(bool dry_run) {
  if (!shard.empty()) {
    static const std::regex form("([0-9]{1,6})/([0-9]{1,6})");
    std::smatch m;
    if (!std::regex_match(shard, m, form))
      throw InputError("--shard", "'" + shard + "'", "must be I/N, e.g. 2/8");
    index = std::stoi(m[1]);
    count = std::stoi(m[2]);
    if (count < 1 || index < 1 || index > count)
      throw InputError("--shard", "'" + shard + "'", "needs 1 <= I <= N");
  }
  if (pin && !mpi) throw InputError("--pin", "option", "applies to --mpi only");
  if (ranks > 0 && !dry_run) throw InputError("--ranks", "option", "applies to --dry-run only");
  if (mpi && sharded()) throw InputError("--mpi", "option", "and --shard exclude each other (the farm spreads the whole suite)");
  if (mpi && dry_run) throw InputError("--mpi", "option", "and --dry-run exclude each other (use --dry-run --ranks R)");
}

std::function<bool(const std::string&)> shard_filter(const std::vector<FarmSuite>& suites,
                                                     const SpreadOptions& spread, std::ostream& log) {
  const RecordedTimes times = RecordedTimes::read(spread.costs);
  const std::vector<JobGroup> groups = plan_groups(suites, KnownRecords::read(spread.costs), times);
  auto ids = std::make_shared<std::set<std::string>>();
  double cost = 0, total = 0;
  size_t jobs = 0;
  for (const JobGroup& g : groups) total += g.cost;
  for (const JobGroup* g : shard_groups(groups, spread.index, spread.count)) {
    ids->insert(g->id);
    cost += g->cost;
    jobs += g->keys.size();
  }
  const bool seconds = times.seconds_per_unit() > 0;
  log << "shard " << spread.shard_text() << ": " << ids->size() << " of " << groups.size() << " job groups, "
      << jobs << " jobs, estimated " << amount(cost, seconds) << " of " << amount(total, seconds)
      << (seconds ? " (recorded times of " + spread.costs + ")" : " (cost model, uncalibrated)") << "\n";
  return [ids](const std::string& id) { return ids->count(id) > 0; };
}

void print_makespan(std::ostream& out, const std::vector<JobGroup>& groups, int ranks,
                    const RecordedTimes& times, const std::string& times_from) {
  std::vector<double> costs;
  for (const JobGroup& g : groups) costs.push_back(g.cost_to_do);
  const Schedule s = list_schedule(costs, ranks);
  const bool seconds = times.seconds_per_unit() > 0;
  out << "makespan on " << ranks << " rank" << (ranks == 1 ? "" : "s") << ": ~" << amount(s.makespan, seconds)
      << " (list scheduling of " << groups.size() << " job groups, largest first; total "
      << amount(s.total, seconds) << ", total/" << ranks << " = " << amount(s.total / ranks, seconds) << ")\n";
  if (s.largest >= 0) {
    const JobGroup& g = groups[size_t(s.largest)];
    out << "  largest indivisible group: " << g.id << ", " << g.keys.size() - g.done.size() << " jobs, "
        << amount(g.cost_to_do, seconds)
        << (s.makespan <= g.cost_to_do * 1.0000001 ? ": it alone sets the makespan" : "") << "\n";
  }
  out << "  " << (seconds ? "seconds calibrated from " + std::to_string(times.records) + " recorded jobs in " + times_from +
                                " (their own times where recorded, else cost units at their rate)"
                          : std::string("cost units (no recorded times to calibrate them: give --costs FILE)"))
      << "; farm ranks are workers (rank 0 only hands out the groups)\n";
}

int run_farm(const FarmRequest& request) {
  const std::string path = farm_module_path();
  std::error_code ec;
  if (path.empty() || !std::filesystem::exists(path, ec))
    throw InputError("--mpi", "option",
                     "this vobench was built without MPI (no " + (path.empty() ? std::string("libvobench-mpi.so") : path) +
                         "; install libopenmpi-dev and build again)");
  // RTLD_GLOBAL: Open MPI's own components look up libmpi's symbols globally.
  void* lib = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
  if (!lib) {
    const char* why = dlerror();
    throw InputError("--mpi", "'" + path + "'", std::string("cannot be loaded (") + (why ? why : "unknown") + ")");
  }
  void* entry = dlsym(lib, VOBENCH_MPI_FARM_ENTRY);
  if (!entry) throw InputError("--mpi", "'" + path + "'", "has no entry point " VOBENCH_MPI_FARM_ENTRY);
  return reinterpret_cast<int (*)(const FarmRequest*)>(entry)(&request);
}

}  // namespace vob

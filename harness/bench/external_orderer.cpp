#include "harness/bench/external_orderer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include "datasets/datasets.h"
#include "datasets/io/subprocess.h"  // last_line_of
#include "harness/bench/registry.h"
#include "harness/bench/sorter_answer.h"
#include "harness/bench/sorter_process.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
namespace fs = std::filesystem;

const char* scene_file_extension(SceneKind k) {
  switch (k) {
    case SceneKind::Cells: return ".vtu";
    case SceneKind::Triangles: return ".off";
    case SceneKind::Voxels: return ".vti";
  }
  return "";
}

class ExternalOrderer final : public Orderer {
 public:
  ExternalOrderer(std::string command, double timeout) : command_(std::move(command)), timeout_(timeout) {}
  ~ExternalOrderer() override {
    if (process_) {  // `run`: a sorter that fails at its exit cannot take back its records
      const std::string problem = process_->finish(2.0);
      if (!problem.empty())
        std::cerr << "vobench: warning: " << where() << ": after its last view it " << problem << "\n";
    }
    process_.reset();  // before the folder holding its stderr file goes
    std::error_code ec;
    if (!dir_.empty()) fs::remove_all(dir_, ec);
  }
  // The end of the views (`check`): the sorter must exit with status 0 once its input ends.
  void finish() {
    if (!process_) return;
    const std::string problem = process_->finish(timeout_);
    if (!problem.empty()) {
      const std::string err = last_line_of((fs::path(dir_) / "stderr.txt").string());
      process_.reset();
      throw InputError(where(), "after its last view", "it " + problem + (err.empty() ? "" : " (its stderr: " + err + ")"));
    }
  }
  Claims claims() const override { return {}; }
  size_t bytes() const override { return 0; }  // the sorter's memory is its own
  void set_view_index(int i) { view_index_ = i; }

  void prepare(const Scene& scene, PhaseClock& clock) override {
    scene_ = scene;
    {
      auto p = clock.phase("write scene");
      std::string tmpl = (fs::temp_directory_path() / "vobench-sorter-XXXXXX").string();
      if (!mkdtemp(tmpl.data())) throw InputError(where(), "scene file", "cannot make a temporary folder");
      dir_ = tmpl;
      scene_path_ = (fs::path(dir_) / (std::string("scene") + scene_file_extension(scene.kind()))).string();
      write_scene(scene, scene_path_);
    }
    auto p = clock.phase("start");
    process_ = std::make_unique<SorterProcess>(
        command_,
        std::vector<std::pair<std::string, std::string>>{{"VOBENCH_SCENE", scene_path_},
                                                         {"VOBENCH_KIND", scene_kind_name(scene.kind())}},
        (fs::path(dir_) / "stderr.txt").string(), dir_);
  }

  Ordering order(const Camera& view, PhaseClock& clock) override {
    if (!process_) throw InputError(where(), view_name(), "the sorter is not running (an earlier view failed)");
    const nlohmann::json request{{"view_index", view_index_}, {"camera", view.to_json()}};
    // The round trip: from writing the request to a checked order in memory.
    const auto t0 = std::chrono::steady_clock::now();
    const auto deadline = t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                   std::chrono::duration<double>(timeout_));
    std::string line;
    SorterProcess::Io io = process_->write_line(request.dump(), deadline);
    // An answer needs about 12 bytes per id; far more without a newline is not one.
    const size_t max_bytes = 64 * scene_.num_primitives() + (size_t(16) << 20);
    if (io == SorterProcess::Io::Ok) io = process_->read_line(line, deadline, max_bytes);
    if (io == SorterProcess::Io::TooLong)
      fail("wrote more than " + std::to_string(max_bytes) + " bytes without ending the line");
    if (io == SorterProcess::Io::Timeout) fail("did not answer within " + short_number(timeout_) + " s (timeout)");
    if (io == SorterProcess::Io::Gone) fail(process_->exit_description() + " before answering");
    const auto answered = std::chrono::steady_clock::now();
    SorterAnswer answer;
    const std::string malformed = decode_sorter_answer(line, answer);
    if (!malformed.empty()) fail(malformed);
    const std::string problem = permutation_problem(scene_, answer.order);
    if (!problem.empty()) fail("the order " + problem);
    const auto done = std::chrono::steady_clock::now();
    const double round_trip = std::chrono::duration<double>(done - t0).count();
    double sorter_seconds = 0;
    for (const auto& [name, s] : answer.phases) sorter_seconds += s;
    // The sorter times its phases inside the round trip: more than it is a wrong clock, and
    // a record must not carry it (1 ms and 1% of slack for clock steps and rounding).
    if (sorter_seconds > round_trip * 1.01 + 1e-3)
      fail("reported phases summing to " + short_number(sorter_seconds) + " s, longer than the " +
           short_number(round_trip) + " s round trip vobench measured");
    for (const auto& [name, s] : answer.phases) clock.add("sorter:" + name, s);
    // The rest of the round trip: encoding, pipes, decoding, the sorter's untimed work.
    clock.add("round_trip", std::max(0.0, round_trip - sorter_seconds));
    Ordering out;
    out.order = std::move(answer.order);
    out.counters["round_trip_seconds"] = round_trip;
    // vobench's own share: decoding and checking the answer.
    out.counters["decode_seconds"] = std::chrono::duration<double>(done - answered).count();
    return out;
  }

 private:
  std::string command_;
  double timeout_;
  int view_index_ = 0;
  Scene scene_;
  std::string dir_, scene_path_;
  std::unique_ptr<SorterProcess> process_;

  std::string where() const { return "command '" + command_ + "'"; }
  std::string view_name() const { return "view " + std::to_string(view_index_); }
  // One line naming the command, the view and what was wrong (with the sorter's last
  // stderr line when it left one); the sorter is stopped: later views cannot trust it.
  [[noreturn]] void fail(const std::string& why) {
    process_->kill_group();
    process_.reset();
    const std::string err = last_line_of((fs::path(dir_) / "stderr.txt").string());
    throw InputError(where(), view_name(), why + (err.empty() ? "" : " (its stderr: " + err + ")"));
  }
};

struct ExternalEntry {
  std::string command;
  SceneKind kind;
  double timeout;
};
std::map<std::string, ExternalEntry>& external_entries() {
  static std::map<std::string, ExternalEntry> entries;
  return entries;
}
}  // namespace

std::unique_ptr<Orderer> make_external_orderer(const std::string& command, double timeout_seconds) {
  return std::make_unique<ExternalOrderer>(command, timeout_seconds);
}

void set_external_view_index(Orderer& orderer, int view_index) {
  if (auto* e = dynamic_cast<ExternalOrderer*>(&orderer)) e->set_view_index(view_index);
}

void finish_external_orderer(Orderer& orderer) {
  if (auto* e = dynamic_cast<ExternalOrderer*>(&orderer)) e->finish();
}

void register_external_orderer(const std::string& name, const std::string& command, SceneKind kind,
                               double timeout_seconds) {
  auto& entries = external_entries();
  const auto known = entries.find(name);
  if (known != entries.end() && known->second.command == command && known->second.kind == kind &&
      known->second.timeout == timeout_seconds)
    return;
  if (known != entries.end())
    throw InputError("orderer", name, "is already registered with another command, kind or timeout");
  register_orderer({name, kind, "external sorter: " + command, {},
                    [command, timeout_seconds](const ResolvedParams&) {
                      return make_external_orderer(command, timeout_seconds);
                    }});
  entries[name] = {command, kind, timeout_seconds};
}

std::string permutation_problem(const Scene& scene, const std::vector<int32_t>& order) {
  const size_t n = scene.num_primitives();
  const std::string what = scene.kind() == SceneKind::Cells       ? "cells"
                           : scene.kind() == SceneKind::Triangles ? "triangles"
                                                                  : "significant voxels";
  if (order.size() != n)
    return "has " + std::to_string(order.size()) + " ids for " + std::to_string(n) + " " + what;
  if (scene.kind() == SceneKind::Voxels) {
    const std::vector<int32_t>& ids = scene.significant_voxels();  // sorted
    std::vector<char> seen(n, 0);
    for (size_t i = 0; i < order.size(); ++i) {
      const auto it = std::lower_bound(ids.begin(), ids.end(), order[i]);
      if (it == ids.end() || *it != order[i])
        return "holds " + std::to_string(order[i]) + " (at " + std::to_string(i) + "), not a significant voxel";
      if (seen[it - ids.begin()]++) return "repeats voxel " + std::to_string(order[i]) + " (at " + std::to_string(i) + ")";
    }
    return "";
  }
  std::vector<char> seen(n, 0);
  for (size_t i = 0; i < order.size(); ++i) {
    const int32_t id = order[i];
    if (id < 0 || static_cast<size_t>(id) >= n)
      return "holds " + std::to_string(id) + " (at " + std::to_string(i) + "), not an id in [0, " +
             std::to_string(n) + ")";
    if (seen[id]++) return "repeats " + std::to_string(id) + " (at " + std::to_string(i) + ")";
  }
  return "";
}

}  // namespace vob

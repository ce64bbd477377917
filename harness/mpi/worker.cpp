// A farm worker: asks rank 0 for a group, runs it with run_suite (only that group; records
// sent to rank 0 instead of written; a job that throws reported as failed and the group
// goes on), and asks again until told to stop.
#include <set>

#include "harness/bench/context.h"
#include "harness/bench/runner.h"
#include "harness/mpi/farm.h"
#include "harness/mpi/farm_messages.h"

namespace vob::farm {

namespace {
// Records to rank 0: this worker's context line before its first record.
class ToRankZero : public RecordSink {
 public:
  ToRankZero(std::string run_id, nlohmann::json placement) : run_id_(std::move(run_id)), placement_(std::move(placement)) {}
  std::set<std::string> done_keys;  // of the group at hand, already in the results file
  bool done(const std::string& key) override { return done_keys.count(key) > 0; }
  bool report(const Record& rec) override {
    if (!context_sent_) {
      nlohmann::json ctx = run_context(rec.threads);
      ctx["placement"] = placement_;
      send(0, kRecord, context_line(run_id_, ctx).dump());
      context_sent_ = true;
    }
    send(0, kRecord, rec.to_json().dump());
    return true;
  }

 private:
  std::string run_id_;
  nlohmann::json placement_;
  bool context_sent_ = false;
};
}  // namespace

void work(const FarmRequest& req, const nlohmann::json& placement) {
  const std::string run_id = new_run_id();
  ToRankZero sink(run_id, placement);
  SceneCache scenes;
  send(0, kReady, "");
  for (;;) {
    const Message m = wait(0);
    if (m.tag == kStop) return;
    const nlohmann::json a = nlohmann::json::parse(m.text);
    const FarmSuite& fs = req.suites.at(a["suite"].get<size_t>());
    const std::string group = a["group"].get<std::string>();
    sink.done_keys = a["done"].get<std::set<std::string>>();
    const auto fail = [&](const std::string& key, const std::string& reason) {
      send(0, kFailure,
           nlohmann::json{{"job_key", key}, {"group", group}, {"reason", reason}, {"run_id", run_id},
                          {"rank", placement["rank"]}, {"host", placement["host"]}}
               .dump());
    };
    RunOptions opt;
    opt.results_path = req.results_path;  // its folder holds the images
    opt.tags = fs.tags;
    opt.validate_full = req.validate_full;
    opt.take_group = [group](const std::string& id) { return id == group; };
    opt.sink = &sink;
    opt.on_failure = [&](const std::string& key, const std::string&, const std::string& reason) { fail(key, reason); };
    opt.run_id = run_id;
    opt.placement = placement;
    opt.scene_cache = &scenes;
    ProgressTracker tracker;
    const KnownRecords none;
    opt.tracker = &tracker;
    opt.known = &none;
    opt.stop_requested = [&req] { return req.stop_signal && req.stop_signal() != 0; };
    try {
      run_suite(fs.suite, opt);
    } catch (const std::exception& e) {
      fail("", e.what());  // the group as a whole (e.g. its image folder cannot be written)
    }
    send(0, kReady, "");
  }
}

}  // namespace vob::farm

// Test plugin: "threads-seen" orders cells by id and reports, as counters, the TBB
// parallelism in effect while it orders (run_threads()) and the threads that ran a parallel
// loop of short busy tasks, so a
// test can see that `--threads N` and a suite's thread counts reach the timed code.
// "frames-logged" orders cells by id and appends its parameter `tag` to the file named by
// VOB_FRAME_LOG at every frame, so a test can see the order in which a run measures frames.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <set>
#include <thread>

#include <numeric>

#include "harness/bench/jobs.h"
#include "harness/bench/plugin.h"

namespace {

class ThreadsSeen final : public vob::Orderer {
 public:
  vob::Claims claims() const override { return {}; }
  void prepare(const vob::Scene& scene, vob::PhaseClock& clock) override {
    auto p = clock.phase("prepare");
    n_ = scene.num_primitives();
  }
  vob::Ordering order(const vob::Camera&, vob::PhaseClock& clock) override {
    auto p = clock.phase("order");
    vob::Ordering out;
    out.order.resize(n_);
    std::iota(out.order.begin(), out.order.end(), 0);
    out.counters["run_threads"] = vob::run_threads();
    out.counters["loop_threads"] = double(loop_threads());
    return out;
  }
  size_t bytes() const override { return 0; }

 private:
  // Threads that took part in 64 tasks of ~0.2 ms each: 1 under a limit of 1 thread.
  static size_t loop_threads() {
    std::mutex m;
    std::set<std::thread::id> ids;
    tbb::parallel_for(tbb::blocked_range<int>(0, 64, 1), [&](const tbb::blocked_range<int>&) {
      const auto t0 = std::chrono::steady_clock::now();
      while (std::chrono::steady_clock::now() - t0 < std::chrono::microseconds(200)) {
      }
      std::lock_guard<std::mutex> lock(m);
      ids.insert(std::this_thread::get_id());
    });
    return ids.size();
  }

  size_t n_ = 0;
};

class FramesLogged final : public vob::Orderer {
 public:
  explicit FramesLogged(int tag) : tag_(tag) {}
  vob::Claims claims() const override { return {}; }
  void prepare(const vob::Scene& scene, vob::PhaseClock&) override { n_ = scene.num_primitives(); }
  vob::Ordering order(const vob::Camera&, vob::PhaseClock& clock) override {
    auto p = clock.phase("order");
    if (const char* log = std::getenv("VOB_FRAME_LOG")) std::ofstream(log, std::ios::app) << tag_ << ' ';
    vob::Ordering out;
    out.order.resize(n_);
    std::iota(out.order.begin(), out.order.end(), 0);
    return out;
  }
  size_t bytes() const override { return 0; }

 private:
  int tag_;
  size_t n_ = 0;
};

}  // namespace

extern "C" void vobench_register_orderers(void) {
  vob::register_orderer({"frames-logged", vob::SceneKind::Cells,
                         "test plugin: cells by id; appends `tag` to $VOB_FRAME_LOG at every frame",
                         {vob::ParamSpec::integer("tag", 0, 0, 9, "written to the log at each frame")},
                         [](const vob::ResolvedParams& p) -> std::unique_ptr<vob::Orderer> {
                           return std::make_unique<FramesLogged>(p.get_int("tag"));
                         }});
  vob::register_orderer({"threads-seen", vob::SceneKind::Cells,
                         "test plugin: cells by id; counters: the TBB parallelism while ordering",
                         {},
                         [](const vob::ResolvedParams&) -> std::unique_ptr<vob::Orderer> {
                           return std::make_unique<ThreadsSeen>();
                         }});
}

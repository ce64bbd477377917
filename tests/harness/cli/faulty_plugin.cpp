// Test plugin: orderers that fail the way a third-party sorter can. "exits-while-ordering"
// calls exit(0) inside order() (as a library it calls might); "throws-while-ordering"
// throws a std::runtime_error there. Neither may end a check with status 0.
#include <cstdlib>
#include <stdexcept>

#include "harness/bench/plugin.h"

namespace {

class Faulty final : public vob::Orderer {
 public:
  explicit Faulty(bool exits) : exits_(exits) {}
  vob::Claims claims() const override { return {}; }
  void prepare(const vob::Scene&, vob::PhaseClock&) override {}
  vob::Ordering order(const vob::Camera&, vob::PhaseClock&) override {
    if (exits_) std::exit(0);
    throw std::runtime_error("the sorter's own failure");
  }
  size_t bytes() const override { return 0; }

 private:
  bool exits_;
};

}  // namespace

extern "C" void vobench_register_orderers(void) {
  vob::register_orderer({"exits-while-ordering", vob::SceneKind::Cells, "calls exit(0) inside order()", {},
                         [](const vob::ResolvedParams&) { return std::make_unique<Faulty>(true); }});
  vob::register_orderer({"throws-while-ordering", vob::SceneKind::Cells, "throws inside order()", {},
                         [](const vob::ResolvedParams&) { return std::make_unique<Faulty>(false); }});
}

#include "harness/bench/orderer.h"

namespace vob {

void CycleReport::add(const std::vector<int32_t>& members) {
  ++cycles;
  for (int32_t m : members) {
    if (primitives.size() >= kMaxReported) return;
    primitives.push_back(m);
  }
}

}  // namespace vob

#include "harness/bench/orderer.h"

#include <stdexcept>

namespace vob {

void CycleReport::add(const std::vector<int32_t>& members) {
  ++cycles;
  for (int32_t m : members) {
    if (primitives.size() >= kMaxReported) return;
    primitives.push_back(m);
  }
}

OracleResult Orderer::composited_verdict(const Camera&, bool) {
  throw std::logic_error("composited_verdict called on an orderer that does not composite");
}

void Orderer::composited_images(const Camera&, Image&, Image&) {
  throw std::logic_error("composited_images called on an orderer that does not composite");
}

}  // namespace vob

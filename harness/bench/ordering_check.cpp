#include "harness/bench/ordering_check.h"

#include <algorithm>
#include <stdexcept>

namespace vob {

void check_complete(const Scene& scene, const Ordering& o, const std::string& who) {
  const std::vector<int32_t>* ids = nullptr;
  size_t n = scene.num_primitives();
  if (scene.kind() == SceneKind::Voxels) ids = &scene.significant_voxels();
  if (o.order.size() != n)
    throw std::logic_error(who + ": ordering has " + std::to_string(o.order.size()) +
                           " entries for " + std::to_string(n) + " primitives");
  if (ids) {
    std::vector<int32_t> sorted = o.order;
    std::sort(sorted.begin(), sorted.end());
    if (sorted != *ids) throw std::logic_error(who + ": ordering is not a permutation of the significant voxels");
    return;
  }
  std::vector<char> seen(n, 0);
  for (int32_t id : o.order) {
    if (id < 0 || static_cast<size_t>(id) >= n || seen[id])
      throw std::logic_error(who + ": ordering repeats or invents primitive " + std::to_string(id));
    seen[id] = 1;
  }
}

}  // namespace vob

#include "datasets/generators/shuffle.h"

#include <climits>
#include <numeric>
#include <utility>
#include <vector>

#include "datasets/generators/splitmix.h"
#include "harness/scene/space_curve.h"

namespace vob {

namespace {
std::vector<int32_t> random_permutation(size_t n, SplitMix64& rng) {
  std::vector<int32_t> v(n);
  std::iota(v.begin(), v.end(), 0);
  for (size_t i = n; i > 1; --i) std::swap(v[i - 1], v[rng.next() % i]);
  return v;
}
}  // namespace

int read_shuffle_param(Params& p) { return p.get_int("shuffle", 0, 0, INT_MAX); }

CellMesh shuffle_numbering(const CellMesh& mesh, uint64_t seed) {
  SplitMix64 rng(seed);
  const std::vector<int32_t> cells = random_permutation(mesh.num_cells(), rng);
  const std::vector<int32_t> points = random_permutation(mesh.num_points(), rng);
  return permute_mesh(mesh, cells, points);
}

}  // namespace vob

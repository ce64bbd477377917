// Times the oracle on a large tet block (not a test: run by hand to measure scale).
// Usage: oracle_timing [cubes_per_side=55] [size=512] [supersample=1]
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "harness/oracle/oracle.h"
#include "harness/view/view_set.h"
#include "tests/support/test_meshes.h"

using namespace vob;

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 55;
  const int size = argc > 2 ? std::atoi(argv[2]) : 512;
  const int S = argc > 3 ? std::atoi(argv[3]) : 1;
  using clk = std::chrono::steady_clock;
  auto secs = [](clk::time_point a) { return std::chrono::duration<double>(clk::now() - a).count(); };
  auto t0 = clk::now();
  const Scene s = Scene::from_mesh("tet block", test::kuhn_block(n));
  std::printf("cells %zu, built in %.2f s\n", s.num_primitives(), secs(t0));
  ViewOptions vo;
  vo.width = vo.height = size;
  const Camera cam = fibonacci_view(s.bounds(), 14, 3, vo);
  auto order = test::tet_block_exact_order(s.mesh(), n, cam);
  OracleOptions o;
  o.supersample = S;
  for (int rep = 0; rep < 2; ++rep) {
    t0 = clk::now();
    const OracleResult r = check_ordering(s, cam, order, o);
    std::printf("%s order: %.2f s, %lld fragments, max_list %d, violating %lld, max_k %d\n",
                rep ? "reversed" : "exact", secs(t0), (long long)r.fragments, r.max_list,
                (long long)r.violating_fragments, r.max_k);
    std::reverse(order.begin(), order.end());
  }
  return 0;
}

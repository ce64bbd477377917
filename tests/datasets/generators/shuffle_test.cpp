// shuffle=SEED on helix and gap: the same cells and points in a different numbering,
// deterministic for a seed, off by default, out-of-range seeds refused like any parameter.
#include <algorithm>
#include <tuple>
#include <vector>

#include "datasets/generators/shuffle.h"
#include "tests/support/test_meshes.h"
#include "tests/support/test_util.h"

using namespace vob;
using namespace vob::test;

namespace {
// The cells as sorted lists of their vertex positions, sorted: equal for two numberings
// of one mesh.
std::vector<std::vector<std::tuple<double, double, double>>> cell_set(const CellMesh& m) {
  std::vector<std::vector<std::tuple<double, double, double>>> out;
  for (size_t c = 0; c < m.num_cells(); ++c) {
    std::vector<std::tuple<double, double, double>> v;
    for (int k = 0; k < m.cell_size(c); ++k) {
      const Vec3 p = m.points[m.cell_points(c)[k]];
      v.emplace_back(p.x, p.y, p.z);
    }
    std::sort(v.begin(), v.end());
    out.push_back(v);
  }
  std::sort(out.begin(), out.end());
  return out;
}
}  // namespace

TEST(Shuffle, RenumbersCellsAndPointsOfTheSameMesh) {
  for (const char* name : {"helix", "gap"}) {
    const auto base = name == std::string("helix")
                          ? std::map<std::string, std::string>{{"cells", "3000"}}
                          : std::map<std::string, std::string>{{"nx", "4"}, {"ny", "3"}, {"nz", "5"}};
    auto with = [&](const char* seed) {
      auto p = base;
      p["shuffle"] = seed;
      return dataset(name, p);
    };
    const Scene plain = dataset(name, base), off = with("0"), a = with("5"), a2 = with("5"), b = with("6");
    EXPECT_EQ(off.mesh().conn, plain.mesh().conn) << name;  // 0: the generator's numbering
    EXPECT_EQ(a.mesh().conn, a2.mesh().conn) << name;       // deterministic
    EXPECT_EQ(a.mesh().points, a2.mesh().points) << name;
    EXPECT_NE(a.mesh().conn, plain.mesh().conn) << name;
    EXPECT_NE(a.mesh().points, plain.mesh().points) << name;
    EXPECT_NE(a.mesh().conn, b.mesh().conn) << name;
    EXPECT_EQ(cell_set(a.mesh()), cell_set(plain.mesh())) << name;
    EXPECT_EQ(a.faces().boundary.size(), plain.faces().boundary.size()) << name;
    EXPECT_THROW(with("-1"), InputError) << name;
    EXPECT_THROW(with("x"), InputError) << name;
  }
}

TEST(Shuffle, KeepsScalarsWithTheirPoints) {
  const CellMesh m = kuhn_block(3);
  const CellMesh s = shuffle_numbering(m, 42);
  ASSERT_EQ(s.num_points(), m.num_points());
  for (size_t p = 0; p < s.num_points(); ++p) EXPECT_EQ(s.scalars[p], test_scalar(s.points[p]));
}

#include "datasets/generators/prism_split.h"

#include <algorithm>

#include "harness/geometry/vec3.h"

namespace vob {

namespace {
// Dompierre's table: the rotation of the prism that brings the smallest id to vertex 0
// (each row is a proper symmetry of the prism, so orientation is kept).
constexpr int kRotate[6][6] = {{0, 1, 2, 3, 4, 5}, {1, 2, 0, 4, 5, 3}, {2, 0, 1, 5, 3, 4},
                               {3, 5, 4, 0, 2, 1}, {4, 3, 5, 1, 0, 2}, {5, 4, 3, 2, 1, 0}};
constexpr int kSplitA[3][4] = {{0, 1, 2, 5}, {0, 1, 5, 4}, {0, 4, 5, 3}};  // diagonal 1-5
constexpr int kSplitB[3][4] = {{0, 1, 2, 4}, {0, 4, 2, 5}, {0, 4, 5, 3}};  // diagonal 2-4

// The local tetrahedra for each (rotation, case), oriented on a reference prism once.
struct Table {
  int tet[6][2][3][4];
  Table() {
    // Positive VTK wedge: bottom normal (p1-p0)x(p2-p0) points away from the top.
    const Vec3 ref[6] = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 1}, {1, 0, 1}};
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 2; ++c)
        for (int t = 0; t < 3; ++t) {
          int* v = tet[r][c][t];
          for (int q = 0; q < 4; ++q) v[q] = kRotate[r][(c == 0 ? kSplitA : kSplitB)[t][q]];
          const double vol = dot(cross(ref[v[1]] - ref[v[0]], ref[v[2]] - ref[v[0]]),
                                 ref[v[3]] - ref[v[0]]);
          if (vol < 0) std::swap(v[1], v[2]);
        }
  }
};
}  // namespace

void split_prism(const int32_t ids[6], int32_t out[3][4]) {
  static const Table table;
  const int r = static_cast<int>(std::min_element(ids, ids + 6) - ids);
  const int* m = kRotate[r];
  const int c = std::min(ids[m[1]], ids[m[5]]) < std::min(ids[m[2]], ids[m[4]]) ? 0 : 1;
  for (int t = 0; t < 3; ++t)
    for (int q = 0; q < 4; ++q) out[t][q] = ids[table.tet[r][c][t][q]];
}

}  // namespace vob

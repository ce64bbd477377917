#include "datasets/generators/gap.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "datasets/generators/kuhn_block.h"
#include "datasets/generators/shuffle.h"
#include "harness/scene/input_error.h"

namespace vob {

CellMesh make_gap_mesh(const GapSpec& s) {
  CellMesh m;
  const int slabs = s.gaps + 1;
  const int base = s.nz / slabs, extra = s.nz % slabs;
  const int64_t layer_points = int64_t(s.nx + 1) * (s.ny + 1);
  m.points.reserve(layer_points * (s.nz + slabs));
  m.scalars.reserve(layer_points * (s.nz + slabs));
  const int64_t cells = int64_t(6) * s.nx * s.ny * s.nz;
  m.types.reserve(cells);
  m.offsets.reserve(cells + 1);
  m.conn.reserve(4 * cells);
  // Scalar: dense along the long axis, fading towards the sides and growing along z, from
  // the position in the unsliced block so that slicing changes no value.
  const double cx = 0.5 * s.nx, cy = 0.5 * s.ny;
  const double rmax = std::sqrt(cx * cx + cy * cy);
  int layer = 0;
  for (int slab = 0; slab < slabs; ++slab) {
    const int nzs = base + (slab < extra ? 1 : 0);
    BlockSpec b{s.nx, s.ny, nzs, s.offset + Vec3{0, 0, layer + slab * kGapWidth}, {1, 1, 1}};
    append_kuhn_block(m, b);
    for (int k = 0; k <= nzs; ++k)
      for (int j = 0; j <= s.ny; ++j)
        for (int i = 0; i <= s.nx; ++i) {
          const double r = std::hypot(i - cx, j - cy) / rmax;
          m.scalars.push_back((1.0 - 0.8 * r) * (0.4 + 0.6 * (layer + k) / s.nz));
        }
    layer += nzs;
  }
  return m;
}

Scene make_gap(Params& p) {
  GapSpec s;
  s.nx = p.get_int("nx", 50, 1, 1000);
  s.ny = p.get_int("ny", 50, 1, 1000);
  s.nz = p.get_int("nz", 100, 1, 2000);
  s.gaps = p.get_int("gaps", 0, 0, 95);
  if (s.gaps >= s.nz)
    throw InputError("gap", "parameter gaps", std::to_string(s.gaps) +
                                                  " gaps need nz > gaps (nz is " +
                                                  std::to_string(s.nz) + ")");
  // Connectivity offsets are int32: 4 ids per tetrahedron must stay below 2^31.
  if (24.0 * s.nx * s.ny * s.nz >= 2147483647.0)
    throw InputError("gap", "parameters nx ny nz", "more than 536 million tetrahedra");
  const int shuffle = read_shuffle_param(p);
  if (p.dry_run()) return {};  // parameters checked, nothing generated
  CellMesh m = make_gap_mesh(s);
  if (shuffle > 0) m = shuffle_numbering(m, static_cast<uint64_t>(shuffle));
  return Scene::from_mesh("gap", std::move(m), p.to_json());
}

}  // namespace vob

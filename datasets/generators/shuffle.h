// The `shuffle` parameter of the cell generators (helix, gap's Kuhn blocks): a seeded random
// renumbering of cells and points, so that generated meshes can be numbered the way meshers
// number theirs (in creation order, not in space order) and the cost of that shows.
#pragma once
#include <cstdint>

#include "harness/bench/params.h"
#include "harness/scene/cell_mesh.h"

namespace vob {

// Reads `shuffle` (0..2^31-1, default 0 = the generator's own numbering; else the seed).
int read_shuffle_param(Params& p);

// `mesh` with cells and points in a random order drawn from `seed` (SplitMix64 and a
// Fisher-Yates shuffle: the same on every platform). Cells keep their vertex order.
CellMesh shuffle_numbering(const CellMesh& mesh, uint64_t seed);

}  // namespace vob

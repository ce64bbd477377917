// The dataset registry: every built-in dataset with its parameters, and make_dataset, which
// generates and then validates (a generator bug is reported like bad input, never passed on).
#include "datasets/datasets.h"

#include "datasets/generators/cycles.h"
#include "datasets/generators/gap.h"
#include "datasets/generators/hard_meshes.h"
#include "datasets/generators/helix.h"
#include "datasets/generators/icosphere.h"
#include "datasets/generators/real_data.h"
#include "datasets/generators/touching_blocks.h"
#include "datasets/generators/view_cases.h"
#include "datasets/generators/volumes.h"
#include "datasets/generators/zoo.h"
#include "harness/bench/names.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
std::vector<DatasetInfo> build_registry() {
  using K = SceneKind;
  std::vector<DatasetInfo> r = {
      {"gap", K::Cells, "block of 6 tets per hex sliced into gaps+1 slabs (Cook et al. 5.2)",
       "nx=50 ny=50 nz=100 (1..1000, nz 1..2000): hexahedra per axis, 6 tets each; "
       "gaps=0 (0..95, < nz): empty slabs of width 0.5 across z; "
       "shuffle=0 (0..2^31-1): > 0 renumbers cells and points at random from that seed",
       false, make_gap, nullptr},
      {"helix", K::Cells, "solid green tube inside the bore of a hollow pink one, 0.001 apart (Cook et al. Fig. 8)",
       "cells=20000 (162*turns..50M, met within 5%): tetrahedra; turns=3 (1..20); "
       "faces=0 (0: near-isotropic cells; > 0: exterior faces, met with cells within 5%); "
       "shuffle=0 (0..2^31-1): > 0 renumbers cells and points at random from that seed", false,
       make_helix, nullptr},
      {"zoo", K::Cells, "six lat-long spheres of tets, pyramids, wedges, hexes (Cook et al. Fig. 14)",
       "scale=1 (1..10): resolution multiplier, cells = 7200*scale^3", false, make_zoo, nullptr},
      {"sphere", K::Triangles, "subdivided icosahedron", "subdiv=3 (0..8): 20*4^subdiv triangles",
       false, make_sphere, nullptr},
      {"spheres", K::Triangles, "three groups of three nested spheres (depth complexity 18)",
       "subdiv=2 (0..7): 9*20*4^subdiv triangles", false, make_spheres, nullptr},
      {"block", K::Voxels, "dense machined block with bores and a chamber (engine-like)",
       "nx=64 ny=64 nz=64 (2..512)", false, make_block_volume, nullptr},
      {"shells", K::Voxels, "solid ball in two concentric shells plus corner balls",
       "nx=64 ny=64 nz=64 (2..512)", false, make_shells_volume, nullptr},
      {"sparse", K::Voxels, "scattered soft balls and a thin helical wire: mostly empty",
       "nx=64 ny=64 nz=64 (2..512); blobs=40 (0..10000); seed=1", false, make_sparse_volume,
       nullptr},
      {"skull", K::Voxels, "CT skull, 64^3 floats (CGAL data skull_2.9.inr)",
       "threshold=0.5 (0..5): significance threshold", false, make_skull, nullptr},
      {"offset", K::Cells, "small helix (or gap block) with coordinates offset by 1e7",
       "shape=helix (helix|gap); offset=1e7 (-1e9..1e9)", true, make_offset, nullptr},
      {"slivers", K::Cells, "slab whose middle layer is near-flat sliver tetrahedra",
       "n=8 (1..200): slivers per side; flatness=1e-6 (1e-12..0.25): sliver half-height", true,
       make_slivers, nullptr},
      {"edge-on", K::Cells, "tet block seen in orthographic views exactly along the axes",
       "n=8 (1..100): hexahedra per side", true, make_edge_on, edge_on_views},
      {"eye-in-plane", K::Cells, "tet block seen from eyes lying in many face planes",
       "n=6 (4..100): hexahedra per side", true, make_eye_in_plane, eye_in_plane_views},
      {"eye-inside", K::Cells, "tet block seen from eyes inside it (one at a mesh vertex)",
       "n=6 (2..100): hexahedra per side", true, make_eye_inside, eye_inside_views},
      {"cycle", K::Cells, "ring of hexahedra whose MPVO face arrows form a directed cycle",
       "cells=6 (6..64); twist=30 (5..30 degrees)", true, make_cycle, cycle_views},
      {"cycle-sticks", K::Cells, "three interlocking sticks: the classic visibility cycle", "",
       true, make_cycle_sticks, cycle_sticks_views},
      {"tiny", K::Cells, "scattered tetrahedra too small to cover pixel centres",
       "count=2000 (1..2M); size=0.001 (1e-9..0.05): edge length in a unit cube; seed=1", true,
       make_tiny, nullptr},
      {"touching-conforming", K::Cells,
       "two stacked tet blocks touching face to face, interface nodes duplicated (conforming)",
       "n=6 (1..40): hexahedra per side (6 tets each), n/2 layers per block", true,
       make_touching_conforming, nullptr},
      {"touching-shifted", K::Cells, "two stacked tet blocks touching, the upper shifted by half a cell",
       "n=6 (1..40): hexahedra per side (6 tets each), n/2 layers per block", true,
       make_touching_shifted, nullptr},
      {"touching-rotated", K::Cells, "two stacked tet blocks touching, the upper rotated about the vertical",
       "n=6 (1..40): hexahedra per side (6 tets each), n/2 layers per block; angle=11 (-180..180): "
       "degrees",
       true, make_touching_rotated, nullptr},
      {"touching-overhang", K::Cells,
       "a finer tet block on a coarser one, its bottom partly over the top and partly over nothing",
       "n=6 (1..40): hexahedra per side (6 tets each), n/2 layers per block", true,
       make_touching_overhang, nullptr},
      {"touching-edge", K::Cells, "three non-conforming tet blocks touching face to face, meeting along an edge",
       "n=6 (1..40): hexahedra per side of the first block (6 tets each)", true, make_touching_edge,
       nullptr},
      {"touching-hex", K::Cells, "two stacked hexahedral blocks touching, the upper shifted by half a cell",
       "n=6 (1..40): hexahedra per side, n/2 layers per block", true, make_touching_hex, nullptr},
  };
  for (const RealModel& m : real_models()) {
    r.push_back({"surface-" + m.name, K::Triangles, "surface of " + m.summary + " (CGAL data)", "",
                 false, [m](Params& p) { return make_surface(m, p); }, nullptr});
    char quality[32];
    std::snprintf(quality, sizeof quality, "%g", m.quality);
    r.push_back({"tet-" + m.name, K::Cells, m.summary + " meshed by TetGen (cached)",
                 std::string("quality=") + quality +
                     " (1.05..100): TetGen radius-edge bound; maxvol=0 (0..1): largest "
                     "tetrahedron as a fraction of the bounding-box volume, 0 = no bound",
                 false, [m](Params& p) { return make_tet(m, p); }, nullptr});
  }
  return r;
}
}  // namespace

const std::vector<DatasetInfo>& dataset_registry() {
  static const std::vector<DatasetInfo> registry = build_registry();
  return registry;
}

const DatasetInfo& find_dataset(const std::string& name) {
  for (const auto& info : dataset_registry())
    if (info.name == name) return info;
  std::vector<std::string> names;
  for (const auto& info : dataset_registry()) names.push_back(info.name);
  throw InputError("--dataset", name, "unknown dataset (" + known_names_hint(name, names) + ")");
}

Scene make_dataset(const std::string& name, Params params) {
  const DatasetInfo& info = find_dataset(name);
  params.set_owner(name);
  Scene s = info.make(params);
  params.check_all_used();
  const std::string source = "dataset " + name;
  switch (s.kind()) {
    case SceneKind::Cells: validate_cell_mesh(s.mesh(), source); break;
    case SceneKind::Triangles: validate_triangle_soup(s.soup(), source); break;
    case SceneKind::Voxels: validate_voxel_grid(s.grid(), source); break;
  }
  return s;
}

void check_dataset_params(const std::string& name, Params params) {
  const DatasetInfo& info = find_dataset(name);
  params.set_owner(name);
  params.set_dry_run(true);
  info.make(params);
  params.check_all_used();
}

}  // namespace vob

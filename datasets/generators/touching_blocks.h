// Hard cases with touching volumes (hard_case = true): blocks that meet face to face without
// sharing vertices, as meshes exported per part or per material and non-conforming
// multi-block meshes are. Each block has its own copy of the interface nodes, so the
// touching faces are exterior faces, coplanar and at equal depth along every ray through
// them. The blocks' interiors are disjoint (each pair is separated by an axis plane), so a
// visibility order exists.
//
// A base block is n x n x n/2 unit hexahedra (Kuhn split into six tetrahedra, or kept as
// hexahedra); coordinates are multiples of 0.25 except where a rotation is asked for, so
// that the interfaces are exactly coplanar in doubles.
//   touching-conforming  a second block stacked on the first with the same grid: the
//                        interface triangles coincide pairwise.
//   touching-shifted     the upper block shifted by half a cell in x and y.
//   touching-rotated     the upper block rotated by `angle` degrees about the vertical axis
//                        through the centre (its bottom stays exactly at z = n/2).
//   touching-overhang    a finer upper block (half-unit cells) whose bottom covers part of
//                        the lower block's top and reaches beyond it.
//   touching-edge        three blocks meeting along one edge: B beside A (finer, x >= n),
//                        C on top of A (shifted by half a cell in y); B and C touch along
//                        the line x = n, z = n/2 only.
//   touching-hex         the shifted case with hexahedra (quadrilateral interface faces).
#pragma once
#include "harness/bench/params.h"
#include "harness/scene/scene.h"

namespace vob {

Scene make_touching_conforming(Params& p);  // n=6
Scene make_touching_shifted(Params& p);     // n=6
Scene make_touching_rotated(Params& p);     // n=6 angle=11
Scene make_touching_overhang(Params& p);    // n=6
Scene make_touching_edge(Params& p);        // n=6
Scene make_touching_hex(Params& p);         // n=6

}  // namespace vob

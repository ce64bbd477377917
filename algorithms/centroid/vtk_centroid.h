// Plugin `vtk-centroid`: VTK 9.1's vtkCellCenterDepthSort behind the Orderer API, the peer
// the radix centroid sort has to beat. VTK sorts cell centres (parametric centres, in
// float) by their depth along the view direction, the key `centroid:key=view` uses, with a
// quicksort that hands out sorted chunks through GetNextCells.
// Parameter chunk (cells per GetNextCells call) is declared in vtk_centroid_orderer_info().
// prepare: builds a vtkUnstructuredGrid from the CellMesh and lets VTK compute its cell
// centres (a first InitTraversal). order: points the vtkCamera at the view and collects all
// chunks. A heuristic, like `centroid`. VTK's camera needs no OpenGL context.
#pragma once
#include "harness/bench/registry.h"

namespace vob {
OrdererInfo vtk_centroid_orderer_info();
}

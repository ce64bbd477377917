// A vobench cell scene from a VTK unstructured grid (the volume cells, through the readers'
// own conversion, datasets/io/vtk_shared.h), and back. Tetrahedra that VTK hands over
// negatively oriented (vtkDataSetTriangleFilter makes them) are turned by swapping two
// vertices: the same cell, so ids and orders do not change.
#pragma once
#include <string>

#include <vtkSmartPointer.h>

#include "harness/scene/scene.h"

class vtkDataSet;
class vtkUnstructuredGrid;

namespace vob {

// InputError naming `source`, the cell and the reason for a grid vobench cannot order.
Scene scene_from_vtk(vtkDataSet* data, const std::string& source);

// The scene's cells as a VTK grid, the point scalars as "scalar" and every cell's own id as
// the cell array "vobench_cell_id" (it survives VTK's filters: the id mapping).
vtkSmartPointer<vtkUnstructuredGrid> grid_from_scene(const Scene& scene);

}  // namespace vob

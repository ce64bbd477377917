#include "vtk/vtk_scene.h"

#include <map>
#include <utility>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include "datasets/io/vtk_shared.h"
#include "harness/geometry/predicates.h"

namespace vob {

Scene scene_from_vtk(vtkDataSet* data, const std::string& source) {
  auto* ug = vtkUnstructuredGrid::SafeDownCast(data);
  if (!ug)
    throw InputError(source, "input", std::string("is a ") + (data ? data->GetClassName() : "null") +
                                          ", not a vtkUnstructuredGrid");
  std::map<std::string, size_t> skipped;
  CellMesh mesh = cells_from_unstructured(ug, source, skipped);
  for (size_t c = 0; c < mesh.num_cells(); ++c) {
    if (mesh.types[c] != CellType::Tetra) continue;
    int32_t* p = mesh.conn.data() + mesh.offsets[c];
    const auto& x = mesh.points;
    if (orient3d(x[p[0]], x[p[1]], x[p[2]], x[p[3]]) < 0) std::swap(p[0], p[1]);
  }
  validate_cell_mesh(mesh, source);
  return Scene::from_mesh(source, std::move(mesh));
}

vtkSmartPointer<vtkUnstructuredGrid> grid_from_scene(const Scene& scene) {
  const CellMesh& m = scene.mesh();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(m.num_points()));
  for (size_t i = 0; i < m.num_points(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), m.points[i].x, m.points[i].y, m.points[i].z);
  vtkNew<vtkDoubleArray> scalar;
  scalar->SetName("scalar");
  scalar->SetNumberOfTuples(static_cast<vtkIdType>(m.num_points()));
  for (size_t i = 0; i < m.num_points(); ++i) scalar->SetValue(static_cast<vtkIdType>(i), m.scalar(i));

  vtkNew<vtkCellArray> cells;
  vtkNew<vtkUnsignedCharArray> types;  // CellType values are VTK's codes
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("vobench_cell_id");
  for (size_t c = 0; c < m.num_cells(); ++c) {
    const int n = m.cell_size(c);
    cells->InsertNextCell(n);
    for (int k = 0; k < n; ++k) cells->InsertCellPoint(m.cell_points(c)[k]);
    types->InsertNextValue(static_cast<unsigned char>(m.types[c]));
    ids->InsertNextValue(static_cast<vtkIdType>(c));
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->SetCells(types, cells);
  grid->GetPointData()->SetScalars(scalar);
  grid->GetCellData()->AddArray(ids);
  return grid;
}

}  // namespace vob

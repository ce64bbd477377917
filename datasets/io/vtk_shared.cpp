#include "datasets/io/vtk_shared.h"

#include <vtkCellData.h>
#include <vtkCellTypes.h>
#include <vtkDataArray.h>
#include <vtkGenericCell.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

namespace vob {

vtkStandardNewMacro(CaptureWindow);
std::mutex capture_mutex;

vtkDataArray* pick_array(vtkDataSetAttributes* a) {
  if (!a) return nullptr;
  if (vtkDataArray* s = a->GetScalars()) return s;
  for (int i = 0; i < a->GetNumberOfArrays(); ++i)
    if (vtkDataArray* d = a->GetArray(i)) return d;
  return nullptr;
}

namespace {
// Dimension of a VTK cell type as VTK itself defines it (-1 for a code VTK does not know).
int cell_dimension(int type) {
  const char* cls = vtkCellTypes::GetClassNameFromTypeId(type);
  if (!cls || std::string(cls) == "UnknownClass") return -1;
  vtkSmartPointer<vtkCell> cell;
  cell.TakeReference(vtkGenericCell::InstantiateCell(type));
  return cell ? cell->GetCellDimension() : -1;
}

std::string type_label(int type) {
  const char* cls = vtkCellTypes::GetClassNameFromTypeId(type);
  return "type " + std::to_string(type) + " (" + (cls ? cls : "unknown") + ")";
}

}  // namespace

CellMesh cells_from_unstructured(vtkUnstructuredGrid* ug, const std::string& path,
                                 std::map<std::string, size_t>& skipped, vtkDataArray* scalars,
                                 bool pick, bool allow_empty) {
  CellMesh m;
  const vtkIdType np = ug->GetNumberOfPoints(), nc = ug->GetNumberOfCells();
  if (np >= (vtkIdType(1) << 31)) throw InputError(path, "points", "more than 2^31 points");
  m.points.resize(np);
  for (vtkIdType i = 0; i < np; ++i) {
    double p[3];
    ug->GetPoint(i, p);
    m.points[i] = {p[0], p[1], p[2]};
  }
  if (vtkDataArray* s = scalars ? scalars : pick ? pick_array(ug->GetPointData()) : nullptr) {
    if (s->GetNumberOfTuples() != np)
      throw InputError(path, std::string("point data ") + (s->GetName() ? s->GetName() : "?"),
                       "has " + std::to_string(s->GetNumberOfTuples()) + " values for " +
                           std::to_string(np) + " points");
    m.scalars.resize(np);
    for (vtkIdType i = 0; i < np; ++i) m.scalars[i] = s->GetComponent(i, 0);
  }
  std::map<int, int> dimension;  // per type code, asked of VTK once
  for (vtkIdType c = 0; c < nc; ++c) {
    const int type = ug->GetCellType(c);
    if (!is_supported_cell_code(type)) {
      auto [it, fresh] = dimension.try_emplace(type, 0);
      if (fresh) it->second = cell_dimension(type);
      if (it->second < 0)
        throw InputError(path, "cell " + std::to_string(c), type_label(type) + " is not a VTK cell type");
      if (it->second < 3) {
        const char* cls = vtkCellTypes::GetClassNameFromTypeId(type);
        ++skipped[cls ? cls : type_label(type)];
        continue;
      }
      throw InputError(path, "cell " + std::to_string(c),
                       type_label(type) +
                           " is not supported (volume cells must be linear tetra, pyramid, wedge or hexahedron)");
    }
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    ug->GetCellPoints(c, n, ids);
    const auto t = static_cast<CellType>(type);
    if (n != cell_vertex_count(t))
      throw InputError(path, "cell " + std::to_string(c),
                       std::string(cell_type_name(t)) + " with " + std::to_string(n) + " points");
    for (vtkIdType q = 0; q < n; ++q) {
      if (ids[q] < 0 || ids[q] >= np)
        throw InputError(path, "cell " + std::to_string(c),
                         "point index " + std::to_string(ids[q]) + " is out of range");
      m.conn.push_back(static_cast<int32_t>(ids[q]));
    }
    m.types.push_back(t);
    m.offsets.push_back(static_cast<int32_t>(m.conn.size()));
  }
  if (m.num_cells() == 0 && !allow_empty)
    throw InputError(path, "cells", nc == 0 ? "the file has no cells"
                                            : "none of the " + std::to_string(nc) +
                                                  " cells is a volume cell (tetra, pyramid, wedge, hexahedron)");
  return m;
}

// "skipped 40 cells of lower dimension (vtkLine 12, vtkTriangle 28)", or "" for none.
std::string skipped_note(const std::map<std::string, size_t>& skipped) {
  size_t total = 0;
  std::string list;
  for (const auto& [name, n] : skipped) {
    total += n;
    list += (list.empty() ? "" : ", ") + name + " " + std::to_string(n);
  }
  if (total == 0) return "";
  return "read the volume cells only; skipped " + std::to_string(total) +
         " cells of lower dimension (" + list + ")";
}

}  // namespace vob

#include "datasets/io/surface_reader.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>

#include "datasets/io/file_util.h"
#include "datasets/io/vtk_shared.h"

namespace vob {

namespace {
template <class Reader>
vtkSmartPointer<vtkPolyData> read_with(const std::string& path) {
  vtkNew<Reader> r;
  r->SetFileName(path.c_str());
  run_checked(r.Get(), path, "file");
  if (!r->GetOutput()) throw InputError(path, "file", "VTK read no surface");
  return r->GetOutput();
}
}  // namespace

TriangleSoup read_surface(const std::string& path, std::string* note) {
  const std::string ext = file_extension(path);
  vtkSmartPointer<vtkPolyData> pd;
  if (ext == ".stl") {
    pd = read_with<vtkSTLReader>(path);
  } else if (ext == ".ply") {
    vtkNew<vtkPLYReader> probe;
    if (!probe->CanReadFile(path.c_str())) throw InputError(path, "header", "is not a PLY file (no 'ply' magic line)");
    pd = read_with<vtkPLYReader>(path);
  } else if (ext == ".obj") {
    pd = read_with<vtkOBJReader>(path);
  } else {
    throw InputError(path, "file", "not a surface extension (.stl .ply .obj)");
  }
  if (pd->GetNumberOfStrips() > 0)
    throw InputError(path, "triangle strips", "are not supported (give triangles or polygons)");
  TriangleSoup s;
  const vtkIdType np = pd->GetNumberOfPoints();
  if (np >= (vtkIdType(1) << 31)) throw InputError(path, "points", "more than 2^31 points");
  s.points.resize(np);
  for (vtkIdType i = 0; i < np; ++i) {
    double p[3];
    pd->GetPoint(i, p);
    s.points[i] = {p[0], p[1], p[2]};
  }
  vtkCellArray* polys = pd->GetPolys();
  const auto iter = vtk::TakeSmartPointer(polys->NewIterator());
  vtkIdType face = 0;
  for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell(), ++face) {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    iter->GetCurrentCell(n, ids);
    if (n < 3) throw InputError(path, "face " + std::to_string(face), "has " + std::to_string(n) + " vertices");
    for (vtkIdType q = 0; q < n; ++q)
      if (ids[q] < 0 || ids[q] >= np)
        throw InputError(path, "face " + std::to_string(face), "vertex index " + std::to_string(ids[q]) + " is out of range");
    for (vtkIdType q = 1; q + 1 < n; ++q)
      s.tris.push_back({int32_t(ids[0]), int32_t(ids[q]), int32_t(ids[q + 1])});
  }
  if (s.tris.empty()) throw InputError(path, "faces", "the file has no triangles or polygons");
  const vtkIdType other = pd->GetNumberOfVerts() + pd->GetNumberOfLines();
  if (note)
    *note = other == 0 ? "" : "read the faces only; skipped " + std::to_string(other) + " vertices and lines";
  return s;
}

}  // namespace vob

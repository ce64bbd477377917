#include "datasets/io/vtk_io.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <map>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkGenericDataObjectReader.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkStructuredPoints.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridWriter.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "datasets/io/file_util.h"
#include "datasets/io/vtk_prescan.h"
#include "datasets/io/vtk_shared.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
VoxelGrid from_image(vtkImageData* img, const std::string& path) {
  VoxelGrid g;
  int dims[3];
  double sp[3], org[3];
  img->GetDimensions(dims);
  img->GetSpacing(sp);
  img->GetOrigin(org);
  int ext[6];
  img->GetExtent(ext);
  vtkDataArray* a = pick_array(img->GetPointData());
  Vec3 origin{org[0] + ext[0] * sp[0], org[1] + ext[2] * sp[1], org[2] + ext[4] * sp[2]};
  if (!a) {  // cell data: each image cell is one voxel, centred half a step in
    a = pick_array(img->GetCellData());
    if (!a) throw InputError(path, "data", "the image has no point or cell data array");
    for (int i = 0; i < 3; ++i) dims[i] = std::max(1, dims[i] - 1);
    origin = origin + Vec3{sp[0], sp[1], sp[2]} * 0.5;
  }
  // A voxel grid is axis-aligned: an image VTK would draw rotated or mirrored by its
  // Direction matrix is refused, not read in the wrong place.
  if (vtkMatrix3x3* d = img->GetDirectionMatrix(); d && !d->IsIdentity()) {
    std::string m;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m += (m.empty() ? "" : " ") + short_number(d->GetElement(r, c));
    throw InputError(path, "Direction", "'" + m + "' is not the identity (rotated or mirrored images are not supported)");
  }
  // One value per voxel decides which voxels are drawn: a vector array is not read as its
  // first component (INRIMAGE's VDIM > 1 is refused alike).
  if (a->GetNumberOfComponents() != 1)
    throw InputError(path, std::string("array ") + (a->GetName() ? a->GetName() : "?"),
                     "has " + std::to_string(a->GetNumberOfComponents()) +
                         " components per voxel (a voxel volume needs one scalar)");
  g.dims = {dims[0], dims[1], dims[2]};
  g.spacing = {sp[0], sp[1], sp[2]};
  g.origin = origin;
  if (a->GetNumberOfTuples() != static_cast<vtkIdType>(g.num_voxels()))
    throw InputError(path, std::string("array ") + (a->GetName() ? a->GetName() : "?"),
                     "has " + std::to_string(a->GetNumberOfTuples()) + " values for " +
                         std::to_string(g.num_voxels()) + " voxels");
  g.values.resize(g.num_voxels());
  for (size_t i = 0; i < g.values.size(); ++i) {
    const double v = a->GetComponent(i, 0);
    g.values[i] = static_cast<float>(v);
    if (std::isfinite(v) && !std::isfinite(g.values[i]))  // not "not finite": the file's value is
      throw InputError(path, "voxel " + std::to_string(i), "value " + short_number(v) + " does not fit a 32-bit float");
  }
  if (vtkFieldData* fd = img->GetFieldData())
    if (vtkDataArray* t = fd->GetArray("vobench_threshold"); t && t->GetNumberOfTuples() > 0) {
      const double v = t->GetComponent(0, 0);
      g.threshold = static_cast<float>(v);
      if (!std::isfinite(g.threshold))  // NaN would make no voxel significant, and the check pass on nothing
        throw InputError(path, "field vobench_threshold", "'" + short_number(v) + "' is not a finite 32-bit float");
    }
  return g;
}

std::string stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

vtkSmartPointer<vtkUnstructuredGrid> to_unstructured(const CellMesh& m) {
  auto ug = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  pts->SetNumberOfPoints(m.num_points());
  for (size_t i = 0; i < m.num_points(); ++i) pts->SetPoint(i, m.points[i].x, m.points[i].y, m.points[i].z);
  ug->SetPoints(pts);
  ug->Allocate(m.num_cells());
  for (size_t c = 0; c < m.num_cells(); ++c) {
    vtkIdType ids[8];
    for (int q = 0; q < m.cell_size(c); ++q) ids[q] = m.cell_points(c)[q];
    ug->InsertNextCell(static_cast<int>(m.types[c]), m.cell_size(c), ids);
  }
  if (!m.scalars.empty()) {
    vtkNew<vtkDoubleArray> s;
    s->SetName("scalar");
    s->SetNumberOfTuples(m.num_points());
    for (size_t i = 0; i < m.num_points(); ++i) s->SetValue(i, m.scalars[i]);
    ug->GetPointData()->SetScalars(s);
  }
  return ug;
}

// The piece files a .pvtu names (<Piece Source="..."/>), relative to its folder.
std::vector<std::string> pvtu_pieces(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  const std::string t = text.str();
  static const std::regex piece("<Piece[^>]*\\sSource=\"([^\"]*)\"");
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(t.begin(), t.end(), piece); it != std::sregex_iterator(); ++it)
    out.push_back((std::filesystem::path(path).parent_path() / (*it)[1].str()).string());
  if (out.empty()) throw InputError(path, "Piece", "the file names no piece (<Piece Source=\"...\"/>)");
  return out;
}

// Pieces repeat the points on their shared borders: points at bit-identical coordinates
// become one (the first), so faces between pieces are shared faces, as in one .vtu.
void merge_piece_points(CellMesh& m) {
  std::map<std::tuple<double, double, double>, int32_t> first;
  std::vector<int32_t> to(m.points.size());
  std::vector<Vec3> pts;
  std::vector<double> sc;
  for (size_t i = 0; i < m.points.size(); ++i) {
    const Vec3& p = m.points[i];
    const auto [it, fresh] = first.try_emplace({p.x, p.y, p.z}, int32_t(pts.size()));
    if (fresh) {
      pts.push_back(p);
      if (!m.scalars.empty()) sc.push_back(m.scalars[i]);
    }
    to[i] = it->second;
  }
  for (int32_t& c : m.conn) c = to[c];
  m.points = std::move(pts);
  m.scalars = std::move(sc);
}

template <class Writer>
void write_with(Writer* w, const std::string& path) {
  write_atomically(path, [&](const std::string& tmp) {
    w->SetFileName(tmp.c_str());
    ScopedCapture capture;
    capture.forward(w);
    if (w->Write() != 1 || !capture.first().empty())
      throw InputError(path, "file", "VTK could not write it" +
                                         (capture.first().empty() ? "" : ": " + capture.first()));
  });
}
}  // namespace

Scene read_vtk_file(const std::string& path, std::string* note) {
  require_readable_file(path);
  const std::string ext = file_extension(path);
  const nlohmann::json params{{"input", path}};
  std::map<std::string, size_t> skipped;
  const auto noted = [&](Scene s) {
    if (note) *note = skipped_note(skipped);
    return s;
  };
  if (ext == ".vtu") prescan_vtk_xml(path, "UnstructuredGrid");
  if (ext == ".vti") prescan_vtk_xml(path, "ImageData");
  if (ext == ".vtk") prescan_vtk_legacy(path);
  if (ext == ".vtu") {
    vtkNew<vtkXMLUnstructuredGridReader> r;
    r->SetFileName(path.c_str());
    run_checked(r.Get(), path, "file");
    if (!r->GetOutput()) throw InputError(path, "file", "VTK read no unstructured grid");
    return noted(Scene::from_mesh(stem(path), cells_from_unstructured(r->GetOutput(), path, skipped), params));
  }
  if (ext == ".pvtu") {
    prescan_vtk_xml(path, "PUnstructuredGrid");
    for (const std::string& piece : pvtu_pieces(path)) {
      try {  // the line names the .pvtu and its piece
        require_readable_file(piece);
        prescan_vtk_xml(piece, "UnstructuredGrid");
      } catch (const InputError& e) {
        throw InputError(path + ": piece " + e.what());
      }
    }
    vtkNew<vtkXMLPUnstructuredGridReader> r;
    r->SetFileName(path.c_str());
    run_checked(r.Get(), path, "file");
    if (!r->GetOutput()) throw InputError(path, "file", "VTK read no unstructured grid");
    CellMesh m = cells_from_unstructured(r->GetOutput(), path, skipped);
    merge_piece_points(m);
    return noted(Scene::from_mesh(stem(path), std::move(m), params));
  }
  if (ext == ".vti") {
    vtkNew<vtkXMLImageDataReader> r;
    r->SetFileName(path.c_str());
    run_checked(r.Get(), path, "file");
    if (!r->GetOutput()) throw InputError(path, "file", "VTK read no image data");
    return Scene::from_grid(stem(path), from_image(r->GetOutput(), path), params);
  }
  if (ext == ".vtk") {
    vtkNew<vtkGenericDataObjectReader> r;
    r->SetFileName(path.c_str());
    run_checked(r.Get(), path, "file");
    if (r->GetErrorCode() != 0)
      throw InputError(path, "file", std::string("VTK: ") + vtkErrorCode::GetStringFromErrorCode(r->GetErrorCode()));
    if (auto* ug = vtkUnstructuredGrid::SafeDownCast(r->GetOutput()))
      return noted(Scene::from_mesh(stem(path), cells_from_unstructured(ug, path, skipped), params));
    if (auto* img = vtkImageData::SafeDownCast(r->GetOutput()))
      return Scene::from_grid(stem(path), from_image(img, path), params);
    const char* what = r->GetOutput() ? r->GetOutput()->GetClassName() : "nothing";
    throw InputError(path, "dataset", std::string("legacy VTK ") + what +
                                          " is not supported (unstructured grid or structured points only)");
  }
  throw InputError(path, "file", "not a VTK file extension (.vtu .pvtu .vtk .vti)");
}

void write_vtu(const CellMesh& m, const std::string& path) { write_vtu(m, path, {}); }

void write_vtu(const CellMesh& m, const std::string& path, const CellArrays& cell_arrays) {
  vtkNew<vtkXMLUnstructuredGridWriter> w;
  auto ug = to_unstructured(m);
  for (const auto& [name, values] : cell_arrays) {
    if (values.size() != m.num_cells())
      throw InputError(path, "cell array " + name, "has " + std::to_string(values.size()) + " values for " +
                                                       std::to_string(m.num_cells()) + " cells");
    vtkNew<vtkTypeInt64Array> a;
    a->SetName(name.c_str());
    a->SetNumberOfTuples(vtkIdType(values.size()));
    for (size_t i = 0; i < values.size(); ++i) a->SetValue(vtkIdType(i), values[i]);
    ug->GetCellData()->AddArray(a);
  }
  w->SetInputData(ug);
  w->SetDataModeToAppended();
  w->EncodeAppendedDataOff();  // raw binary: doubles round-trip exactly
  write_with(w.Get(), path);
}

void write_vtk_legacy(const CellMesh& m, const std::string& path) {
  vtkNew<vtkUnstructuredGridWriter> w;
  auto ug = to_unstructured(m);
  w->SetInputData(ug);
  w->SetFileTypeToBinary();
  write_with(w.Get(), path);
}

void write_mask_vti(const std::vector<uint8_t>& mask, int width, int height, const std::string& name,
                    const std::string& path) {
  if (mask.size() != size_t(width) * size_t(height))
    throw InputError(path, "image", "mask of " + std::to_string(mask.size()) + " pixels is not " +
                                        std::to_string(width) + "x" + std::to_string(height));
  vtkNew<vtkImageData> img;
  img->SetDimensions(width, height, 1);
  vtkNew<vtkUnsignedCharArray> v;
  v->SetName(name.c_str());
  v->SetNumberOfTuples(vtkIdType(mask.size()));
  for (size_t i = 0; i < mask.size(); ++i) v->SetValue(vtkIdType(i), mask[i]);
  img->GetPointData()->SetScalars(v);
  vtkNew<vtkXMLImageDataWriter> w;
  w->SetInputData(img);
  write_with(w.Get(), path);
}

void write_vti(const VoxelGrid& g, const std::string& path) {
  vtkNew<vtkImageData> img;
  img->SetDimensions(g.dims[0], g.dims[1], g.dims[2]);
  img->SetSpacing(g.spacing.x, g.spacing.y, g.spacing.z);
  img->SetOrigin(g.origin.x, g.origin.y, g.origin.z);
  vtkNew<vtkFloatArray> v;
  v->SetName("values");
  v->SetNumberOfTuples(g.num_voxels());
  for (size_t i = 0; i < g.num_voxels(); ++i) v->SetValue(i, g.values[i]);
  img->GetPointData()->SetScalars(v);
  vtkNew<vtkFloatArray> t;
  t->SetName("vobench_threshold");
  t->InsertNextValue(g.threshold);
  img->GetFieldData()->AddArray(t);
  vtkNew<vtkXMLImageDataWriter> w;
  w->SetInputData(img);
  w->SetDataModeToAppended();
  w->EncodeAppendedDataOff();
  write_with(w.Get(), path);
}

}  // namespace vob

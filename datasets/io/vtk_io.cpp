#include "datasets/io/vtk_io.h"

#include <filesystem>
#include <map>
#include <mutex>

#include <vtkCallbackCommand.h>
#include <vtkCellData.h>
#include <vtkCellTypes.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkGenericCell.h>
#include <vtkGenericDataObjectReader.h>
#include <vtkImageData.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkStructuredPoints.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridWriter.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "datasets/io/file_util.h"
#include "datasets/io/vtk_prescan.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
// VTK reports problems through the global output window (and, when an algorithm has an
// observer, as ErrorEvent on it). While a file is read or written, a capturing window
// collects them instead of printing, and the first error becomes one InputError line.
class CaptureWindow : public vtkOutputWindow {
 public:
  static CaptureWindow* New();
  vtkTypeMacro(CaptureWindow, vtkOutputWindow);
  void DisplayText(const char* t) override { keep(t); }
  void DisplayErrorText(const char* t) override { keep(t); }
  // A warning on reading is a problem with the file too (VTK reports a short binary read
  // as one), so it is kept like an error.
  void DisplayWarningText(const char* t) override { keep(t); }
  void DisplayGenericWarningText(const char* t) override { keep(t); }
  void DisplayDebugText(const char*) override {}
  // VTK messages read "ERROR: In file, line N\nClass (0x...): text" (or "Warning: In ..."):
  // keep the text.
  void keep(const char* t) {
    if (!first.empty() || !t) return;
    std::string msg = t;
    std::string best;
    size_t start = 0;
    while (start <= msg.size()) {
      size_t end = msg.find('\n', start);
      if (end == std::string::npos) end = msg.size();
      std::string line = msg.substr(start, end - start);
      start = end + 1;
      if (line.empty() || line.rfind("ERROR: In ", 0) == 0 || line.rfind("Warning: In ", 0) == 0 ||
          line.rfind("Generic Warning: In ", 0) == 0)
        continue;
      if (const auto p = line.find("): "); p != std::string::npos && line.find(" (0x") < p)
        line = line.substr(p + 3);
      best = line;
      break;
    }
    first = best.empty() ? msg : best;
  }
  std::string first;
};
vtkStandardNewMacro(CaptureWindow);

// The output window and the logger level are process-wide: one capture at a time.
std::mutex capture_mutex;

class ScopedCapture {
 public:
  // VTK also logs errors to stderr through vtkLogger; that is muted meanwhile. vtkLogger
  // has no getter for the stderr level: the cutoff equals it unless log callbacks exist.
  ScopedCapture()
      : lock_(capture_mutex),
        prev_(vtkOutputWindow::GetInstance()),
        level_(vtkLogger::GetCurrentVerbosityCutoff()) {
    vtkOutputWindow::SetInstance(win_);
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  ~ScopedCapture() {
    if (algo_) {  // the window dies with us; so must the links
      algo_->RemoveObserver(tag_);
      algo_->RemoveObserver(warning_tag_);
    }
    vtkLogger::SetStderrVerbosity(level_);
    vtkOutputWindow::SetInstance(prev_);
  }
  void forward(vtkObject* algo) {
    cb_->SetCallback([](vtkObject*, unsigned long, void* self, void* data) {
      static_cast<CaptureWindow*>(self)->keep(static_cast<const char*>(data));
    });
    cb_->SetClientData(win_.Get());
    algo_ = algo;
    tag_ = algo->AddObserver(vtkCommand::ErrorEvent, cb_);
    warning_tag_ = algo->AddObserver(vtkCommand::WarningEvent, cb_);
  }
  const std::string& first() const { return win_->first; }

 private:
  std::lock_guard<std::mutex> lock_;
  vtkSmartPointer<vtkOutputWindow> prev_;
  vtkLogger::Verbosity level_;
  vtkNew<CaptureWindow> win_;
  vtkNew<vtkCallbackCommand> cb_;
  vtkObject* algo_ = nullptr;
  unsigned long tag_ = 0, warning_tag_ = 0;
};

template <class Algo>
void run_checked(Algo* algo, const std::string& path, const char* what) {
  ScopedCapture capture;
  capture.forward(algo);
  algo->Update();
  if (!capture.first().empty()) throw InputError(path, what, "VTK: " + capture.first());
}

vtkDataArray* pick_array(vtkDataSetAttributes* a) {
  if (!a) return nullptr;
  if (vtkDataArray* s = a->GetScalars()) return s;
  for (int i = 0; i < a->GetNumberOfArrays(); ++i)
    if (vtkDataArray* d = a->GetArray(i)) return d;
  return nullptr;
}

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

// The volume cells of `ug`. Vertices, lines and surface cells beside them (gmsh writes its
// boundary and edge elements into the same file) are skipped and counted in `skipped` by
// class name; a volume cell other than the four linear types is refused. Points are kept
// as numbered in the file, so point data stays aligned with them.
CellMesh from_unstructured(vtkUnstructuredGrid* ug, const std::string& path,
                           std::map<std::string, size_t>& skipped) {
  CellMesh m;
  const vtkIdType np = ug->GetNumberOfPoints(), nc = ug->GetNumberOfCells();
  if (np >= (vtkIdType(1) << 31)) throw InputError(path, "points", "more than 2^31 points");
  m.points.resize(np);
  for (vtkIdType i = 0; i < np; ++i) {
    double p[3];
    ug->GetPoint(i, p);
    m.points[i] = {p[0], p[1], p[2]};
  }
  if (vtkDataArray* s = pick_array(ug->GetPointData())) {
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
  if (m.num_cells() == 0)
    throw InputError(path, "cells", nc == 0 ? "the file has no cells"
                                            : "none of the " + std::to_string(nc) +
                                                  " cells is a volume cell (tetra, pyramid, wedge, hexahedron)");
  return m;
}

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
  g.dims = {dims[0], dims[1], dims[2]};
  g.spacing = {sp[0], sp[1], sp[2]};
  g.origin = origin;
  if (a->GetNumberOfTuples() != static_cast<vtkIdType>(g.num_voxels()))
    throw InputError(path, std::string("array ") + (a->GetName() ? a->GetName() : "?"),
                     "has " + std::to_string(a->GetNumberOfTuples()) + " values for " +
                         std::to_string(g.num_voxels()) + " voxels");
  g.values.resize(g.num_voxels());
  for (size_t i = 0; i < g.values.size(); ++i) g.values[i] = static_cast<float>(a->GetComponent(i, 0));
  if (vtkFieldData* fd = img->GetFieldData())
    if (vtkDataArray* t = fd->GetArray("vobench_threshold"); t && t->GetNumberOfTuples() > 0)
      g.threshold = static_cast<float>(t->GetComponent(0, 0));
  return g;
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
    return noted(Scene::from_mesh(stem(path), from_unstructured(r->GetOutput(), path, skipped), params));
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
      return noted(Scene::from_mesh(stem(path), from_unstructured(ug, path, skipped), params));
    if (auto* img = vtkImageData::SafeDownCast(r->GetOutput()))
      return Scene::from_grid(stem(path), from_image(img, path), params);
    const char* what = r->GetOutput() ? r->GetOutput()->GetClassName() : "nothing";
    throw InputError(path, "dataset", std::string("legacy VTK ") + what +
                                          " is not supported (unstructured grid or structured points only)");
  }
  throw InputError(path, "file", "not a VTK file extension (.vtu .vtk .vti)");
}

void write_vtu(const CellMesh& m, const std::string& path) {
  vtkNew<vtkXMLUnstructuredGridWriter> w;
  auto ug = to_unstructured(m);
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

#include "datasets/io/exodus_reader.h"

#include <vtkCompositeDataIterator.h>
#include <vtkDataArray.h>
#include <vtkExodusIIReader.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <fstream>

#include "datasets/io/netcdf_prescan.h"
#include "datasets/io/vtk_shared.h"

namespace vob {

namespace {
// The Exodus and netCDF libraries under VTK print their errors straight to stderr; while a
// file is read, stderr goes to /dev/null (VTK's own messages are captured as usual).
class QuietStderr {
 public:
  QuietStderr() {
    std::fflush(stderr);
    saved_ = dup(2);
    const int null = open("/dev/null", O_WRONLY);
    if (saved_ >= 0 && null >= 0) dup2(null, 2);
    if (null >= 0) close(null);
  }
  ~QuietStderr() {
    std::fflush(stderr);
    if (saved_ >= 0) {
      dup2(saved_, 2);
      close(saved_);
    }
  }

 private:
  int saved_ = -1;
};

// Exodus II files are netCDF (classic "CDF\1", 64-bit "CDF\2", CDF-5 "CDF\5") or netCDF-4
// (HDF5, "\x89HDF").
void check_magic(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char m[4] = {};
  in.read(m, 4);
  const bool cdf = std::memcmp(m, "CDF", 3) == 0 && (m[3] == 1 || m[3] == 2 || m[3] == 5);
  const bool hdf = std::memcmp(m, "\x89HDF", 4) == 0;
  if (!cdf && !hdf) throw InputError(path, "header", "is not a netCDF or HDF5 file (not Exodus II)");
  if (cdf) prescan_netcdf_classic(path);
}
}  // namespace

CellMesh read_exodus(const std::string& path, const std::string& variable, std::string* note) {
  check_magic(path);
  QuietStderr quiet;
  vtkNew<vtkExodusIIReader> r;
  {
    ScopedCapture capture;
    if (!r->CanReadFile(path.c_str()))
      throw InputError(path, "file", "is not an Exodus II file VTK can read" +
                                         (capture.first().empty() ? "" : ": " + capture.first()));
  }
  r->SetFileName(path.c_str());
  {
    ScopedCapture capture;
    capture.forward(r.Get());
    r->UpdateInformation();
    if (!capture.first().empty()) throw InputError(path, "file", "VTK: " + capture.first());
  }
  // Every block, every node in the file's numbering, no generated id arrays.
  r->SetAllArrayStatus(vtkExodusIIReader::ELEM_BLOCK, 1);
  r->SetSqueezePoints(false);
  r->SetGenerateObjectIdCellArray(0);
  r->SetGenerateGlobalElementIdArray(0);
  r->SetGenerateGlobalNodeIdArray(0);
  r->SetGenerateImplicitElementIdArray(0);
  r->SetGenerateImplicitNodeIdArray(0);
  r->SetTimeStep(0);
  std::string chosen = variable;
  const int nvars = r->GetNumberOfPointResultArrays();
  if (chosen.empty() && nvars > 0) chosen = r->GetPointResultArrayName(0);
  if (!chosen.empty()) {
    bool found = false;
    std::string names;
    for (int i = 0; i < nvars; ++i) {
      const std::string n = r->GetPointResultArrayName(i);
      found = found || n == chosen;
      names += (names.empty() ? "" : ", ") + n;
    }
    if (!found)
      throw InputError(path, "nodal variable '" + chosen + "'",
                       "is not in the file (it has: " + (names.empty() ? std::string("none") : names) + ")");
    r->SetPointResultArrayStatus(chosen.c_str(), 1);
  }
  run_checked(r.Get(), path, "file");
  vtkMultiBlockDataSet* out = r->GetOutput();
  if (!out) throw InputError(path, "file", "VTK read no element blocks");

  CellMesh m;
  std::map<std::string, size_t> skipped;
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(out->NewIterator());
  size_t blocks = 0;
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem()) {
    auto* ug = vtkUnstructuredGrid::SafeDownCast(it->GetCurrentDataObject());
    if (!ug) continue;
    ++blocks;
    vtkDataArray* s = chosen.empty() ? nullptr : ug->GetPointData()->GetArray(chosen.c_str());
    if (!chosen.empty() && !s)
      throw InputError(path, "nodal variable '" + chosen + "'", "VTK read no values at time step 0");
    CellMesh b = cells_from_unstructured(ug, path, skipped, s, false, true);
    if (b.num_cells() == 0) continue;
    if (m.points.empty()) {
      m.points = std::move(b.points);
      m.scalars = std::move(b.scalars);
    } else if (b.points.size() != m.points.size()) {
      throw InputError(path, "element blocks", "blocks do not share one node numbering");
    }
    const int32_t base = int32_t(m.conn.size());
    for (const int32_t p : b.conn) m.conn.push_back(p);
    for (size_t c = 0; c < b.num_cells(); ++c) {
      m.types.push_back(b.types[c]);
      m.offsets.push_back(base + b.offsets[c + 1]);
    }
  }
  if (m.num_cells() == 0)
    throw InputError(path, "element blocks", blocks == 0 ? "the file has no element blocks"
                                                         : "no block holds volume cells (tetra, pyramid, wedge, hexahedron)");
  if (note) *note = skipped_note(skipped);
  return m;
}

}  // namespace vob

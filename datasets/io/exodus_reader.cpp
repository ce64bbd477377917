#include "datasets/io/exodus_reader.h"

#include <vtkCompositeDataIterator.h>
#include <vtkDataArray.h>
#include <vtkExodusIIReader.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtk_exodusII.h>

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <regex>
#include <vector>

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

// The Exodus library's last error, for a message.
std::string exodus_error() {
  const char *msg = nullptr, *func = nullptr;
  int code = 0;
  ex_get_err(&msg, &func, &code);
  if (!msg || !*msg) return "error " + std::to_string(code);
  // Its messages end with the library's own file handle ("... in file id 65536"): dropped.
  std::string m = std::regex_replace(std::string(msg), std::regex(" (in|for) file id:? -?[0-9]+"), "");
  return std::regex_replace(m, std::regex(" +"), " ");
}

// Every block's and set's parameters read through the Exodus library before VTK's reader
// asks for them: the reader does not look at the library's status, and one block whose
// parameters fail (a renamed dimension or "elem_type" attribute: one changed byte) left
// its sorted block list shorter than its block count (SIGSEGV in
// vtkExodusIIReaderPrivate::GetSortedObjectInfo). Call with stderr quieted.
void check_exodus_objects(const std::string& path) {
  int cpu_word = 8, io_word = 0;
  float version = 0;
  const int id = ex_open(path.c_str(), EX_READ, &cpu_word, &io_word, &version);
  if (id < 0) throw InputError(path, "file", "the Exodus II library cannot open it: " + exodus_error());
  struct Close {
    int id;
    ~Close() { ex_close(id); }
  } close{id};
  ex_set_int64_status(id, EX_ALL_INT64_API);
  ex_init_params init;
  if (ex_get_init_ext(id, &init) < 0)
    throw InputError(path, "header", "the Exodus II library cannot read its sizes: " + exodus_error());
  struct Kind {
    ex_entity_type type;
    ex_inquiry count;
    const char* name;
    bool block;
  };
  const Kind kinds[] = {
      {EX_ELEM_BLOCK, EX_INQ_ELEM_BLK, "element block", true}, {EX_EDGE_BLOCK, EX_INQ_EDGE_BLK, "edge block", true},
      {EX_FACE_BLOCK, EX_INQ_FACE_BLK, "face block", true},    {EX_NODE_SET, EX_INQ_NODE_SETS, "node set", false},
      {EX_EDGE_SET, EX_INQ_EDGE_SETS, "edge set", false},      {EX_FACE_SET, EX_INQ_FACE_SETS, "face set", false},
      {EX_SIDE_SET, EX_INQ_SIDE_SETS, "side set", false},      {EX_ELEM_SET, EX_INQ_ELEM_SETS, "element set", false}};
  for (const Kind& k : kinds) {
    const int64_t n = ex_inquire_int(id, k.count);
    if (n <= 0) continue;
    std::vector<int64_t> ids(static_cast<size_t>(n));
    if (ex_get_ids(id, k.type, ids.data()) < 0)
      throw InputError(path, std::string(k.name) + "s", "the Exodus II library cannot read their ids: " + exodus_error());
    for (const int64_t object : ids) {
      int status;
      if (k.block) {
        char type[MAX_STR_LENGTH + 1] = {};
        int64_t entries = 0, nodes = 0, edges = 0, faces = 0, attributes = 0;
        status = ex_get_block(id, k.type, object, type, &entries, &nodes, &edges, &faces, &attributes);
      } else {
        int64_t entries = 0, distribution = 0;
        status = ex_get_set_param(id, k.type, object, &entries, &distribution);
      }
      if (status < 0)
        throw InputError(path, std::string(k.name) + " " + std::to_string(object),
                         "the Exodus II library cannot read its parameters: " + exodus_error());
    }
  }
}
}  // namespace

CellMesh read_exodus(const std::string& path, const std::string& variable, std::string* note) {
  check_magic(path);
  QuietStderr quiet;
  check_exodus_objects(path);
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

// libvobench-gmsh.so: the gmsh SDK's reading of .msh files, a module beside libvobench.so
// that datasets/io/gmsh_reader.cpp loads on the first .msh file. Linking the SDK into
// libvobench.so made every vobench process load it (OpenCASCADE, FLTK, ...), about 60 ms
// at start-up whether it read a .msh file or not.
#include <gmsh.h>

#include <map>
#include <mutex>
#include <unordered_map>

#include "datasets/gmsh/msh2_node_refs.h"
#include "datasets/gmsh/msh4_blocks.h"
#include "datasets/io/gmsh_reader.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
// The SDK holds one global model: one read at a time, initialised and finalised around it.
std::mutex gmsh_mutex;

class GmshSession {
 public:
  GmshSession() {
    gmsh::initialize(0, nullptr, false);  // no user configuration files
    gmsh::option::setNumber("General.Terminal", 0);  // gmsh prints to stdout otherwise
    gmsh::option::setNumber("General.Verbosity", 0);
  }
  ~GmshSession() {
    try {
      gmsh::finalize();
    } catch (...) {
    }
  }
};

struct VolumeType {
  int gmsh;
  CellType cell;
  int nodes;
  int vtk_node[8];  // VTK's node q is gmsh's node vtk_node[q]
};
// gmsh element codes of the linear volume elements (gmsh's "MSH element types"). gmsh's
// prism turns its triangles the other way round from VTK's wedge (gmsh's own VTK export
// swaps the same nodes); the others number their nodes as VTK does.
constexpr VolumeType kVolumeTypes[] = {{4, CellType::Tetra, 4, {0, 1, 2, 3}},
                                       {5, CellType::Hexahedron, 8, {0, 1, 2, 3, 4, 5, 6, 7}},
                                       {6, CellType::Wedge, 6, {0, 2, 1, 3, 5, 4}},
                                       {7, CellType::Pyramid, 5, {0, 1, 2, 3, 4}}};

// The table's entry for a gmsh element code, or null.
const VolumeType* volume_type(int type) {
  for (const VolumeType& v : kVolumeTypes)
    if (v.gmsh == type) return &v;
  return nullptr;
}

std::string element_name(int type, int* dim) {
  std::string name;
  int order = 0, nodes = 0, primary = 0;
  std::vector<double> local;
  gmsh::model::mesh::getElementProperties(type, name, *dim, order, nodes, local, primary);
  return name;
}

// gmsh's dimension and node count of an element type code; nodes 0 for a code gmsh does
// not know (it throws or logs an error for those). The linear volume types come from the
// table, and read_locked names only the other types: for a prism, getElementProperties
// builds gmsh 4.8's nodal basis, whose ClosureGen::getFaceClosurePrism frees with delete
// what it made with new[] and leaks more (AddressSanitizer: alloc-dealloc-mismatch and
// 1296 bytes leaked, running datasets.formats under scripts/test --sanitize's flags).
GmshElementType element_type(int type) {
  if (const VolumeType* v = volume_type(type)) return {3, v->nodes};
  std::string name;
  int dim = 0, order = 0, nodes = 0, primary = 0;
  std::vector<double> local;
  try {
    gmsh::model::mesh::getElementProperties(type, name, dim, order, nodes, local, primary);
  } catch (...) {
    return {};
  }
  return {dim, nodes};
}

// gmsh 4.8 throws its error text as a std::string (not a std::exception); its logger keeps
// the last error too.
std::string gmsh_reason(const std::string& thrown) {
  std::string last;
  try {
    gmsh::logger::getLastError(last);
  } catch (...) {
  }
  return last.empty() ? thrown : last;
}

CellMesh read_locked(const std::string& path, std::string* note) {
  GmshSession session;
  gmsh::logger::start();
  check_msh2_node_refs(path, [](int type) { return element_type(type).nodes; });
  check_msh4_blocks(path, element_type);
  gmsh::open(path);  // errors are thrown; caught in read_gmsh
  std::string last;
  gmsh::logger::getLastError(last);
  if (!last.empty()) throw InputError(path, "file", "gmsh: " + last);

  CellMesh m;
  std::vector<std::size_t> node_tags;
  std::vector<double> coord, param;
  gmsh::model::mesh::getNodes(node_tags, coord, param, -1, -1, false, false);
  if (node_tags.size() >= (size_t(1) << 31)) throw InputError(path, "nodes", "more than 2^31 nodes");
  std::unordered_map<std::size_t, int32_t> index;
  index.reserve(node_tags.size());
  m.points.resize(node_tags.size());
  for (size_t i = 0; i < node_tags.size(); ++i) {
    index.emplace(node_tags[i], int32_t(i));
    m.points[i] = {coord[3 * i], coord[3 * i + 1], coord[3 * i + 2]};
  }

  std::vector<int> types;
  std::vector<std::vector<std::size_t>> elem_tags, elem_nodes;
  gmsh::model::mesh::getElements(types, elem_tags, elem_nodes, -1, -1);
  std::map<std::string, size_t> skipped;
  size_t total = 0;
  for (size_t t = 0; t < types.size(); ++t) {
    total += elem_tags[t].size();
    const VolumeType* vt = volume_type(types[t]);
    if (!vt) {
      int dim = 0;
      const std::string name = element_name(types[t], &dim);
      if (dim < 3) {
        skipped[name] += elem_tags[t].size();
        continue;
      }
      throw InputError(path, "element " + std::to_string(elem_tags[t].empty() ? 0 : elem_tags[t][0]),
                       "gmsh type " + std::to_string(types[t]) + " (" + name +
                           ") is not supported (volume elements must be linear tetrahedra, hexahedra, prisms or pyramids)");
    }
    const std::vector<std::size_t>& nodes = elem_nodes[t];
    if (nodes.size() != elem_tags[t].size() * size_t(vt->nodes))
      throw InputError(path, "gmsh type " + std::to_string(types[t]) + " elements",
                       "node list does not match the element count");
    for (size_t e = 0; e < elem_tags[t].size(); ++e) {
      for (int q = 0; q < vt->nodes; ++q) {
        const std::size_t node = nodes[e * vt->nodes + vt->vtk_node[q]];
        const auto it = index.find(node);
        if (it == index.end())
          throw InputError(path, "element " + std::to_string(elem_tags[t][e]),
                           "node " + std::to_string(node) + " is not defined");
        m.conn.push_back(it->second);
      }
      m.types.push_back(vt->cell);
      m.offsets.push_back(int32_t(m.conn.size()));
    }
  }
  if (m.num_cells() == 0)
    throw InputError(path, "elements", total == 0 ? "the file has no elements"
                                                  : "none of the " + std::to_string(total) +
                                                        " elements is a volume element");

  std::vector<int> views;
  gmsh::view::getTags(views);
  for (const int v : views) {
    std::string kind;
    std::vector<std::size_t> tags;
    std::vector<std::vector<double>> data;
    double time = 0;
    int comps = 0;
    try {
      gmsh::view::getModelData(v, 0, kind, tags, data, time, comps);
    } catch (...) {
      continue;  // a list-based view: not model data
    }
    if (kind != "NodeData" || comps < 1) continue;
    std::vector<char> has(m.points.size(), 0);
    m.scalars.assign(m.points.size(), 0.0);
    for (size_t i = 0; i < tags.size(); ++i) {
      const auto it = index.find(tags[i]);
      if (it == index.end() || data[i].empty()) continue;
      m.scalars[it->second] = data[i][0];
      has[it->second] = 1;
    }
    for (const int32_t p : m.conn)
      if (!has[p]) {
        std::string vname;
        gmsh::option::getString("View[" + std::to_string(gmsh::view::getIndex(v)) + "].Name", vname);
        throw InputError(path, "node data '" + vname + "'",
                         "has no value at node " + std::to_string(node_tags[p]) + " of a volume element");
      }
    break;
  }
  if (note) {
    size_t n = 0;
    std::string list;
    for (const auto& [name, k] : skipped) {
      n += k;
      list += (list.empty() ? "" : ", ") + name + ": " + std::to_string(k);
    }
    *note = n == 0 ? "" : "read the volume elements only; skipped " + std::to_string(n) +
                              " elements of lower dimension (" + list + ")";
  }
  return m;
}
}  // namespace

// The file was prescanned (prescan_msh) by the caller.
extern "C" void vobench_gmsh_read(const std::string& path, CellMesh& out, std::string* note) {
  std::lock_guard<std::mutex> lock(gmsh_mutex);
  try {
    out = read_locked(path, note);
  } catch (const InputError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::string& thrown) {
    throw InputError(path, "file", "gmsh: " + gmsh_reason(thrown));
  } catch (const std::exception& e) {
    throw InputError(path, "file", "gmsh: " + gmsh_reason(e.what()));
  } catch (...) {
    throw InputError(path, "file", "gmsh: " + gmsh_reason("unknown error"));
  }
}

}  // namespace vob

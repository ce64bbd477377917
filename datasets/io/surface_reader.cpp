#include "datasets/io/surface_reader.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "datasets/io/file_util.h"
#include "datasets/io/obj_prescan.h"
#include "datasets/io/ply_prescan.h"
#include "datasets/io/vtk_shared.h"

namespace vob {

namespace {
// Binary STL: 80 header bytes, a triangle count, 50 bytes per triangle. VTK reads a cut
// file silently as fewer triangles, so the size must match the count exactly; a file that
// does not match is ASCII only if it starts with "solid" and its start is text. Returns the
// number of triangles the file holds (ASCII: its "facet" lines), which VTK must give back:
// its merging drops degenerate triangles without a word.
size_t check_stl(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char head[84] = {};
  in.read(reinterpret_cast<char*>(head), 84);
  const auto got = in.gcount();
  const uintmax_t size = std::filesystem::file_size(path);
  const uint32_t n = uint32_t(head[80]) | uint32_t(head[81]) << 8 | uint32_t(head[82]) << 16 | uint32_t(head[83]) << 24;
  if (got == 84 && size == 84 + 50 * uintmax_t(n)) return n;  // binary, complete
  bool text = got >= 5 && std::memcmp(head, "solid", 5) == 0;
  for (std::streamsize i = 0; text && i < got; ++i)
    text = head[i] == '\n' || head[i] == '\r' || head[i] == '\t' || (head[i] >= 32 && head[i] < 127);
  if (text) {
    in.clear();
    in.seekg(0);
    size_t facets = 0;
    std::string word, line;
    while (std::getline(in, line)) {
      std::istringstream ls(line);
      facets += (ls >> word) && word == "facet";
    }
    return facets;
  }
  if (got < 84) throw InputError(path, "header", "file ends inside the 84-byte binary STL header");
  throw InputError(path, "triangles", "binary STL declares " + std::to_string(n) + " triangles (" +
                                          std::to_string(84 + 50 * uintmax_t(n)) + " bytes) but the file has " +
                                          std::to_string(size) + " bytes");
}

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
  size_t stl_triangles = 0;
  ObjFaces obj;
  if (ext == ".stl") {
    stl_triangles = check_stl(path);
    pd = read_with<vtkSTLReader>(path);
    if (size_t(pd->GetNumberOfPolys()) != stl_triangles)
      throw InputError(path, "triangles", "VTK read " + std::to_string(pd->GetNumberOfPolys()) + " of the file's " +
                                              std::to_string(stl_triangles) +
                                              " (it drops triangles with two corners at one point: degenerate)");
  } else if (ext == ".ply") {
    prescan_ply(path);
    pd = read_with<vtkPLYReader>(path);
  } else if (ext == ".obj") {
    obj = prescan_obj(path);
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
  std::vector<int32_t> ids32;
  // OBJ faces with texture or normal indices: VTK's point of each corner -> the file's vertex.
  std::vector<int32_t> file_vertex(obj.corner_points ? size_t(np) : 0, -1);
  const size_t obj_faces = obj.corner_points ? obj.start.size() - 1 : 0;
  for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell(), ++face) {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    iter->GetCurrentCell(n, ids);
    if (n < 3) throw InputError(path, "face " + std::to_string(face), "has " + std::to_string(n) + " vertices");
    for (vtkIdType q = 0; q < n; ++q)
      if (ids[q] < 0 || ids[q] >= np)
        throw InputError(path, "face " + std::to_string(face), "vertex index " + std::to_string(ids[q]) + " is out of range");
    ids32.assign(ids, ids + n);
    append_polygon(s, ids32.data(), ids32.size(), path, "face " + std::to_string(face));
    if (obj.corner_points) {
      if (size_t(face) >= obj_faces || obj.start[face + 1] - obj.start[face] != size_t(n))
        throw InputError(path, "face " + std::to_string(face), "VTK's OBJ reader gave it other points than the file");
      for (vtkIdType q = 0; q < n; ++q) {
        const int32_t v = obj.vertex[obj.start[face] + q];
        if (file_vertex[ids[q]] >= 0 && file_vertex[ids[q]] != v)
          throw InputError(path, "face " + std::to_string(face), "VTK's OBJ reader gave it other points than the file");
        file_vertex[ids[q]] = v;
      }
    }
  }
  if (obj.corner_points) {
    // The corners share their file's vertices again (numbered in file order, the vertices no
    // face uses left out, as VTK leaves them out): a closed surface stays closed.
    if (size_t(face) != obj_faces)
      throw InputError(path, "faces", "VTK's OBJ reader read " + std::to_string(face) + " of the file's " +
                                          std::to_string(obj_faces));
    std::vector<int32_t> index(*std::max_element(obj.vertex.begin(), obj.vertex.end()) + size_t(1), -1);
    for (const int32_t v : file_vertex)
      if (v >= 0) index[v] = 0;
    int32_t next = 0;
    for (int32_t& i : index)
      if (i == 0) i = next++;
    std::vector<Vec3> points(static_cast<size_t>(next));
    std::vector<char> seen(static_cast<size_t>(next), 0);
    for (vtkIdType g = 0; g < np; ++g) {
      if (file_vertex[g] < 0) continue;
      const int32_t to = index[file_vertex[g]];
      if (seen[to] && (points[to].x != s.points[g].x || points[to].y != s.points[g].y || points[to].z != s.points[g].z))
        throw InputError(path, "vertex " + std::to_string(file_vertex[g] + 1),
                         "VTK's OBJ reader gave its corners different coordinates");
      points[to] = s.points[g];
      seen[to] = 1;
    }
    for (auto& t : s.tris)
      for (int32_t& v : t) v = index[file_vertex[v]];
    s.points = std::move(points);
  }
  if (s.tris.empty()) throw InputError(path, "faces", "the file has no triangles or polygons");
  const vtkIdType other = pd->GetNumberOfVerts() + pd->GetNumberOfLines();
  if (note)
    *note = other == 0 ? "" : "read the faces only; skipped " + std::to_string(other) + " vertices and lines";
  return s;
}

}  // namespace vob

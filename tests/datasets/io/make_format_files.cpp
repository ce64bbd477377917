// Writes one file per format vobench reads through a library, made from generated scenes
// with VTK's own writers (Exodus II, .pvtu in 3 pieces, STL, PLY, OBJ) or by hand plus zlib
// (.inr.gz: INRIMAGE has no VTK writer), and counts.json with what each must read back as.
//   make_format_files write OUTDIR      files + counts.json
//   make_format_files scalars FILE [VAR] "points N scalars N min MIN max MAX" of the loaded
//                                       scene (VAR: the Exodus nodal variable)
#include <zlib.h>

#include <cstdio>
#include <fstream>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkExodusIIWriter.h>
#include <vtkExtractUnstructuredGridPiece.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkOBJWriter.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLWriter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPUnstructuredGridWriter.h>

#include <nlohmann/json.hpp>

#include "datasets/datasets.h"
#include "tests/support/test_util.h"

using namespace vob;

namespace {
vtkSmartPointer<vtkUnstructuredGrid> grid(const CellMesh& m) {
  auto ug = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (const Vec3& p : m.points) pts->InsertNextPoint(p.x, p.y, p.z);
  ug->SetPoints(pts);
  for (size_t c = 0; c < m.num_cells(); ++c) {
    vtkIdType ids[8];
    for (int q = 0; q < m.cell_size(c); ++q) ids[q] = m.cell_points(c)[q];
    ug->InsertNextCell(int(m.types[c]), m.cell_size(c), ids);
  }
  vtkNew<vtkDoubleArray> s;
  s->SetName("temperature");
  for (size_t i = 0; i < m.num_points(); ++i) s->InsertNextValue(1.0 + m.points[i].x);  // known values
  ug->GetPointData()->AddArray(s);
  vtkNew<vtkDoubleArray> q;
  q->SetName("pressure");
  for (size_t i = 0; i < m.num_points(); ++i) q->InsertNextValue(100.0 + m.points[i].y);
  ug->GetPointData()->AddArray(q);
  return ug;
}

vtkSmartPointer<vtkPolyData> surface(const TriangleSoup& t) {
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (const Vec3& p : t.points) pts->InsertNextPoint(p.x, p.y, p.z);
  vtkNew<vtkCellArray> polys;
  for (const auto& tri : t.tris) {
    const vtkIdType ids[3] = {tri[0], tri[1], tri[2]};
    polys->InsertNextCell(3, ids);
  }
  pd->SetPoints(pts);
  pd->SetPolys(polys);
  return pd;
}

template <class W>
void write(W* w, const std::string& path) {
  w->SetFileName(path.c_str());
  if (w->Write() != 1) {
    std::fprintf(stderr, "could not write %s\n", path.c_str());
    std::exit(1);
  }
}

// INRIMAGE-4: a 256-byte header block, then float samples, little endian, x fastest.
void write_inr_gz(const VoxelGrid& g, const std::string& path) {
  char head[257];
  std::snprintf(head, sizeof head,
                "#INRIMAGE-4#{\nXDIM=%d\nYDIM=%d\nZDIM=%d\nVDIM=1\nVX=%g\nVY=%g\nVZ=%g\nTYPE=float\n"
                "PIXSIZE=32 bits\nCPU=decm\n",
                g.dims[0], g.dims[1], g.dims[2], g.spacing.x, g.spacing.y, g.spacing.z);
  std::string header(head);
  header += std::string(256 - 4 - header.size(), '\n') + "##}\n";
  gzFile f = gzopen(path.c_str(), "wb");
  gzwrite(f, header.data(), unsigned(header.size()));
  gzwrite(f, g.values.data(), unsigned(g.values.size() * sizeof(float)));
  gzclose(f);
}
}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 && argc != 4) return 64;
  const std::string mode = argv[1], arg = argv[2];
  if (mode == "scalars") {
    InputOptions opt;
    if (argc == 4) opt.variable = argv[3];
    const Scene s = load_input(arg, opt);
    const CellMesh& m = s.mesh();
    double lo = 1e300, hi = -1e300;
    for (double v : m.scalars) lo = std::min(lo, v), hi = std::max(hi, v);
    std::printf("points %zu scalars %zu min %.17g max %.17g\n", m.num_points(), m.scalars.size(), lo, hi);
    return 0;
  }
  const std::string dir = arg;
  nlohmann::json counts;
  const Scene zoo = test::make("zoo");  // tetra, pyramid, wedge, hexahedron
  const Scene helix = test::make("helix", {{"cells", "3000"}});
  {
    vtkNew<vtkExodusIIWriter> w;
    w->SetInputData(grid(zoo.mesh()));
    write(w.Get(), dir + "/zoo.exo");
    counts["zoo.exo"] = zoo.mesh().num_cells();
  }
  {
    vtkNew<vtkExodusIIWriter> w;
    w->SetInputData(grid(helix.mesh()));
    write(w.Get(), dir + "/helix.e");
    counts["helix.e"] = helix.mesh().num_cells();
  }
  {
    vtkNew<vtkExtractUnstructuredGridPiece> split;  // honest pieces, borders repeated
    split->SetInputData(grid(helix.mesh()));
    vtkNew<vtkXMLPUnstructuredGridWriter> w;
    w->SetInputConnection(split->GetOutputPort());
    w->SetNumberOfPieces(3);
    w->SetStartPiece(0);
    w->SetEndPiece(2);
    write(w.Get(), dir + "/helix.pvtu");
    counts["helix.pvtu"] = helix.mesh().num_cells();
  }
  const Scene spheres = test::make("spheres", {{"subdiv", "1"}});
  const Scene sphere = test::make("sphere", {{"subdiv", "2"}});
  {
    vtkNew<vtkSTLWriter> w;
    w->SetInputData(surface(spheres.soup()));
    w->SetFileTypeToBinary();
    write(w.Get(), dir + "/spheres.stl");
    counts["spheres.stl"] = spheres.soup().num_triangles();
    vtkNew<vtkSTLWriter> a;
    a->SetInputData(surface(sphere.soup()));
    a->SetFileTypeToASCII();
    write(a.Get(), dir + "/sphere-ascii.stl");
    counts["sphere-ascii.stl"] = sphere.soup().num_triangles();
  }
  {
    vtkNew<vtkPLYWriter> w;
    w->SetInputData(surface(spheres.soup()));
    w->SetFileTypeToBinary();
    write(w.Get(), dir + "/spheres.ply");
    counts["spheres.ply"] = spheres.soup().num_triangles();
  }
  {
    vtkNew<vtkOBJWriter> w;
    w->SetInputData(surface(sphere.soup()));
    write(w.Get(), dir + "/sphere.obj");
    counts["sphere.obj"] = sphere.soup().num_triangles();
  }
  const Scene vox = test::make("sparse", {{"nx", "20"}, {"ny", "12"}, {"nz", "9"}});
  write_inr_gz(vox.grid(), dir + "/sparse.inr.gz");
  counts["sparse.inr.gz"] = vox.num_primitives();
  std::ofstream(dir + "/counts.json") << counts.dump(1) << "\n";
  // The pieces repeat their border points; read back, the .pvtu must have the mesh's points.
  std::ofstream(dir + "/points.json") << nlohmann::json{{"helix.pvtu", helix.mesh().num_points()}}.dump() << "\n";
  return 0;
}

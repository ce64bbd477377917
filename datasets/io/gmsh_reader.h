// gmsh meshes (.msh, versions 2.2 and 4.1, ASCII and binary) through the gmsh SDK.
// Volume elements become cells: 4-node tetrahedra, 8-node hexahedra, 6-node prisms and
// 5-node pyramids (prism nodes renumbered to VTK's wedge). Points, lines and surface
// elements beside them are skipped (told in `note`); other volume elements (second order,
// ...) are refused. Scalars: component 0 of the first node-data view ($NodeData) in the
// file, which must give a value at every node used by a cell; none when the file has none.
#pragma once
#include <string>

#include "harness/scene/cell_mesh.h"

namespace vob {

// The file is prescanned here (datasets/io/msh_prescan.h); the SDK, in the module
// libvobench-gmsh.so beside libvobench.so, is loaded on the first file that passes.
CellMesh read_gmsh(const std::string& path, std::string* note = nullptr);

// The module's entry point (datasets/gmsh/gmsh_sdk_reader.cpp); errors are thrown as
// InputError naming `path`.
extern "C" void vobench_gmsh_read(const std::string& path, CellMesh& out, std::string* note);
#define VOBENCH_GMSH_READ_ENTRY "vobench_gmsh_read"
#define VOBENCH_GMSH_MODULE "libvobench-gmsh.so"

}  // namespace vob

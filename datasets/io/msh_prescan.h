// The counts a gmsh .msh file declares, checked against its size before gmsh reads it:
// gmsh sizes its arrays from the $Nodes and $Elements headers, so a small file declaring
// 10^9 nodes would take minutes and gigabytes before failing. Every node and element takes
// at least 2 bytes. Checks the $MeshFormat line too (version 2.x or 4.x, ASCII or binary);
// a file must start with it (or with MSH 1's $NOD), as gmsh requires of a mesh.
// $NodeData's value count is checked the same way (gmsh dropped a view declaring more
// than an int holds, silently). Only the section headers are checked; gmsh reports what
// lies inside them. Line ends are LF or CRLF (gmsh reads both alike).
#pragma once
#include <string>

namespace vob {

void prescan_msh(const std::string& path);

}  // namespace vob

// Surfaces (.stl ASCII/binary, .ply, .obj) through VTK's readers (vtkSTLReader merges the
// repeated corners of STL's separate triangles into shared points, as TetGen needs).
// Polygons are fan-split from their first vertex (as OFF files are); vertices and lines
// beside them are skipped and told in `note`; triangle strips are refused.
#pragma once
#include <string>

#include "harness/scene/triangle_soup.h"

namespace vob {

TriangleSoup read_surface(const std::string& path, std::string* note = nullptr);

}  // namespace vob

// OFF surface files: "[ST][C][N]OFF", counts "V F E", V vertex lines (x y z, then optional
// normal/colour/texture values, ignored), F face lines "n i1 .. in [colour]". Polygons are
// fan-split into triangles from their first vertex. Indices are 0-based (the format's rule).
#pragma once
#include <string>

#include "harness/scene/triangle_soup.h"

namespace vob {

TriangleSoup read_off(const std::string& path);
void write_off(const TriangleSoup& s, const std::string& path);  // atomically, %.17g

}  // namespace vob

// TetGen's .node/.ele files (https://wias-berlin.de/software/tetgen/fformats.html).
#pragma once
#include <string>

#include "harness/scene/cell_mesh.h"

namespace vob {

// Reads points (first attribute, if any, becomes the point scalar) and 4-node tetrahedra.
// Indices may start at 0 or 1 (taken from the first point; the .ele uses the same base).
// Comments (#) and blank lines are skipped. InputError names file, line and element.
CellMesh read_tetgen(const std::string& node_path, const std::string& ele_path);

// The .ele beside a .node (same stem) and vice versa.
std::string tetgen_partner(const std::string& path, const char* ext);

// Writes <stem>.node (scalar as one attribute) and <stem>.ele, each atomically; 0-based.
// InputError if the mesh holds cells other than tetrahedra.
void write_tetgen(const CellMesh& m, const std::string& node_path);

}  // namespace vob

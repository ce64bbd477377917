// The zoo of cell types (VTK numbering and vertex order) and their local faces.
// With VTK's vertex order and a positively oriented cell, every local face below is listed
// counter-clockwise seen from outside, so its right-hand normal points out of the cell.
#pragma once
#include <cstdint>
#include <string>

namespace vob {

enum class CellType : uint8_t { Tetra = 10, Hexahedron = 12, Wedge = 13, Pyramid = 14 };

struct LocalFaces {
  int count;        // number of faces
  int size[6];      // 3 or 4 vertices each
  int v[6][4];      // local vertex indices, outward orientation
};

int cell_vertex_count(CellType t);
const LocalFaces& cell_local_faces(CellType t);
const char* cell_type_name(CellType t);
// True for the four supported VTK codes.
bool is_supported_cell_code(int vtk_code);

}  // namespace vob

#include "harness/scene/cell_types.h"

namespace vob {
namespace {
// Face tables follow vtkTetra, vtkHexahedron, vtkWedge and vtkPyramid, oriented outward.
const LocalFaces kTetra{4, {3, 3, 3, 3, 0, 0}, {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {0, 2, 1}}};
const LocalFaces kHex{6,
                      {4, 4, 4, 4, 4, 4},
                      {{0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 7, 6, 2}, {0, 3, 2, 1},
                       {4, 5, 6, 7}}};
const LocalFaces kWedge{5,
                        {3, 3, 4, 4, 4, 0},
                        {{0, 1, 2}, {3, 5, 4}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}}};
const LocalFaces kPyramid{5,
                          {4, 3, 3, 3, 3, 0},
                          {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}};
}  // namespace

int cell_vertex_count(CellType t) {
  switch (t) {
    case CellType::Tetra: return 4;
    case CellType::Pyramid: return 5;
    case CellType::Wedge: return 6;
    case CellType::Hexahedron: return 8;
  }
  return 0;
}

const LocalFaces& cell_local_faces(CellType t) {
  switch (t) {
    case CellType::Tetra: return kTetra;
    case CellType::Pyramid: return kPyramid;
    case CellType::Wedge: return kWedge;
    case CellType::Hexahedron: return kHex;
  }
  return kTetra;
}

const char* cell_type_name(CellType t) {
  switch (t) {
    case CellType::Tetra: return "tetra";
    case CellType::Pyramid: return "pyramid";
    case CellType::Wedge: return "wedge";
    case CellType::Hexahedron: return "hexahedron";
  }
  return "?";
}

bool is_supported_cell_code(int c) { return c == 10 || c == 12 || c == 13 || c == 14; }

}  // namespace vob

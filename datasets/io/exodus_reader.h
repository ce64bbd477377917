// Exodus II meshes (.exo, .e) through VTK's vtkExodusIIReader: the volume cells of every
// element block, at the first time step, on the file's global node numbering (blocks
// share nodes, so faces between blocks are shared faces). Lower-dimensional blocks (shells,
// beams) are skipped and told in `note`. Scalars: the nodal variable named `variable`, or
// the file's first nodal variable when `variable` is empty, or none when it has none.
#pragma once
#include <string>

#include "harness/scene/cell_mesh.h"

namespace vob {

CellMesh read_exodus(const std::string& path, const std::string& variable = "", std::string* note = nullptr);

}  // namespace vob

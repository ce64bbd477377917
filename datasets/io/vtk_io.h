// VTK files through VTK's own readers and writers.
//   .vtu  XML unstructured grid -> cells (tetra, pyramid, wedge, hexahedron); vertices,
//         lines and surface cells beside them are skipped (see read_vtk_file's note),
//         other volume cells (quadratic, polyhedron, ...) are refused.
//   .pvtu parallel XML unstructured grid: its pieces, read as one mesh (points repeated at
//         bit-identical coordinates on piece borders become one point).
//   .vtk  legacy: an unstructured grid -> cells; structured points -> voxels.
//   .vti  XML image data -> voxels.
// Point scalars: the active scalars, else the first point-data array (component 0).
// Voxels: image points are voxel centres (point data), or image cells are voxels when the
// file has only cell data. The significance threshold is read from the field-data array
// "vobench_threshold" (written by write_vti), else 0: values > 0 are significant.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "harness/scene/scene.h"

namespace vob {

// `note`, when given, receives what the caller should tell once the scene has been
// validated ("" when nothing): cells of lower dimension skipped beside the volume cells.
Scene read_vtk_file(const std::string& path, std::string* note = nullptr);
void write_vtu(const CellMesh& m, const std::string& path);
// The mesh with extra named cell arrays (one value per cell each), e.g. for ParaView.
using CellArrays = std::vector<std::pair<std::string, std::vector<int64_t>>>;
void write_vtu(const CellMesh& m, const std::string& path, const CellArrays& cell_arrays);
// A width x height image (one point per pixel, row 0 at the bottom as the camera's window
// y) with the uint8 point array `name`, for ParaView.
void write_mask_vti(const std::vector<uint8_t>& mask, int width, int height, const std::string& name,
                    const std::string& path);
void write_vtk_legacy(const CellMesh& m, const std::string& path);  // binary, exact doubles
void write_vti(const VoxelGrid& g, const std::string& path);

}  // namespace vob

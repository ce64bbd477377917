// Cheap checks on a VTK file's own text before VTK parses it, for what VTK would turn into
// a crash (deep XML nesting), a huge allocation (a small file declaring 10^9 points) or a
// silent default (a .vti origin of "nan" or "abc" read as 0). Each throws one InputError
// naming the file, the element and the reason. Defined in vtk_xml_prescan.cpp and
// vtk_legacy_prescan.cpp, which share vtk_prescan_text.h.
#pragma once
#include <string>

namespace vob {

inline constexpr int kMaxXmlDepth = 64;
// A compressed XML file may promise at most this many values per byte of file (zlib's
// deflate peaks near 1032:1, and VTK compresses in blocks that each carry a header).
inline constexpr double kMaxCompressionRatio = 1100;

// .vtu and .vti: tag nesting depth, Piece/DataArray counts against the file size, and for
// image data WholeExtent/Extent (integers) and Origin/Spacing/Direction (finite numbers).
// A piece's "offsets" and "types" arrays hold NumberOfCells values (ASCII ones counted,
// binary and appended ones by their headers), ASCII types VTK cell type codes; connectivity
// and offsets are integers of 16 to 64 bits, types integers. Every binary or appended array's
// header promises no more bytes (compressed: blocks, and data at kMaxCompressionRatio) than
// follow it.
// `expected_type` is the VTKFile type the extension promises (UnstructuredGrid, ImageData).
void prescan_vtk_xml(const std::string& path, const std::string& expected_type);
// Legacy .vtk: POINTS, CELLS, CELL_TYPES, POINT_DATA, CELL_DATA and DIMENSIONS counts are
// integers and fit the file (every value takes at least one byte); a cell list in the format
// before 5.1 ("k id_1 .. id_k" per cell) holds exactly its declared values, every k
// non-negative and within them (VTK walks it unchecked); CELL_TYPES gives one type per cell
// of CELLS, each a VTK cell type code (VTK keeps them in a byte). In ASCII files the float
// or double POINTS and SCALARS values are finite numbers, as many as declared (VTK's `>>`
// stops at "nan" and says only "Error reading ascii data").
void prescan_vtk_legacy(const std::string& path);

}  // namespace vob

// An OBJ file walked before VTK's reader (VTK 9.1's vtkOBJReader) sees it: that reader takes
// what it can from a line and goes on. Measured on it: `v 0.3 0.2` read with z = 0, `nan`,
// `abc` and `0x10` read as 0, 1e400 clamped to the float maximum (its points are floats; 1e-50
// became 0), `f 2 3 4x` and `f 2 3 4.5` read as 4, 99999999999 wrapped to another index,
// index 0 and indices past the vertices kept (-1 or a point that does not exist), unknown
// statements (`F`, free-form `curv`) skipped, and a texture or normal index past its list
// read past the array (`f 1/1 2/2 3/3` without `vt` lines: SIGSEGV).
// Checks, naming the line: each `v` holds 3 finite numbers (4 with OBJ's w, 6 or 7 with
// colours), within float range (a non-zero value must not become 0); `vt` 1 to 3 and `vn` 3
// finite numbers; every `f`, `l` and `p` reference is an integer of one form per statement
// (v, v/vt, v/vt/vn, v//vn; lines v or v/vt; points v), 1-based or negative (relative to
// the entries read so far, as VTK resolves them) and within its list; a face has at least 3
// points and no trailing comment (VTK fails on one), and all faces have texture and normal
// references or all lack them (VTK skips the faces that differ); lines of at most 262,144 bytes (VTK's
// limit); statements other than v vt vn f l p g o s usemtl mtllib and OBJ's display
// attributes are refused. A `\` at a line's end continues the statement, as in VTK.
//
// VTK gives each face corner a point of its own when faces carry texture or normal indices
// (unless those equal the vertex indices): its surface has no shared points, so a closed
// file looked open. For such files the faces' vertex indices are returned, to share the
// points again.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace vob {

struct ObjFaces {
  bool corner_points = false;  // the faces carry texture or normal indices; then:
  std::vector<size_t> start;    // face f's vertices: vertex[start[f] .. start[f + 1])
  std::vector<int32_t> vertex;  // 0-based, negative ones resolved
};

ObjFaces prescan_obj(const std::string& path);

}  // namespace vob

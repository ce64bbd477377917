// A PLY file walked against its own header before VTK's reader sees it: VTK's PLY code
// frees twice or reads past its buffers on a file that ends early or holds a malformed
// number. Checks: the header's grammar and types, then every element instance present
// (ASCII: enough numeric tokens, list counts non-negative integers; binary: enough bytes,
// list counts read in the file's byte order), and every face's vertex_indices (or
// vertex_index) within the vertices (VTK's reader reads far past its points for a large
// one) and at most 255 of them (VTK keeps the count in a byte). The header must give the
// vertices scalar x, y, z and the faces that index list, vertices first (VTK's reader
// crashes otherwise). One InputError naming file, element, reason.
#pragma once
#include <string>

namespace vob {

void prescan_ply(const std::string& path);

}  // namespace vob

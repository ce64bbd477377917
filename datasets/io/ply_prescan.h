// A PLY file walked against its own header before VTK's reader sees it: VTK's PLY code
// frees twice or reads past its buffers on a file that ends early or holds a malformed
// number. Checks: the header's grammar and types, then every element instance present
// (ASCII: enough numeric tokens, list counts non-negative integers; binary: enough bytes,
// list counts read in the file's byte order), and every face's vertex_indices within the
// vertices (VTK's reader reads far past its points for a large one). One InputError naming
// file, element, reason.
#pragma once
#include <string>

namespace vob {

void prescan_ply(const std::string& path);

}  // namespace vob

// MSH 4.1 files (ASCII and binary): $Entities, $Nodes and $Elements walked block by block
// before gmsh reads them. gmsh 4.8's MSH 4 reader allocates the header's node and element
// counts and writes every block's entries into that array: blocks holding more than the
// header declares overran it ("double free or corruption", SIGSEGV under random byte
// mutations), fewer left entries it reads later uninitialised; it also sizes vectors from
// counts before reading them. So a file is refused here when a count exceeds the bytes
// left or the header's total, the blocks hold fewer entries than the header, a section's
// data do not end at its $End line, a node tag is 0 or given twice, or a node or element
// tag is beyond what gmsh holds (kMaxGmshTag, msh_text.h). Element types
// unknown to gmsh or of another dimension than their entity, and elements naming a node
// $Nodes lacks, gmsh reports itself; they are refused here too, with the element named.
// Other versions are left to gmsh (4.0; 2.x: see msh2_node_refs.h); so are the contents
// of other sections ($PartitionedEntities, $NodeData, ...), which gmsh checks itself.
#pragma once
#include <functional>
#include <string>

namespace vob {

struct GmshElementType {
  int dim = 0;
  int nodes = 0;  // 0: not a type gmsh knows
};

// type_of(code): gmsh's dimension and node count of an element type code.
// Throws InputError naming the section, block or element and the reason.
void check_msh4_blocks(const std::string& path, const std::function<GmshElementType(int)>& type_of);

}  // namespace vob

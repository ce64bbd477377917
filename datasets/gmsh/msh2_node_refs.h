// MSH 2.x files: every node an element names must be a node of $Nodes (or
// $ParametricNodes). gmsh 4.8's MSH 2 reader lets the tag just past the last of densely
// numbered nodes through as a null node, then crashes on it
// (GModel::_associateEntityWithMeshVertices), so such a file is refused here first; so is
// a node or element tag of an ASCII file beyond what gmsh holds (kMaxGmshTag, msh_text.h;
// binary files hold 32-bit tags). Element lines and binary element blocks are checked
// against their tag counts and their types' node counts (gmsh reads numbers, not lines,
// and failed later with "Error loading" or "Wrong node index 0").
// Other versions, and files this scan cannot follow (cut, garbled), are left to gmsh,
// which reports them.
#pragma once
#include <functional>
#include <string>

namespace vob {

// nodes_of(type): the node count of a gmsh element type (for binary files; may throw for
// a type gmsh does not know). Throws InputError naming the element and the node.
void check_msh2_node_refs(const std::string& path, const std::function<int(int)>& nodes_of);

}  // namespace vob

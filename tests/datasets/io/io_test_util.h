// What the reader tests of tests/datasets/io share: writing a file, and gmsh .msh files
// read through the program (the gmsh reader is a module beside libvobench.so, which the
// tests do not link).
#pragma once
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "tests/support/test_util.h"

namespace vob::test {

inline void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// The one line the program refuses the .msh file `path` with (exit 2).
inline std::string msh_error(const std::string& path) {
  const CommandOutput r = run_vobench(VOB_BINARY, "validate " + path);
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  return r.out;
}
// The cell count the program reads from a valid `path`.
inline size_t msh_cells(const std::string& path) {
  const CommandOutput r = run_vobench(VOB_BINARY, "validate " + path);
  EXPECT_EQ(r.code, 0) << r.out;
  return size_t(std::strtoull(r.out.substr(r.out.find(": ") + 2).c_str(), nullptr, 10));
}

// One tetrahedron (or more) in gmsh's MSH 4.1 ASCII format: node tags as given, one per
// point of kTetPoints, and element lines "tag n1 n2 n3 n4".
inline const char* const kTetPoints[] = {"0 0 0", "1 0 0", "0 1 0", "0 0 1", "1 1 1"};
inline std::string msh41(const std::vector<std::string>& node_tags, const std::vector<std::string>& elements) {
  std::string s = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 0 1\n1 0 0 0 1 1 1 0 0\n$EndEntities\n";
  s += "$Nodes\n1 " + std::to_string(node_tags.size()) + " 1 " + node_tags.back() + "\n3 1 0 " +
       std::to_string(node_tags.size()) + "\n";
  for (const std::string& t : node_tags) s += t + "\n";
  for (size_t i = 0; i < node_tags.size(); ++i) s += std::string(kTetPoints[i]) + "\n";
  s += "$EndNodes\n$Elements\n1 " + std::to_string(elements.size()) + " 1 " + std::to_string(elements.size()) +
       "\n3 1 4 " + std::to_string(elements.size()) + "\n";
  for (const std::string& e : elements) s += e + "\n";
  return s + "$EndElements\n";
}
// The same in MSH 2.2 ASCII; element lines "id type ntags tags... nodes...".
inline std::string msh22(const std::vector<std::string>& node_tags, const std::vector<std::string>& elements) {
  std::string s = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" + std::to_string(node_tags.size()) + "\n";
  for (size_t i = 0; i < node_tags.size(); ++i) s += node_tags[i] + " " + kTetPoints[i] + "\n";
  s += "$EndNodes\n$Elements\n" + std::to_string(elements.size()) + "\n";
  for (const std::string& e : elements) s += e + "\n";
  return s + "$EndElements\n";
}

}  // namespace vob::test

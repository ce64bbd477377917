#include "datasets/gmsh/msh_text.h"

#include <fstream>

namespace vob {

bool read_msh_if_starts_with(const std::string& path, std::string_view prefix, std::string& out) {
  std::ifstream in(path, std::ios::binary);
  out.assign(64, '\0');
  in.read(out.data(), std::streamsize(out.size()));
  out.resize(size_t(in.gcount()));
  if (out.rfind(prefix, 0) != 0) return false;
  in.clear();
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size <= 0) return false;
  in.seekg(0);
  out.resize(size_t(size));
  in.read(out.data(), size);
  out.resize(size_t(in.gcount()));
  return true;
}

}  // namespace vob

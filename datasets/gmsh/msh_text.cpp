#include "datasets/gmsh/msh_text.h"

#include <fstream>

namespace vob {

bool read_msh_if_version(const std::string& path, std::string_view version, std::string& out, size_t& version_at) {
  std::ifstream in(path, std::ios::binary);
  out.assign(64, '\0');
  in.read(out.data(), std::streamsize(out.size()));
  out.resize(size_t(in.gcount()));
  const std::string_view tag = "$MeshFormat";
  if (out.rfind(tag, 0) != 0) return false;
  version_at = after_line_end(out, tag.size());
  if (version_at == std::string::npos || out.compare(version_at, version.size(), version) != 0) return false;
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

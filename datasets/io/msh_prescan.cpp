#include "datasets/io/msh_prescan.h"

#include <climits>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "datasets/gmsh/msh_text.h"
#include "datasets/io/file_util.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
// The file is scanned in chunks for the lines "$Nodes" and "$Elements" (LF or CRLF); a chunk
// keeps the tail of the previous one so a marker split between them is still found.
constexpr size_t kChunk = size_t(1) << 20;
// A $NodeData header (its tags) is read from this many bytes after the marker.
constexpr size_t kDataHeader = 1024;

// $NodeData's header: string tags (the view's name first), real tags, integer tags, one a
// line; the third integer tag counts the values that follow. False when it cannot be read
// here (gmsh reports it).
bool node_data_header(const std::string& text, std::string& name, long long& count) {
  std::istringstream in(text);
  std::string line;
  const auto number = [&](long long& v) { return std::getline(in, line) && std::sscanf(line.c_str(), "%lld", &v) == 1; };
  long long n = 0;
  if (!number(n) || n < 0 || n > 8) return false;
  for (long long i = 0; i < n; ++i) {
    if (!std::getline(in, line)) return false;
    if (i == 0) name = line.substr(0, line.find_last_not_of("\r") + 1);
  }
  if (!number(n) || n < 0 || n > 8) return false;
  for (long long i = 0; i < n; ++i)
    if (!std::getline(in, line)) return false;
  long long ints = 0, v = 0;
  if (!number(ints) || ints < 3) return false;
  for (int i = 0; i < 3; ++i)
    if (!number(v)) return false;
  count = v;
  return true;
}
}  // namespace

void prescan_msh(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const uintmax_t size = std::filesystem::file_size(path);
  std::string head(256, '\0');
  in.read(head.data(), 256);
  head.resize(size_t(in.gcount()));
  // gmsh reads a .msh file as a mesh only when it starts so; anything else it runs as a
  // .geo script (4 GB of NUL bytes took over a minute, then "no elements").
  require_file_start(path, {"$MeshFormat", "$NOD", "$NOE"}, false, "gmsh mesh", "$MeshFormat");
  if (head.rfind("$MeshFormat", 0) != 0) return;  // MSH 1: gmsh checks it
  std::istringstream fmt(head.substr(head.find('\n') + 1));
  double version = 0;
  int binary = -1, data_size = 0;
  if (!(fmt >> version >> binary >> data_size) || (binary != 0 && binary != 1))
    throw InputError(path, "$MeshFormat", "expected 'version file-type data-size'");
  if (!((version >= 2 && version < 3) || (version >= 4 && version < 5)))
    throw InputError(path, "$MeshFormat", "version " + std::to_string(version).substr(0, 4) + " is not 2.x or 4.x");
  const bool raw_counts = binary == 1 && version >= 4;  // 4.x binary: section headers are size_t
  if (raw_counts && data_size != 8) throw InputError(path, "$MeshFormat", "data-size must be 8 (size_t)");

  in.clear();
  in.seekg(0);
  std::string buf;
  uintmax_t base = 0;  // file offset of buf[0]
  bool open_nodes = false, open_elements = false, end_nodes = false, end_elements = false;
  for (;;) {
    std::string chunk(kChunk, '\0');
    in.read(chunk.data(), std::streamsize(kChunk));
    chunk.resize(size_t(in.gcount()));
    if (chunk.empty()) break;
    buf += chunk;
    open_nodes = open_nodes || buf.find("\n$Nodes") != std::string::npos;
    open_elements = open_elements || buf.find("\n$Elements") != std::string::npos;
    end_nodes = end_nodes || buf.find("\n$EndNodes") != std::string::npos;
    end_elements = end_elements || buf.find("\n$EndElements") != std::string::npos;
    for (const std::string name : {"Nodes", "Elements"}) {
      const std::string marker = "$" + name;
      for (size_t at = find_line(buf, marker, 1); at != std::string::npos; at = find_line(buf, marker, at + 1)) {
        const size_t after = after_line_end(buf, at + marker.size());
        if (after + 64 > buf.size() && in) continue;  // read more first (found again next round)
        uint64_t count = 0;
        if (raw_counts) {  // numEntityBlocks, then the count
          if (after + 16 > buf.size()) throw InputError(path, marker, "file ends inside the section header");
          std::memcpy(&count, buf.data() + after + 8, 8);
        } else {
          std::istringstream line(buf.substr(after, 64));
          uint64_t first = 0;
          if (!(line >> first)) throw InputError(path, name, "the count is not a number");
          count = first;
          if (version >= 4 && !(line >> count))  // numEntityBlocks count ...
            throw InputError(path, name, "expected 'blocks count min max'");
        }
        const uintmax_t left = size - (base + after);
        if (count > left / 2)
          throw InputError(path, name,
                           "declares " + std::to_string(count) + " entries but only " + std::to_string(left) +
                               " bytes follow");
      }
    }
    // gmsh reads the count into an int: beyond it (10^12 values declared, 2 given) the
    // view was dropped without a word, and the mesh read without its scalars.
    for (size_t at = find_line(buf, "$NodeData", 1); at != std::string::npos; at = find_line(buf, "$NodeData", at + 1)) {
      const size_t after = after_line_end(buf, at + std::strlen("$NodeData"));
      if (after + kDataHeader > buf.size() && in) continue;  // found again next round
      std::string name;
      long long count = 0;
      if (!node_data_header(buf.substr(after, kDataHeader), name, count)) continue;
      const uintmax_t left = size - (base + after);
      const std::string declares = "declares " + std::to_string(count) + " values";
      if (count < 0 || uintmax_t(count) > left / 2)
        throw InputError(path, "NodeData " + name, declares + " but only " + std::to_string(left) + " bytes follow");
      if (count > INT32_MAX) throw InputError(path, "NodeData " + name, declares + "; gmsh reads at most 2147483647");
    }
    if (!in) break;
    // Keep a tail that can hold a marker and its header; drop the rest.
    const size_t keep = std::min(buf.size(), kDataHeader + 64);
    base += buf.size() - keep;
    buf.erase(0, buf.size() - keep);
  }
  // gmsh accepts a file cut inside the closing tag; a cut file is refused here.
  if (open_nodes && !end_nodes) throw InputError(path, "Nodes", "no $EndNodes: the file ends inside the section");
  if (open_elements && !end_elements)
    throw InputError(path, "Elements", "no $EndElements: the file ends inside the section");
}

}  // namespace vob

#include "datasets/io/inr_reader.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string_view>

#include "datasets/io/gzip_file.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
bool host_is_little() {
  const uint16_t one = 1;
  unsigned char b;
  std::memcpy(&b, &one, 1);
  return b == 1;
}

template <class T>
T load(const unsigned char* p, bool swap) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, p, sizeof(T));
  if (swap)
    for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
  T v;
  std::memcpy(&v, b, sizeof(T));
  return v;
}
}  // namespace

namespace {
VoxelGrid parse_inr(std::istream& in, const std::string& path) {
  // Header: whole 256-byte blocks until one ends with "##}\n".
  std::string header;
  char block[256];
  for (;;) {
    in.read(block, 256);
    if (in.gcount() != 256) throw InputError(path, "header", "file ends inside the header");
    header.append(block, 256);
    if (header.size() == 256 && header.rfind("#INRIMAGE-4#{", 0) != 0)
      throw InputError(path, "header", "does not start with #INRIMAGE-4#{ (not an INRIMAGE-4 file)");
    if (header.find("##}") != std::string::npos) break;
    if (header.size() > (1 << 20)) throw InputError(path, "header", "no ##} within 1 MB");
  }
  std::map<std::string, std::string> kv;
  std::istringstream hs(header.substr(0, header.find("##}")));
  std::string line;
  while (std::getline(hs, line)) {
    const auto eq = line.find('=');
    if (line.empty() || line[0] == '#' || eq == std::string::npos) continue;
    kv[line.substr(0, eq)] = line.substr(eq + 1);
  }
  auto integer = [&](const char* key, long def, bool required) {
    auto it = kv.find(key);
    if (it == kv.end()) {
      if (required) throw InputError(path, std::string("header ") + key, "is missing");
      return def;
    }
    long v = 0;  // the whole value, strictly: "4abc" or "4 " is not 4
    const auto [p, ec] = std::from_chars(it->second.data(), it->second.data() + it->second.size(), v);
    if (ec != std::errc() || p != it->second.data() + it->second.size() || v <= 0)
      throw InputError(path, std::string("header ") + key, "'" + it->second + "' is not a positive integer");
    return v;
  };
  auto real = [&](const char* key) {
    auto it = kv.find(key);
    if (it == kv.end()) return 1.0;
    char* end = nullptr;
    const double v = std::strtod(it->second.c_str(), &end);
    if (end == it->second.c_str() || *end != '\0' || !std::isfinite(v) || v <= 0)
      throw InputError(path, std::string("header ") + key, "'" + it->second + "' is not a positive number");
    return v;
  };
  VoxelGrid g;
  const long nx = integer("XDIM", 0, true), ny = integer("YDIM", 0, true), nz = integer("ZDIM", 1, false);
  if (integer("VDIM", 1, false) != 1)
    throw InputError(path, "header VDIM", "vector images (VDIM > 1) are not supported");
  if (double(nx) * ny * nz >= 2147483647.0) throw InputError(path, "header XDIM/YDIM/ZDIM", "more than 2^31 voxels");
  g.dims = {static_cast<int32_t>(nx), static_cast<int32_t>(ny), static_cast<int32_t>(nz)};
  g.spacing = {real("VX"), real("VY"), real("VZ")};
  const std::string type = kv.count("TYPE") ? kv["TYPE"] : "";
  const std::string pix = kv.count("PIXSIZE") ? kv["PIXSIZE"] : "";
  int bits = 0;  // "32 bits", strictly
  if (const auto [p, ec] = std::from_chars(pix.data(), pix.data() + pix.size(), bits);
      ec != std::errc() || std::string_view(p, pix.data() + pix.size() - p) != " bits")
    throw InputError(path, "header PIXSIZE", "'" + pix + "' is not '<n> bits'");
  const bool is_float = type == "float";
  const bool is_unsigned = type == "unsigned fixed";
  if (!is_float && !is_unsigned && type != "signed fixed")
    throw InputError(path, "header TYPE", "'" + type + "' is not unsigned fixed, signed fixed or float");
  if (is_float ? (bits != 32 && bits != 64) : (bits != 8 && bits != 16 && bits != 32))
    throw InputError(path, "header PIXSIZE", "'" + pix + "' is not supported for TYPE=" + type);
  const std::string cpu = kv.count("CPU") ? kv["CPU"] : "decm";
  bool little;
  if (cpu == "decm" || cpu == "pc" || cpu == "alpha")
    little = true;
  else if (cpu == "sun" || cpu == "sgi")
    little = false;
  else
    throw InputError(path, "header CPU", "'" + cpu + "' is not decm, pc, alpha, sun or sgi");
  const bool swap = little != host_is_little();

  const size_t n = g.num_voxels(), bytes = n * (bits / 8);
  // Check the size before allocating: a lying header must not exhaust memory.
  const std::streamoff data_start = in.tellg();
  in.seekg(0, std::ios::end);
  const std::streamoff available = in.tellg() - data_start;
  in.seekg(data_start);
  if (available < static_cast<std::streamoff>(bytes))
    throw InputError(path, "voxel " + std::to_string(available / (bits / 8)),
                     "file ends early: the header promises " + std::to_string(n) + " voxels of " +
                         std::to_string(bits) + " bits");
  std::vector<unsigned char> raw(bytes);
  in.read(reinterpret_cast<char*>(raw.data()), static_cast<std::streamsize>(bytes));
  if (static_cast<size_t>(in.gcount()) != bytes)
    throw InputError(path, "voxel " + std::to_string(in.gcount() / (bits / 8)),
                     "file ends early: the header promises " + std::to_string(n) + " voxels of " +
                         std::to_string(bits) + " bits");
  g.values.resize(n);
  const unsigned char* p = raw.data();
  for (size_t i = 0; i < n; ++i) {
    double v;
    if (is_float)
      v = bits == 32 ? load<float>(p + 4 * i, swap) : load<double>(p + 8 * i, swap);
    else if (bits == 8)
      v = is_unsigned ? double(p[i]) : double(static_cast<int8_t>(p[i]));
    else if (bits == 16)
      v = is_unsigned ? double(load<uint16_t>(p + 2 * i, swap)) : double(load<int16_t>(p + 2 * i, swap));
    else
      v = is_unsigned ? double(load<uint32_t>(p + 4 * i, swap)) : double(load<int32_t>(p + 4 * i, swap));
    g.values[i] = static_cast<float>(v);
  }
  return g;
}
}  // namespace

VoxelGrid read_inr(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "file", std::string("cannot be opened: ") + std::strerror(errno));
  return parse_inr(in, path);
}

VoxelGrid read_inr_gz(const std::string& path) {
  std::istringstream in(gunzip_file(path));
  return parse_inr(in, path);
}

}  // namespace vob

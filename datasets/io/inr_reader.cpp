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
// The header, the grid it describes (no values yet) and how its samples are stored.
struct InrHeader {
  VoxelGrid grid;
  size_t data_start = 0, bytes = 0;  // where the samples begin, and how many bytes they take
  int bits = 0;
  bool is_float = false, is_unsigned = false, swap = false;
};

InrHeader parse_header(std::istream& in, const std::string& path) {
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
    const auto [it, fresh] = kv.try_emplace(line.substr(0, eq), line.substr(eq + 1));
    if (!fresh)  // which one counts is not the reader's to guess
      throw InputError(path, "header " + it->first,
                       "is given twice ('" + it->second + "' and '" + line.substr(eq + 1) + "')");
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

  InrHeader h;
  h.data_start = static_cast<size_t>(in.tellg());
  h.bytes = g.num_voxels() * size_t(bits / 8);
  h.bits = bits;
  h.is_float = is_float;
  h.is_unsigned = is_unsigned;
  h.swap = swap;
  h.grid = std::move(g);
  return h;
}

// The samples must fill the file after the header exactly: fewer is a cut file, more means
// the header's dimensions are not the data's (a volume read as part of itself).
void check_data_size(const InrHeader& h, size_t available, const std::string& path) {
  const size_t each = size_t(h.bits / 8);
  const std::string promise = "the header promises " + std::to_string(h.grid.num_voxels()) + " voxels of " +
                              std::to_string(h.bits) + " bits";
  if (available < h.bytes)
    throw InputError(path, "voxel " + std::to_string(available / each), "file ends early: " + promise);
  if (available > h.bytes)
    throw InputError(path, "data", promise + " (" + std::to_string(h.bytes) +
                                       " bytes), but more data follows them (dimensions not the data's?)");
}

VoxelGrid decode(InrHeader h, const unsigned char* p, const std::string& path) {
  VoxelGrid g = std::move(h.grid);
  const size_t n = g.num_voxels();
  const int bits = h.bits;
  const bool is_float = h.is_float, is_unsigned = h.is_unsigned, swap = h.swap;
  g.values.resize(n);
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
    if (std::isfinite(v) && !std::isfinite(g.values[i]))  // a 64-bit float beyond float's range
      throw InputError(path, "voxel " + std::to_string(i), "value " + short_number(v) + " does not fit a 32-bit float");
  }
  return g;
}
}  // namespace

VoxelGrid read_inr(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "file", std::string("cannot be opened: ") + std::strerror(errno));
  InrHeader h = parse_header(in, path);
  // Check the size before allocating: a lying header must not exhaust memory.
  in.seekg(0, std::ios::end);
  const size_t available = static_cast<size_t>(in.tellg()) - h.data_start;
  check_data_size(h, available, path);
  in.seekg(static_cast<std::streamoff>(h.data_start));
  std::vector<unsigned char> raw(h.bytes);
  in.read(reinterpret_cast<char*>(raw.data()), static_cast<std::streamsize>(h.bytes));
  if (static_cast<size_t>(in.gcount()) != h.bytes) check_data_size(h, size_t(in.gcount()), path);
  return decode(std::move(h), raw.data(), path);
}

VoxelGrid read_inr_gz(const std::string& path) {
  // The header first (at most 1 MB), then only as many inflated bytes as it promises, and
  // one more: a small file inflating to far more than its header says is refused, not held.
  constexpr size_t kHeaderMost = (size_t(1) << 20) + 256;
  std::string text = gunzip_file(path, kHeaderMost);
  InrHeader h;
  {
    std::istringstream in(text);
    h = parse_header(in, path);
  }
  if (text.size() > kHeaderMost) text = gunzip_file(path, h.data_start + h.bytes);
  check_data_size(h, text.size() - h.data_start, path);
  return decode(std::move(h), reinterpret_cast<const unsigned char*>(text.data()) + h.data_start, path);
}

}  // namespace vob

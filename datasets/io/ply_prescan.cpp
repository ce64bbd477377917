#include "datasets/io/ply_prescan.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "harness/scene/input_error.h"

namespace vob {

namespace {
struct Property {
  std::string name;
  int size = 0;        // bytes of a scalar, or of each list item
  int count_size = 0;  // lists: bytes of the count (0: not a list)
  bool count_signed = false, count_float = false;  // lists: the count's type
  bool item_signed = false, item_float = false;  // lists: the items' type
};
struct Element {
  std::string name;
  long long count = 0;
  std::vector<Property> props;
};

int type_size(const std::string& t, bool* is_signed = nullptr, bool* is_float = nullptr) {
  static const std::map<std::string, std::pair<int, bool>> sizes{
      {"char", {1, true}},    {"int8", {1, true}},     {"uchar", {1, false}},  {"uint8", {1, false}},
      {"short", {2, true}},   {"int16", {2, true}},    {"ushort", {2, false}}, {"uint16", {2, false}},
      {"int", {4, true}},     {"int32", {4, true}},    {"uint", {4, false}},   {"uint32", {4, false}},
      {"float", {4, true}},   {"float32", {4, true}},  {"double", {8, true}},  {"float64", {8, true}}};
  const auto it = sizes.find(t);
  if (it == sizes.end()) return 0;
  if (is_signed) *is_signed = it->second.second;
  if (is_float) *is_float = t.rfind("float", 0) == 0 || t == "double";
  return it->second.first;
}

// A binary list item as VTK takes it (converted to int from its own type).
double item_value(const char* p, const Property& prop, bool swap) {
  unsigned char b[8] = {};
  for (int i = 0; i < prop.size; ++i) b[i] = static_cast<unsigned char>(p[swap ? prop.size - 1 - i : i]);
  if (prop.item_float) {
    if (prop.size == 4) {
      float f;
      std::memcpy(&f, b, 4);
      return f;
    }
    double d;
    std::memcpy(&d, b, 8);
    return d;
  }
  uint64_t u = 0;
  for (int i = prop.size - 1; i >= 0; --i) u = (u << 8) | b[i];
  if (prop.item_signed && (b[prop.size - 1] & 0x80)) return double(int64_t(u) - (int64_t(1) << (8 * prop.size)));
  return double(u);
}
}  // namespace

void prescan_ply(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || (line != "ply" && line != "ply\r"))
    throw InputError(path, "header", "does not start with the line 'ply' (not a PLY file)");
  std::string format;
  std::vector<Element> elements;
  for (int n = 1;; ++n) {
    if (!std::getline(in, line)) throw InputError(path, "header", "no end_header line");
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream ls(line);
    std::string key;
    ls >> key;
    if (key == "end_header") break;
    if (key == "comment" || key == "obj_info" || key.empty()) continue;
    const std::string where = "header line " + std::to_string(n + 1);
    if (key == "format") {
      ls >> format;
      if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
        throw InputError(path, where, "format '" + format + "' is not ascii or binary_*_endian");
    } else if (key == "element") {
      Element e;
      if (!(ls >> e.name >> e.count) || e.count < 0) throw InputError(path, where, "expected 'element NAME COUNT'");
      elements.push_back(e);
    } else if (key == "property") {
      if (elements.empty()) throw InputError(path, where, "property before any element");
      std::string t;
      ls >> t;
      Property p;
      if (t == "list") {
        std::string ct, it;
        ls >> ct >> it;
        p.count_size = type_size(ct, &p.count_signed, &p.count_float);
        p.size = type_size(it, &p.item_signed, &p.item_float);
        if (!p.count_size || !p.size) throw InputError(path, where, "unknown list types '" + ct + " " + it + "'");
      } else if (!(p.size = type_size(t))) {
        throw InputError(path, where, "unknown property type '" + t + "'");
      }
      ls >> p.name;
      elements.back().props.push_back(p);
    } else {
      throw InputError(path, where, "unknown keyword '" + key + "'");
    }
  }
  if (format.empty()) throw InputError(path, "header", "no format line");
  // What VTK's reader takes from the header without checking: without scalar x, y and z its
  // points are unset (SIGSEGV), and without the faces' index list it frees an unset pointer
  // (abort). It takes the list by two names, and the vertices must come first.
  const auto is_index_name = [](const std::string& n) { return n == "vertex_indices" || n == "vertex_index"; };
  bool seen_vertex = false;
  for (const Element& e : elements) {
    seen_vertex |= e.name == "vertex";
    if (e.name == "face" && !seen_vertex)  // it sets up each polygon with the points it has read (SIGSEGV)
      throw InputError(path, "element face", "comes before element vertex (VTK's PLY reader needs the vertices first)");
    if (e.name == "vertex")
      for (const char* axis : {"x", "y", "z"}) {
        const auto it = std::find_if(e.props.begin(), e.props.end(), [&](const Property& p) { return p.name == axis; });
        if (it == e.props.end() || it->count_size)
          throw InputError(path, "element vertex", std::string("no scalar property '") + axis +
                                                       "' (the points need x, y and z)");
      }
    if (e.name == "face" && std::none_of(e.props.begin(), e.props.end(), [&](const Property& p) {
          return p.count_size && is_index_name(p.name);
        }))
      throw InputError(path, "element face", "no list property 'vertex_indices' or 'vertex_index' (the polygons' points)");
  }
  const std::streamoff start = in.tellg();
  in.seekg(0, std::ios::end);
  const std::streamoff bytes = in.tellg() - start;
  in.seekg(start);
  for (const Element& e : elements)  // every instance takes at least a byte: no huge loops
    if (e.count > bytes) throw InputError(path, "element " + e.name, std::to_string(e.count) + " instances do not fit in the file");
  // VTK's reader takes the faces' "vertex_indices" as ids into the vertices, unchecked: a
  // large one makes it read far past its points (SIGSEGV).
  long long vertices = 0;
  for (const Element& e : elements)
    if (e.name == "vertex") vertices = e.count;
  const auto is_index_list = [&](const Element& e, const Property& p) {
    return e.name == "face" && p.count_size && is_index_name(p.name);
  };
  // VTK keeps a polygon's vertex count in a byte: a longer polygon would be read cut short.
  constexpr long long kMaxPolygon = 255;
  const auto check_polygon = [&](long long n, const std::string& where) {
    if (n > kMaxPolygon)
      throw InputError(path, where, "polygon of " + std::to_string(n) + " points (VTK's PLY reader keeps at most " +
                                        std::to_string(kMaxPolygon) + ")");
  };
  const auto check_index = [&](double v, const std::string& where) {
    if (!(v > -1 && v < double(vertices)))  // VTK truncates to int
      throw InputError(path, where, "vertex index " +  // cast only where defined (NaN, huge floats)
                                        (std::abs(v) < 9e18 ? std::to_string(static_cast<long long>(v)) : std::to_string(v)) +
                                        " is out of range (" + std::to_string(vertices) + " vertices)");
  };
  const bool ascii = format == "ascii";
  const bool swap = format == "binary_big_endian";  // hosts here are little endian
  if (ascii) {
    // VTK reads an ASCII element instance as one line of words: each line must hold exactly
    // the instance's numbers (a list: its count, then that many).
    std::string text;
    for (const Element& e : elements)
      for (long long i = 0; i < e.count; ++i) {
        const std::string where = e.name + " " + std::to_string(i);
        do {
          if (!std::getline(in, text)) throw InputError(path, where, "file ends early");
        } while (text.find_first_not_of(" \t\r") == std::string::npos);
        std::istringstream words(text);
        std::string token;
        auto number = [&]() {
          if (!(words >> token)) throw InputError(path, where, "line has too few numbers");
          char* end = nullptr;
          const double v = std::strtod(token.c_str(), &end);
          if (*end != '\0' || !std::isfinite(v)) throw InputError(path, where, "'" + token + "' is not a finite number");
          return v;
        };
        for (const Property& p : e.props) {
          double n = 1;
          if (p.count_size) {
            n = number();
            if (n < 0 || n != std::floor(n) || n > double(bytes))
              throw InputError(path, where, "list count '" + token + "' is not a valid count");
          }
          const bool indices = is_index_list(e, p);
          if (indices) check_polygon(static_cast<long long>(n), where);
          for (long long k = 0; k < static_cast<long long>(n); ++k) {
            const double v = number();
            if (indices) check_index(v, where);
          }
        }
        if (words >> token) throw InputError(path, where, "line has more numbers than the header declares");
      }
    return;
  }
  std::vector<char> buf(8);
  // A list count in its own type (any of the eight, as VTK converts it): a whole number from
  // 0 to the file's size.
  auto binary_count = [&](const Property& p, const std::string& where) -> long long {
    if (!in.read(buf.data(), p.count_size)) throw InputError(path, where, "file ends early");
    Property count;
    count.size = p.count_size, count.item_signed = p.count_signed, count.item_float = p.count_float;
    const double v = item_value(buf.data(), count, swap);
    if (!(v >= 0 && v <= double(bytes)) || v != std::floor(v)) {
      std::ostringstream text;
      text << v;
      throw InputError(path, where, "list count " + text.str() + " is not a valid count");
    }
    return static_cast<long long>(v);
  };
  for (const Element& e : elements)
    for (long long i = 0; i < e.count; ++i) {
      const std::string where = e.name + " " + std::to_string(i);
      for (const Property& p : e.props) {
        long long n = 1;
        if (p.count_size) {
          n = binary_count(p, where);
        }
        if (is_index_list(e, p)) {
          check_polygon(n, where);
          // Bounded by the bytes left before the buffer grows: a bogus count is refused, not allocated.
          if (n * p.size > bytes - (in.tellg() - start)) throw InputError(path, where, "file ends early");
          if (buf.size() < size_t(n * p.size)) buf.resize(size_t(n * p.size));
          if (!in.read(buf.data(), n * p.size)) throw InputError(path, where, "file ends early");
          for (long long k = 0; k < n; ++k) check_index(item_value(buf.data() + k * p.size, p, swap), where);
        } else if (!in.seekg(n * p.size, std::ios::cur) || in.tellg() - start > bytes) {
          throw InputError(path, where, "file ends early");
        }
      }
    }
}

}  // namespace vob

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <string_view>
#include <vector>

#include <vtkCellType.h>

#include "datasets/io/file_util.h"
#include "datasets/io/vtk_prescan.h"
#include "datasets/io/vtk_prescan_text.h"
#include "harness/scene/input_error.h"

namespace vob {

using namespace vtk_prescan;

namespace {
// The file's text up to `stop` (exclusive), read in chunks so that a large appended
// binary section is never held in memory.
std::string text_before(const std::string& path, std::string_view stop) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "file", "cannot be opened");
  std::string text;
  std::vector<char> buf(1 << 20);
  while (in) {
    in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
    const size_t from = text.size() >= stop.size() ? text.size() - stop.size() : 0;
    text.append(buf.data(), static_cast<size_t>(in.gcount()));
    if (const size_t at = text.find(stop, from); at != std::string::npos) {
      text.resize(at);
      break;
    }
  }
  return text;
}

struct Tag {
  std::string name;
  std::map<std::string, std::string> attrs;
};

// Attributes of a start tag's text (between '<' and '>'), name="value" or name='value'.
Tag parse_tag(std::string_view t) {
  Tag tag;
  size_t i = 0;
  while (i < t.size() && !std::isspace(static_cast<unsigned char>(t[i])) && t[i] != '/') ++i;
  tag.name = std::string(t.substr(0, i));
  while (i < t.size()) {
    while (i < t.size() && (std::isspace(static_cast<unsigned char>(t[i])) || t[i] == '/')) ++i;
    const size_t nb = i;
    while (i < t.size() && t[i] != '=' && !std::isspace(static_cast<unsigned char>(t[i]))) ++i;
    const std::string name(t.substr(nb, i - nb));
    while (i < t.size() && std::isspace(static_cast<unsigned char>(t[i]))) ++i;
    if (i >= t.size() || t[i] != '=') continue;
    ++i;
    while (i < t.size() && std::isspace(static_cast<unsigned char>(t[i]))) ++i;
    if (i >= t.size() || (t[i] != '"' && t[i] != '\'')) break;
    const char q = t[i++];
    const size_t vb = i;
    while (i < t.size() && t[i] != q) ++i;
    tag.attrs[name] = std::string(t.substr(vb, i - vb));
    ++i;
  }
  return tag;
}

void check_numbers(const std::string& path, const Tag& tag, const char* attr, size_t n, bool integers) {
  const auto it = tag.attrs.find(attr);
  if (it == tag.attrs.end()) return;
  const std::string element = tag.name + " " + attr;
  const auto parts = split(it->second);
  if (parts.size() != n)
    throw InputError(path, element, "'" + it->second + "' needs " + std::to_string(n) +
                                        (integers ? " integers" : " numbers"));
  for (auto p : parts) {
    int64_t i = 0;
    double d = 0;
    if (integers ? !parse_int(p, i) || std::abs(i) > (int64_t(1) << 30) : !parse_finite(p, d))
      throw InputError(path, element, "'" + std::string(p) + "' is not " +
                                          (integers ? "an integer" : "a finite number"));
  }
}

// How a .vtu file stores binary data: VTKFile's byte_order, header_type and compressor.
struct BinaryLayout {
  bool little_endian = true;
  size_t word = 4;  // bytes of a header word (UInt32 or UInt64)
  bool compressed = false;
};

// Bytes of a DataArray's value type; 0 for a name not known here.
size_t value_bytes(const std::string& type) {
  if (type == "Int8" || type == "UInt8") return 1;
  if (type == "Int16" || type == "UInt16") return 2;
  if (type == "Int32" || type == "UInt32" || type == "Float32") return 4;
  if (type == "Int64" || type == "UInt64" || type == "Float64") return 8;
  return 0;
}

// The first `want` bytes base64 `text` decodes to (whitespace skipped), or fewer at its end.
std::string base64_head(std::string_view text, size_t want) {
  std::string out;
  uint32_t acc = 0;
  int bits = 0;
  for (const char c : text) {
    if (out.size() >= want || c == '=') break;
    const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const char* d = c ? std::strchr(digits, c) : nullptr;
    if (!d) continue;  // whitespace (anything else VTK reports)
    acc = acc << 6 | uint32_t(d - digits);
    if ((bits += 6) >= 8) out += char(acc >> (bits -= 8) & 0xFF);
  }
  return out;
}

// A binary or appended array's header (`head`, raw bytes): one word, the data's byte count,
// or for compressed data the block count, block size and last block's size.
bool header_words(const std::string& head, const BinaryLayout& f, uint64_t (&w)[3]) {
  const size_t words = f.compressed ? 3 : 1;
  if (head.size() < words * f.word) return false;
  for (size_t k = 0; k < 3; ++k) w[k] = 0;
  for (size_t k = 0; k < words; ++k)
    for (size_t b = 0; b < f.word; ++b) {
      const auto byte = uint64_t(static_cast<unsigned char>(head[k * f.word + (f.little_endian ? b : f.word - 1 - b)]));
      w[k] |= byte << (8 * b);
    }
  return true;
}

// The byte count of the (uncompressed) data from the header words.
uint64_t data_bytes(const BinaryLayout& f, const uint64_t (&w)[3]) {
  return !f.compressed ? w[0] : w[0] == 0 ? 0 : (w[0] - 1) * w[1] + (w[2] ? w[2] : w[1]);
}

bool data_bytes(const std::string& head, const BinaryLayout& f, uint64_t& bytes) {
  uint64_t w[3];
  if (!header_words(head, f, w)) return false;
  bytes = data_bytes(f, w);
  return true;
}

// A header's promises against `room`, the raw bytes its array can have from the header on
// (to the file's end, or in the element's base64 text). VTK takes a longer declared length
// on trust and reads what it needs (the file accepted silently), and allocates a compressed
// header's block count before reading it (2^31 blocks: 8 GB, then "Error reading
// compression header").
void check_data_header(const std::string& path, const std::string& element, const std::string& head,
                       const BinaryLayout& f, uint64_t room) {
  uint64_t w[3];
  if (!header_words(head, f, w)) return;  // VTK reports a header cut short
  const auto follow = "but only " + std::to_string(room) + " bytes follow it";
  if (!f.compressed) {
    if (w[0] > room || w[0] + f.word > room)
      throw InputError(path, element, "its header declares " + std::to_string(w[0]) + " bytes of data, " + follow);
    return;
  }
  if (w[0] > room / f.word || (3 + w[0]) * f.word > room)
    throw InputError(path, element, "its header declares " + std::to_string(w[0]) + " compressed blocks, " + follow);
  const uint64_t bytes = data_bytes(f, w);
  if (static_cast<double>(bytes) > static_cast<double>(room) * kMaxCompressionRatio ||
      (w[0] > 1 && w[1] > std::numeric_limits<uint64_t>::max() / (w[0] - 1)))
    throw InputError(path, element, "its header declares " + std::to_string(bytes) + " bytes uncompressed, more than the " +
                                        std::to_string(room) + " bytes that follow it can hold (" +
                                        std::to_string(int(kMaxCompressionRatio)) + " to 1 at most)");
}

// Raw bytes that `chars` of base64 text decode to at most.
uint64_t base64_room(uint64_t chars) { return (chars + 3) / 4 * 3; }

// A Cells array's value type. Connectivity, offsets and types are integers: VTK casts a
// Float32/Float64 array to ids (3.5 read as 3) and cell type codes the same way.
void check_cell_array_type(const std::string& path, const std::string& name, const std::string& type) {
  const bool integer = type == "Int8" || type == "UInt8" || type == "Int16" || type == "UInt16" ||
                       type == "Int32" || type == "UInt32" || type == "Int64" || type == "UInt64";
  if (integer) return;
  const bool real = type == "Float32" || type == "Float64";
  throw InputError(path, "Cells DataArray '" + name + "'",
                   "type '" + type + "' is not an integer type (Int8 to UInt64" +
                       (real ? "; VTK would cast 3.5 to 3)" : ")"));
}

// An ASCII 8-bit array's values within its type: VTK reads each as a wider integer and
// narrows it unchecked ("260" in a UInt8 connectivity read as point 4). Binary 8-bit arrays
// cannot hold such values; wider ASCII ones fail in VTK's own reader.
void check_ascii_byte_range(const std::string& path, const std::string& name, const std::string& type,
                            std::string_view data) {
  if (type != "Int8" && type != "UInt8") return;
  const int64_t lo = type == "Int8" ? -128 : 0, hi = type == "Int8" ? 127 : 255;
  uint64_t n = 0;
  for (const std::string_view w : split(data)) {
    int64_t v = 0;
    if (parse_int(w, v) && (v < lo || v > hi))
      throw InputError(path, "Cells DataArray '" + name + "'",
                       "value " + std::to_string(n) + " (" + std::string(w.substr(0, 40)) + ") is outside " + type +
                           " (" + std::to_string(lo) + " to " + std::to_string(hi) + "; VTK would narrow it)");
    ++n;
  }
}

// A Cells array ("offsets" or "types") must hold one value per cell: VTK reads NumberOfCells
// of them and ignores the rest (NumberOfCells="1" over two cells read one, silently).
void check_cell_count(const std::string& path, const std::string& name, uint64_t held, uint64_t cells) {
  if (held != cells)
    throw InputError(path, "Cells DataArray '" + name + "'",
                     "its value count " + std::to_string(held) + " differs from the Piece's NumberOfCells " +
                         std::to_string(cells));
}

// An ASCII "offsets" or "types" array: its values counted, types range-checked (VTK keeps a
// type in a byte: "266" in a UInt8 array was read as 10, a tetra).
void check_ascii_cells(const std::string& path, const std::string& name, std::string_view data, uint64_t cells) {
  uint64_t n = 0;
  for (const std::string_view w : split(data)) {
    int64_t type = 0;
    if (name == "types" && (!parse_int(w, type) || type < 0 || type >= VTK_NUMBER_OF_CELL_TYPES))
      throw InputError(path, "Cells DataArray 'types'", "cell " + std::to_string(n) + ": type '" +
                                                             std::string(w.substr(0, 40)) + "' is not a VTK cell type");
    ++n;
  }
  check_cell_count(path, name, n, cells);
}

// An image's point or cell array must hold one tuple per point or cell of its Piece's
// extent: VTK read 10 ASCII values into 8 points and ignored the rest, silently.
void check_image_values(const std::string& path, const std::string& element, const std::string& parent,
                        double held, double want, const char* what) {
  if (held != want)
    throw InputError(path, element, "holds " + std::to_string(uint64_t(held)) + " " + what + ", but its Piece's extent has " +
                                        std::to_string(uint64_t(want)) + " (" +
                                        (parent == "PointData" ? "points" : "cells") + " times components)");
}

struct AppendedArray {
  std::string element, name;  // element as errors name it; a Cells array's name
  uint64_t offset, value_bytes;
  int64_t cells;  // for "offsets" and "types": the Piece's NumberOfCells; else -1
  std::string parent;  // the tag it sits in
  double image_values;  // an image's point or cell array: the values its extent needs; else -1
};

// Arrays in <AppendedData> (which starts at byte `at`): each one's header read at its offset
// past the '_', raw or base64 as the section's encoding says, checked against the bytes
// after it and, for counted Cells arrays, NumberOfCells; an image's point and cell arrays
// against the values its extent needs, as inline ones.
void check_appended(const std::string& path, uint64_t at, const BinaryLayout& layout,
                    const std::vector<AppendedArray>& arrays) {
  const uint64_t size = file_size(path);
  std::ifstream in(path, std::ios::binary);
  std::string tag(4096, '\0');
  in.seekg(std::streamoff(at));
  in.read(tag.data(), std::streamsize(tag.size()));
  tag.resize(size_t(in.gcount()));
  const size_t close = tag.find('>');
  const size_t mark = close == std::string::npos ? close : tag.find('_', close);
  if (mark == std::string::npos) return;  // VTK reports it
  const Tag t = parse_tag(std::string_view(tag).substr(1, close - 1));
  const bool base64 = t.attrs.count("encoding") && t.attrs.at("encoding") == "base64";
  const size_t want = 3 * layout.word;
  for (const AppendedArray& a : arrays) {
    std::string head(base64 ? want * 4 / 3 + 4 : want, '\0');
    const uint64_t from = at + mark + 1 + a.offset;
    if (from >= size) continue;  // VTK reports it
    in.clear();
    in.seekg(std::streamoff(from));
    in.read(head.data(), std::streamsize(head.size()));
    head.resize(size_t(in.gcount()));
    if (base64) head = base64_head(head, want);
    check_data_header(path, a.element, head, layout, base64 ? base64_room(size - from) : size - from);
    uint64_t bytes = 0;
    if (a.cells >= 0 && data_bytes(head, layout, bytes))
      check_cell_count(path, a.name, bytes / a.value_bytes, uint64_t(a.cells));
    if (a.image_values >= 0 && a.value_bytes > 0 && data_bytes(head, layout, bytes))
      check_image_values(path, a.element, a.parent, double(bytes / a.value_bytes), a.image_values,
                         "values (by its header)");
  }
}

// Points of an extent "x0 x1 y0 y1 z0 z1" (already checked to hold 6 integers).
double extent_points(const std::string& path, const std::string& element, const std::string& text) {
  const auto parts = split(text);
  double n = 1;
  for (int a = 0; a < 3; ++a) {
    int64_t lo = 0, hi = 0;
    parse_int(parts[2 * a], lo);
    parse_int(parts[2 * a + 1], hi);
    if (hi < lo)
      throw InputError(path, element, "'" + text + "' has an upper bound below its lower bound");
    n *= static_cast<double>(hi - lo + 1);
  }
  return n;
}

}  // namespace

void prescan_vtk_xml(const std::string& path, const std::string& expected_type) {
  // Before the text is read whole (a 3 GB file of NUL bytes took 4.5 GB).
  require_file_start(path, {"<?xml", "<VTKFile", "<!--", "\xEF\xBB\xBF<"}, true, "VTK XML", "<?xml or <VTKFile");
  const double bytes = static_cast<double>(file_size(path));
  const std::string text = text_before(path, "<AppendedData");
  double budget = bytes;
  int depth = 0;
  size_t i = 0;
  BinaryLayout layout;
  int64_t piece_cells = -1;  // the current Piece's NumberOfCells
  // ImageData: the WholeExtent's text and the current Piece's point and cell counts.
  std::string whole_extent;
  double image_points = -1, image_cells = -1;
  // Values a PointData or CellData array of the current image Piece must hold; -1: not one.
  const auto image_values = [&](const std::string& parent, uint64_t comps) {
    if (expected_type != "ImageData" || image_points < 0) return -1.0;
    if (parent == "PointData") return image_points * double(comps);
    if (parent == "CellData") return image_cells * double(comps);
    return -1.0;
  };
  bool in_cells = false;
  std::vector<std::string> open;        // the open tags' names (errors name an array's parent)
  std::vector<AppendedArray> appended;  // arrays in <AppendedData>, checked after the tags
  while ((i = text.find('<', i)) != std::string::npos) {
    if (text.compare(i, 4, "<!--") == 0) {
      const size_t e = text.find("-->", i);
      if (e == std::string::npos) throw InputError(path, "XML", "comment is not closed");
      i = e + 3;
      continue;
    }
    const size_t e = text.find('>', i);
    if (e == std::string::npos)
      throw InputError(path, "XML byte " + std::to_string(i), "tag is not closed");
    const std::string_view body(text.data() + i + 1, e - i - 1);
    i = e + 1;
    if (body.empty() || body[0] == '?' || body[0] == '!') continue;
    if (body[0] == '/') {
      --depth;
      if (!open.empty()) open.pop_back();
      if (body.substr(1, 5) == "Cells") in_cells = false;
      continue;
    }
    const bool closed = body.back() == '/';
    if (!closed && ++depth > kMaxXmlDepth)
      throw InputError(path, "XML byte " + std::to_string(i - body.size() - 2),
                       "tags nest deeper than " + std::to_string(kMaxXmlDepth) + " levels");
    const Tag tag = parse_tag(body);
    const std::string parent = open.empty() ? "" : open.back();
    if (!closed) open.push_back(tag.name);
    if (tag.name == "VTKFile") {
      const auto t = tag.attrs.find("type");
      if (t == tag.attrs.end() || t->second != expected_type)
        throw InputError(path, "VTKFile type", "'" + (t == tag.attrs.end() ? "" : t->second) +
                                                  "' is not " + expected_type);
      if (tag.attrs.count("compressor")) budget = bytes * kMaxCompressionRatio;
      layout.compressed = tag.attrs.count("compressor") > 0;
      layout.little_endian = !tag.attrs.count("byte_order") || tag.attrs.at("byte_order") != "BigEndian";
      layout.word = tag.attrs.count("header_type") && tag.attrs.at("header_type") == "UInt64" ? 8 : 4;
    }
    if (tag.name == "Cells") in_cells = !closed;
    if (tag.name == "Piece") {
      if (auto a = tag.attrs.find("NumberOfPoints"); a != tag.attrs.end())
        count(path, "Piece NumberOfPoints", a->second, budget / 3, "point count");
      piece_cells = -1;
      if (auto a = tag.attrs.find("NumberOfCells"); a != tag.attrs.end())
        piece_cells = int64_t(count(path, "Piece NumberOfCells", a->second, budget, "cell count"));
    }
    if (tag.name == "DataArray") {
      const auto a = tag.attrs.find("NumberOfTuples");
      const auto c = tag.attrs.find("NumberOfComponents");
      const std::string name = tag.attrs.count("Name") ? tag.attrs.at("Name") : "?";
      const uint64_t comps = c == tag.attrs.end() ? 1
                             : count(path, "DataArray " + name + " NumberOfComponents", c->second, budget, "component count");
      if (a != tag.attrs.end())
        count(path, "DataArray " + name + " NumberOfTuples", a->second,
              budget / static_cast<double>(std::max<uint64_t>(comps, 1)), "tuple count");
      const auto f = tag.attrs.find("format");
      const std::string type = tag.attrs.count("type") ? tag.attrs.at("type") : "";
      const size_t each = value_bytes(type);
      if (in_cells && (name == "connectivity" || name == "offsets" || name == "types"))
        check_cell_array_type(path, name, type);
      const bool counted = in_cells && piece_cells >= 0 && (name == "offsets" || name == "types") && each > 0;
      const std::string element = parent + " DataArray" + (tag.attrs.count("Name") ? " '" + name + "'" : "");
      const std::string_view data = closed ? std::string_view() : std::string_view(text).substr(i, text.find('<', i) - i);
      if (f == tag.attrs.end()) {
        // VTK reports a missing format
      } else if (f->second == "ascii") {
        if (in_cells && (name == "connectivity" || name == "offsets")) check_ascii_byte_range(path, name, type, data);
        if (counted) check_ascii_cells(path, name, data, uint64_t(piece_cells));
        if (const double want = image_values(parent, comps); want >= 0)
          check_image_values(path, element, parent, double(split(data).size()), want, "values");
      } else if (f->second == "binary") {
        const std::string head = base64_head(data, 3 * layout.word);
        check_data_header(path, element, head, layout, base64_room(data.size()));
        uint64_t held = 0;
        if (counted && data_bytes(head, layout, held)) check_cell_count(path, name, held / each, uint64_t(piece_cells));
        if (const double want = image_values(parent, comps); want >= 0 && each > 0 && data_bytes(head, layout, held))
          check_image_values(path, element, parent, double(held / each), want, "values (by its header)");
      } else if (f->second == "appended" && tag.attrs.count("offset")) {
        int64_t offset = 0;
        if (parse_int(tag.attrs.at("offset"), offset) && offset >= 0)
          appended.push_back({element, name, uint64_t(offset), each, counted ? piece_cells : -1, parent,
                              image_values(parent, comps)});
      }
    }
    if (tag.name == "ImageData" || tag.name == "Piece") {
      const char* ext = tag.name == "ImageData" ? "WholeExtent" : "Extent";
      check_numbers(path, tag, ext, 6, true);
      check_numbers(path, tag, "Origin", 3, false);
      check_numbers(path, tag, "Spacing", 3, false);
      check_numbers(path, tag, "Direction", 9, false);
      if (auto a = tag.attrs.find(ext); a != tag.attrs.end() &&
                                        extent_points(path, tag.name + " " + ext, a->second) > budget)
        throw InputError(path, tag.name + " " + ext,
                         "'" + a->second + "' promises more points than a file of this size can hold");
      // An image is read as one piece covering the WholeExtent: VTK read a Piece with another
      // Extent without a word (its values placed in the whole extent's grid).
      if (expected_type == "ImageData" && tag.attrs.count(ext)) {
        const auto ints = [](const std::string& t) {
          std::vector<int64_t> v;
          for (const std::string_view w : split(t)) parse_int(w, v.emplace_back());
          return v;
        };
        if (tag.name == "ImageData") {
          whole_extent = tag.attrs.at(ext);
        } else if (parent == "ImageData") {
          if (!whole_extent.empty() && ints(tag.attrs.at(ext)) != ints(whole_extent))
            throw InputError(path, "Piece Extent", "'" + tag.attrs.at(ext) + "' is not the WholeExtent '" + whole_extent +
                                                       "' (an image is read as one piece covering its whole extent)");
          const auto e = ints(tag.attrs.at(ext));
          image_points = image_cells = 1;
          for (int a = 0; a < 3; ++a) {
            const double n = double(e[2 * a + 1] - e[2 * a] + 1);
            image_points *= n;
            image_cells *= n > 1 ? n - 1 : 1;
          }
        }
      }
    }
  }
  if (!appended.empty()) check_appended(path, text.size(), layout, appended);
}

}  // namespace vob

#include <algorithm>
#include <cctype>
#include <climits>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <fstream>
#include <limits>
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
// Integers from a stream through a buffer (`in >> v` per value cost more than VTK's own read
// of a large file): ASCII words as `>>` reads them (sign, digits, stopping at anything
// else), or big-endian 32-bit values. finish() puts the stream just past the last one read.
class ValueReader {
 public:
  ValueReader(std::istream& in, bool binary) : in_(in), binary_(binary), start_(in.tellg()) {}
  bool next(int64_t& v) {
    if (binary_) {
      if (!fill(4)) return false;
      const auto* b = reinterpret_cast<const unsigned char*>(buf_.data() + pos_);
      pos_ += 4;
      v = static_cast<int32_t>(uint32_t(b[0]) << 24 | uint32_t(b[1]) << 16 | uint32_t(b[2]) << 8 | uint32_t(b[3]));
      return true;
    }
    for (;;) {  // whitespace, across refills
      while (pos_ < end_ && std::isspace(static_cast<unsigned char>(buf_[pos_]))) ++pos_;
      if (pos_ < end_ || !fill(1)) break;
    }
    if (!fill(kLongestWord)) fill(1);  // a word whole in the buffer (or the file's last bytes)
    const char* b = buf_.data() + pos_;
    const char* e = buf_.data() + end_;
    if (b < e && *b == '+' && b + 1 < e && *(b + 1) != '-') ++b;
    long long x = 0;
    const auto [p, ec] = std::from_chars(b, e, x);
    if (ec != std::errc()) return false;
    pos_ = static_cast<size_t>(p - buf_.data());
    v = x;
    return true;
  }
  // The next word of an ASCII file (valid until the next call); false at the file's end.
  bool word(std::string_view& w) {
    for (;;) {
      while (pos_ < end_ && std::isspace(static_cast<unsigned char>(buf_[pos_]))) ++pos_;
      if (pos_ < end_ || !fill(1)) break;
    }
    if (pos_ >= end_) return false;
    size_t have = 0;
    for (;;) {  // a word cut by the buffer's end: read more
      while (pos_ + have < end_ && !std::isspace(static_cast<unsigned char>(buf_[pos_ + have]))) ++have;
      if (pos_ + have < end_ || !fill(have + 1)) break;
    }
    w = std::string_view(buf_.data() + pos_, have);
    pos_ += have;
    return true;
  }
  // Line breaks read over so far (for naming the line of the last word).
  size_t breaks() const {
    return breaks_ + size_t(std::count(buf_.begin(), buf_.begin() + static_cast<std::ptrdiff_t>(pos_), '\n'));
  }
  // Returns the line breaks read over (the caller's line count goes on from them).
  size_t finish() {
    in_.clear();
    in_.seekg(start_ + std::streamoff(consumed_ + pos_));
    return breaks_ + size_t(std::count(buf_.begin(), buf_.begin() + static_cast<std::ptrdiff_t>(pos_), '\n'));
  }

 private:
  static constexpr size_t kLongestWord = 32, kChunk = size_t(1) << 20;
  // At least n unread bytes in the buffer, reading more if needed; false at the file's end.
  bool fill(size_t n) {
    if (end_ - pos_ >= n) return true;
    breaks_ += size_t(std::count(buf_.begin(), buf_.begin() + static_cast<std::ptrdiff_t>(pos_), '\n'));
    buf_.erase(buf_.begin(), buf_.begin() + static_cast<std::ptrdiff_t>(pos_));
    consumed_ += pos_;
    end_ -= pos_;
    pos_ = 0;
    buf_.resize(end_ + kChunk);
    in_.read(buf_.data() + end_, static_cast<std::streamsize>(kChunk));
    end_ += static_cast<size_t>(in_.gcount());
    buf_.resize(end_);
    return end_ - pos_ >= n;
  }
  std::istream& in_;
  bool binary_;
  std::streampos start_;
  std::vector<char> buf_;
  size_t pos_ = 0, end_ = 0, consumed_ = 0, breaks_ = 0;
};

// The cell list before format 5.1: `cells` records "k id_1 .. id_k" in `size` values (ASCII
// words, or big-endian 32-bit integers in a binary file), which VTK walks unchecked: a
// negative or too large k writes past its arrays (heap corruption). 5.1 files give OFFSETS
// and CONNECTIVITY instead, whose cells are checked after reading.
size_t walk_legacy_cells(std::istream& in, const std::string& path, const std::string& where, uint64_t cells,
                         uint64_t size, bool binary) {
  ValueReader values(in, binary);
  const auto next = [&]() -> int64_t {
    int64_t v = 0;
    if (!values.next(v))
      throw InputError(path, where, binary ? "the cell list ends early"
                                           : "the cell list ends early or holds a word that is not an integer");
    return v;
  };
  uint64_t used = 0;
  for (uint64_t c = 0; c < cells; ++c) {
    const int64_t k = next();
    ++used;
    if (k < 0 || used > size || static_cast<uint64_t>(k) > size - used)
      throw InputError(path, where, "cell " + std::to_string(c) + ": point count " + std::to_string(k) +
                                        " does not fit the list's " + std::to_string(size) + " values");
    for (int64_t j = 0; j < k; ++j) {
      // VTK reads the list into 32-bit ints: a larger index ended in "Error reading ascii
      // cell data!" (negative ones are named after reading).
      const int64_t id = next();
      if (id > INT32_MAX)
        throw InputError(path, where, "cell " + std::to_string(c) + ": point index " + std::to_string(id) +
                                          " is beyond 2147483647 (VTK reads these lists as 32-bit integers)");
    }
    used += static_cast<uint64_t>(k);
  }
  if (used != size)
    throw InputError(path, where, std::to_string(cells) + " cells use " + std::to_string(used) + " of the list's " +
                                      std::to_string(size) + " values");
  return values.finish();
}

// CELL_TYPES' `n` values (ASCII words or big-endian 32-bit integers): VTK keeps a cell's
// type in a byte, so type 266 became 10 (a tetra), and 9999 was reported as type 15.
size_t walk_cell_types(std::istream& in, const std::string& path, const std::string& where, uint64_t n,
                       bool binary) {
  ValueReader values(in, binary);
  for (uint64_t c = 0; c < n; ++c) {
    int64_t type = 0;
    if (!values.next(type))
      throw InputError(path, where, binary ? "the type list ends after " + std::to_string(c) + " of its " +
                                                 std::to_string(n) + " values"
                                           : "the type list ends early or holds a word that is not an integer");
    if (type < 0 || type >= VTK_NUMBER_OF_CELL_TYPES)
      throw InputError(path, where, "cell " + std::to_string(c) + ": type " + std::to_string(type) +
                                        " is not a VTK cell type");
  }
  return values.finish();
}

// A legacy keyword: capitals and '_' ("NAN" and "INF" are numbers to `>>`'s eye, if not finite).
bool is_keyword(std::string_view w) {
  std::string lower;
  for (const char c : w) {
    if (!std::isupper(static_cast<unsigned char>(c)) && c != '_') return false;
    lower += char(std::tolower(static_cast<unsigned char>(c)));
  }
  return !w.empty() && lower != "nan" && lower != "inf" && lower != "infinity";
}

// `n` ASCII numbers after line `line` (point coordinates, or scalars): VTK reads them with
// `>>`, which stops at "nan", "inf" or a word that is no number, and says only "Error reading
// ascii data". Each must be a finite number (within float's range for float data). An item
// (point, cell) holds `per` of them; `what` names the values.
size_t walk_ascii_reals(std::istream& in, const std::string& path, const std::string& where, int64_t line,
                        uint64_t n, uint64_t per, const char* item, const std::string& what, bool as_float) {
  ValueReader values(in, false);
  std::string_view w;
  for (uint64_t i = 0; i < n; ++i) {
    if (!values.word(w))
      throw InputError(path, where, "the file ends after " + std::to_string(i) + " of its " + std::to_string(n) +
                                        " values");
    double v = 0;
    const bool finite = parse_finite(w, v);
    if (finite && !(as_float && std::abs(v) > std::numeric_limits<float>::max())) continue;
    const std::string at = "line " + std::to_string(line + 1 + int64_t(values.breaks()));
    if (is_keyword(w))  // the values end early
      throw InputError(path, where, "holds " + std::to_string(i) + " of its " + std::to_string(n) + " values, then '" +
                                        std::string(w.substr(0, 40)) + "' at " + at);
    throw InputError(path, std::string(item) + " " + std::to_string(i / per) + " (" + at + ")",
                     what + " is '" + std::string(w.substr(0, 40)) + "', " +
                         (finite ? "beyond float's range" : "not a finite number"));
  }
  return values.finish();
}
}  // namespace

void prescan_vtk_legacy(const std::string& path) {
  // VTK requires it of the first line; checked before the lines are read.
  require_file_start(path, {"# vtk DataFile Version"}, false, "legacy VTK", "'# vtk DataFile Version'");
  const double bytes = static_cast<double>(file_size(path));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "file", "cannot be opened");
  // Keyword lines are ASCII lines of their own, also in binary files; a line of binary data
  // that happens to start with a keyword would need the exact spelling below.
  std::string line;
  int64_t number = 0;
  bool binary = false;
  bool cell_lists = true;  // cells as "k id_1 .. id_k" lists: VTK reads them so below version 5.1
  // An unstructured grid's CELLS and CELL_TYPES must agree: VTK reads CELL_TYPES' own count
  // and leaves the other cells' types uninitialised (a real tet dropped at random).
  std::string cells_at, types_at;  // "CELLS (line N)", or "" until seen
  uint64_t cells_count = 0, types_count = 0;
  uint64_t data_count = 0;            // of the last POINT_DATA or CELL_DATA
  const char* data_item = nullptr;    // "point" or "cell" after one of them
  const auto agree = [&] {
    if (!cells_at.empty() && !types_at.empty() && cells_count != types_count)
      throw InputError(path, types_at, "type count " + std::to_string(types_count) + " differs from the cell count " +
                                           std::to_string(cells_count) + " of " + cells_at);
  };
  while (std::getline(in, line)) {
    ++number;
    if (number == 1) {  // "# vtk DataFile Version M.m": VTK takes what it cannot read as 0.0
      int major = 0, minor = 0;
      const size_t at = line.find("Version");
      if (at != std::string::npos) std::sscanf(line.c_str() + at + 7, "%d.%d", &major, &minor);
      cell_lists = major < 5 || (major == 5 && minor < 1);
    }
    if (number == 3) binary = line.rfind("BINARY", 0) == 0;  // the header's third line: ASCII or BINARY
    if (line.size() > 256 || line.empty() || !std::isupper(static_cast<unsigned char>(line[0]))) continue;
    const auto t = split(line);
    const std::string key(t[0]);
    // VTK matches keywords by prefix; "POINTS\x01" or "POINTSX" must not pass as POINTS.
    for (const char* k : {"POINTS", "CELLS", "CELL_TYPES", "POINT_DATA", "CELL_DATA", "DIMENSIONS",
                          "SPACING", "ORIGIN", "DATASET", "SCALARS", "LOOKUP_TABLE"})
      if (key.rfind(k, 0) == 0 && key != k)
        throw InputError(path, "line " + std::to_string(number), "'" + key + "' is not a keyword (" + k + "?)");
    const std::string where = key + " (line " + std::to_string(number) + ")";
    auto need = [&](size_t n) {
      if (t.size() < n)
        throw InputError(path, where, "expected " + std::to_string(n - 1) + " numbers after the keyword");
    };
    if (key == "POINTS") {
      need(3);
      const uint64_t n = count(path, where, t[1], bytes / 3, "point count");
      if (!binary && (t[2] == "float" || t[2] == "double"))
        number += int64_t(walk_ascii_reals(in, path, where, number, 3 * n, 3, "point", "a coordinate", t[2] == "float"));
    } else if (key == "CELLS" || key == "POLYGONS" || key == "LINES" || key == "VERTICES" ||
               key == "TRIANGLE_STRIPS") {
      need(3);
      const uint64_t cells = count(path, where, t[1], bytes, "cell count");
      const uint64_t size = count(path, where, t[2], bytes, "connectivity size");
      if (cell_lists) number += int64_t(walk_legacy_cells(in, path, where, cells, size, binary));
      if (key == "CELLS") {  // 5.1 files give the offsets' count, one more than the cells
        cells_at = where;
        cells_count = cell_lists || cells == 0 ? cells : cells - 1;
        agree();
      }
    } else if (key == "CELL_TYPES") {
      need(2);
      types_at = where;
      types_count = count(path, where, t[1], bytes, "count");
      agree();
      number += int64_t(walk_cell_types(in, path, where, types_count, binary));
    } else if (key == "POINT_DATA" || key == "CELL_DATA") {
      need(2);
      data_count = count(path, where, t[1], bytes, "count");
      data_item = key == "POINT_DATA" ? "point" : "cell";
    } else if (key == "SCALARS" && !binary && data_item && t.size() >= 3 && (t[2] == "float" || t[2] == "double")) {
      int64_t comps = 1;
      if (t.size() > 3 && (!parse_int(t[3], comps) || comps < 1 || comps > 4)) continue;  // VTK says why
      const std::string what = "scalar '" + std::string(t[1]) + "'";
      const bool as_float = t[2] == "float";
      const std::streampos next = in.tellg();
      if (std::getline(in, line) && line.rfind("LOOKUP_TABLE", 0) == 0) {
        ++number;
      } else {  // the table line is optional
        in.clear();
        in.seekg(next);
      }
      number += int64_t(walk_ascii_reals(in, path, where, number, data_count * uint64_t(comps), uint64_t(comps),
                                         data_item, what, as_float));  // `t` viewed the line read over
    } else if (key == "DIMENSIONS") {
      need(4);
      double n = 1;
      for (int a = 1; a <= 3; ++a) n *= static_cast<double>(count(path, where, t[a], bytes, "dimension"));
      if (n > bytes)
        throw InputError(path, where, "dimensions promise more points than a file of this size can hold");
    } else if (key == "SPACING" || key == "ORIGIN" || key == "ASPECT_RATIO") {
      need(4);
      for (int a = 1; a <= 3; ++a) {
        double d = 0;
        if (!parse_finite(t[a], d))
          throw InputError(path, where, "'" + std::string(t[a]) + "' is not a finite number");
      }
    }
  }
  if (!cells_at.empty() && types_at.empty())
    throw InputError(path, cells_at, "no CELL_TYPES section follows (cell count " + std::to_string(cells_count) +
                                         "; the file ends at line " + std::to_string(number) + ")");
}

}  // namespace vob

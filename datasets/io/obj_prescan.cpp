#include "datasets/io/obj_prescan.h"

#include <cfloat>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string_view>
#include <vector>

#include "harness/scene/input_error.h"

namespace vob {

namespace {
constexpr size_t kMaxLine = 262144;  // VTK's vtkOBJReader fails on longer lines

std::string q(std::string_view s) {  // quoted; appended, as GCC 12 warns (-Wrestrict) on a + chain
  std::string r(1, '\'');
  r.append(s).push_back('\'');
  return r;
}

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

std::vector<std::string_view> split(std::string_view s) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && is_blank(s[i])) ++i;
    const size_t b = i;
    while (i < s.size() && !is_blank(s[i])) ++i;
    if (i > b) out.push_back(s.substr(b, i - b));
  }
  return out;
}

struct Walker {
  std::string path;
  int line = 0;  // the statement's first line
  int64_t counts[3] = {0, 0, 0};  // v, vt, vn read so far
  // The largest positive reference into each list and its line: checked against the list's
  // final length (a face may name a vertex given after it; VTK resolves positive indices at
  // the end).
  int64_t max_ref[3] = {0, 0, 0};
  int max_line[3] = {0, 0, 0};
  int face_form = -1, face_form_line = 0;  // the first face's form (bit 1: vt, bit 2: vn) and line
  int64_t last_vertex = 0;                 // the last reference's vertex, resolved (1-based)
  ObjFaces* faces = nullptr;               // filled when the faces carry texture or normal indices

  [[noreturn]] void fail(const std::string& reason) const {
    throw InputError(path, "line " + std::to_string(line), reason);
  }

  double number(std::string_view t, const char* what) const {
    std::string_view s = t;
    if (!s.empty() && s[0] == '+') s.remove_prefix(1);
    double v = 0;
    const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || r.ptr != s.data() + s.size() || (r.ec != std::errc() && r.ec != std::errc::result_out_of_range) ||
        (r.ec == std::errc() && !std::isfinite(v)))
      fail(std::string(what) + " " + q(t) + " is not a finite number");
    if (r.ec == std::errc::result_out_of_range || std::abs(v) > FLT_MAX)
      fail(std::string(what) + " " + q(t) + " is beyond the float range VTK's OBJ reader stores points in");
    if (v != 0 && static_cast<float>(v) == 0)
      fail(std::string(what) + " " + q(t) + " becomes 0 in the floats VTK's OBJ reader stores points in");
    return v;
  }

  // One index of a reference into list k (0 v, 1 vt, 2 vn).
  void index(std::string_view t, int k, std::string_view ref) {
    static const char* names[] = {"vertex", "texture coordinate", "normal"};
    static const char* lists[] = {"vertices", "texture coordinates (vt)", "normals (vn)"};
    std::string_view s = t;
    if (!s.empty() && s[0] == '+') s.remove_prefix(1);
    int64_t v = 0;
    const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    std::string head = "'";  // built by appending: GCC 12 warns (-Wrestrict) on the + chain
    head.append(ref).append("': ");
    if (s.empty() || r.ptr != s.data() + s.size() || r.ec != std::errc())
      fail(head.append(names[k]).append(" index '").append(t).append("' is not an integer"));
    if (v == 0) fail(head.append(names[k]).append(" index 0 (OBJ counts from 1)"));
    if (v < 0) {
      if (-v > counts[k])
        fail(head.append("relative ").append(names[k]).append(" index ").append(std::to_string(v))
                 .append(" reaches before the first (").append(std::to_string(counts[k])).append(" ")
                 .append(lists[k]).append(" so far)"));
    } else if (v > max_ref[k]) {
      max_ref[k] = v;
      max_line[k] = line;
    }
    if (k == 0) last_vertex = v < 0 ? counts[0] + v + 1 : v;
  }

  // A reference of a face, line or point: "v", "v/vt", "v/vt/vn" or "v//vn". Returns its form
  // (bit 1: vt, bit 2: vn).
  int reference(std::string_view ref) {
    std::string_view part[3];
    int parts = 0;
    size_t b = 0;
    for (size_t i = 0; i <= ref.size(); ++i)
      if (i == ref.size() || ref[i] == '/') {
        if (parts == 3) fail(q(ref) + " is not a reference (v, v/vt, v/vt/vn or v//vn)");
        part[parts++] = ref.substr(b, i - b);
        b = i + 1;
      }
    if (part[0].empty() || (parts == 2 && part[1].empty()) || (parts == 3 && part[2].empty()))
      fail(q(ref) + " is not a reference (v, v/vt, v/vt/vn or v//vn)");
    index(part[0], 0, ref);
    int form = 0;
    if (parts >= 2 && !part[1].empty()) index(part[1], 1, ref), form |= 1;
    if (parts == 3) index(part[2], 2, ref), form |= 2;
    return form;
  }

  void statement(const std::vector<std::string_view>& w) {
    const std::string_view key = w[0];
    // A '#' ends the words VTK reads (it accepts one after a vertex's numbers).
    size_t n = w.size();
    for (size_t i = 1; i < w.size(); ++i)
      if (w[i][0] == '#') {
        n = i;
        break;
      }
    if (key == "v") {
      const size_t k = n - 1;
      if (k != 3 && k != 4 && k != 6 && k != 7)
        fail("vertex has " + std::to_string(k) + " numbers (x y z, with OBJ's w 4, with a colour 6 or 7)");
      for (size_t i = 1; i < n; ++i) number(w[i], i <= 3 ? "coordinate" : "value");
      ++counts[0];
    } else if (key == "vt" || key == "vn") {
      const bool vt = key == "vt";
      const size_t k = n - 1;
      if (vt ? (k < 1 || k > 3) : k != 3)
        fail(std::string(vt ? "texture coordinate has " : "normal has ") + std::to_string(k) + " numbers (" +
             (vt ? "1 to 3)" : "3)"));
      for (size_t i = 1; i < n; ++i) number(w[i], "value");
      ++counts[vt ? 1 : 2];
    } else if (key == "f" || key == "l" || key == "p") {
      if (key == "f" && n < w.size()) fail("a '#' comment after a face's points (VTK's OBJ reader fails on it)");
      const size_t min = key == "f" ? 3 : key == "l" ? 2 : 1;
      if (n - 1 < min)
        fail(std::string(key == "f" ? "face" : key == "l" ? "line" : "point") + " statement has " + std::to_string(n - 1) +
             " references (at least " + std::to_string(min) + ")");
      int form = -1;
      std::vector<int32_t> ids;
      for (size_t i = 1; i < n; ++i) {
        const int f = reference(w[i]);
        ids.push_back(last_vertex > INT32_MAX ? -1 : int32_t(last_vertex - 1));  // past the vertices: refused below
        if (key == "p" && f != 0) fail(q(w[i]) + ": a point statement takes vertex indices only");
        if (key == "l" && (f & 2)) fail(q(w[i]) + ": a line statement takes no normals");
        if (form >= 0 && f != form)
          fail(q(w[i]) + " is of another form than " + q(w[1]) +
               " (one statement uses one of v, v/vt, v/vt/vn, v//vn)");
        form = f;
      }
      if (key == "f") {
        if (face_form < 0) face_form = form, face_form_line = line;
        if (form != face_form) {
          const char* what = (form ^ face_form) & 2 ? "normals (v//vn, v/vt/vn)" : "texture coordinates (v/vt)";
          fail(std::string("a face ") + ((form ^ face_form) & form ? "with " : "without ") + what + " after one " +
               ((form ^ face_form) & form ? "without" : "with") + " them on line " + std::to_string(face_form_line) +
               " (VTK's OBJ reader skips faces that differ so)");
        }
        if (form != 0) {
          faces->corner_points = true;
          faces->start.push_back(faces->vertex.size());
          faces->vertex.insert(faces->vertex.end(), ids.begin(), ids.end());
        }
      }
    } else if (key == "g" || key == "o" || key == "s" || key == "usemtl" || key == "mtllib" || key == "usemap" ||
               key == "maplib" || key == "lod" || key == "bevel" || key == "c_interp" || key == "d_interp" ||
               key == "shadow_obj" || key == "trace_obj" || key == "ctech" || key == "stech") {
      // names and display attributes: no geometry
    } else if (key == "vp" || key == "cstype" || key == "deg" || key == "bmat" || key == "step" || key == "curv" ||
               key == "curv2" || key == "surf" || key == "parm" || key == "trim" || key == "hole" || key == "scrv" ||
               key == "sp" || key == "end" || key == "con" || key == "mg") {
      fail("free-form geometry ('" + std::string(key) + "') is not read (VTK's OBJ reader skips it)");
    } else {
      fail("unknown statement '" + std::string(key) + "' (VTK's OBJ reader would skip it)");
    }
  }
};
}  // namespace

ObjFaces prescan_obj(const std::string& path) {
  ObjFaces faces;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "file", "cannot be read");
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  Walker w;
  w.path = path;
  w.faces = &faces;
  std::string joined;  // a statement continued over lines ending in '\'
  int line_no = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string_view l(text.data() + pos, end - pos);
    pos = end + 1;
    ++line_no;
    if (joined.empty()) w.line = line_no;
    if (l.size() > kMaxLine)
      throw InputError(path, "line " + std::to_string(line_no),
                       "is longer than " + std::to_string(kMaxLine) + " bytes (VTK's OBJ reader fails on it)");
    if (l.find('\0') != std::string_view::npos)
      throw InputError(path, "line " + std::to_string(line_no), "holds a NUL byte (not an OBJ text file)");
    while (!l.empty() && is_blank(l.back())) l.remove_suffix(1);
    if (!l.empty() && l.back() == '\\' && split(l)[0][0] != '#') {
      joined.append(l.substr(0, l.size() - 1)).push_back(' ');
      continue;
    }
    std::vector<std::string_view> words;
    if (!joined.empty()) {
      joined.append(l);
      words = split(joined);
    } else {
      words = split(l);
    }
    if (!words.empty() && words[0][0] != '#') w.statement(words);
    joined.clear();
  }
  if (!joined.empty()) {
    w.statement(split(joined));
  }
  static const char* lists[] = {"vertices", "texture coordinates (vt)", "normals (vn)"};
  static const char* names[] = {"vertex", "texture coordinate", "normal"};
  for (int k = 0; k < 3; ++k)
    if (w.max_ref[k] > w.counts[k])
      throw InputError(path, "line " + std::to_string(w.max_line[k]),
                       std::string(names[k]) + " index " + std::to_string(w.max_ref[k]) + " is out of range (the file has " +
                           std::to_string(w.counts[k]) + " " + lists[k] + ")");
  if (faces.corner_points) faces.start.push_back(faces.vertex.size());
  return faces;
}

}  // namespace vob

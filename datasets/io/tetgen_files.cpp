#include "datasets/io/tetgen_files.h"

#include <cstdio>
#include <filesystem>
#include <memory>

#include "datasets/io/file_util.h"
#include "datasets/io/text_lines.h"
#include "harness/scene/input_error.h"

namespace vob {

std::string tetgen_partner(const std::string& path, const char* ext) {
  return std::filesystem::path(path).replace_extension(ext).string();
}

CellMesh read_tetgen(const std::string& node_path, const std::string& ele_path) {
  CellMesh m;
  TextLines n(node_path);
  if (!n.next()) n.fail("header", "file is empty (expected '<#points> 3 <#attributes> <#markers>')");
  const int64_t np = n.integer(0, "header");
  const int64_t dim = n.tokens().size() > 1 ? n.integer(1, "header") : 3;
  const int64_t nattr = n.tokens().size() > 2 ? n.integer(2, "header") : 0;
  const int64_t nmark = n.tokens().size() > 3 ? n.integer(3, "header") : 0;
  if (np < 0 || np >= (int64_t(1) << 31)) n.fail("header", "point count " + std::to_string(np) + " is out of range");
  if (dim != 3) n.fail("header", "dimension " + std::to_string(dim) + " is not 3");
  if (nattr < 0 || nattr > 1000) n.fail("header", "attribute count " + std::to_string(nattr) + " is out of range");
  if (nmark != 0 && nmark != 1) n.fail("header", "boundary marker flag " + std::to_string(nmark) + " is not 0 or 1");
  n.require_fits(np, 8, "header", "point count");  // "0 0 0 0\n"
  m.points.reserve(n.capacity_for(np, 8));  // "0 0 0 0\n"
  if (nattr > 0) m.scalars.reserve(n.capacity_for(np, 8));
  int64_t base = 0;
  for (int64_t i = 0; i < np; ++i) {
    const std::string el = "point " + std::to_string(i);
    if (!n.next())
      throw InputError(node_path, el, "file ends early: the header promises " + std::to_string(np) +
                                          " points, found " + std::to_string(i));
    n.need(4 + nattr + nmark, el, std::to_string(4 + nattr + nmark) + " values (index, x, y, z" +
                                      (nattr ? ", attributes" : "") + (nmark ? ", marker" : "") + ")");
    const int64_t idx = n.integer(0, el);
    if (i == 0) {
      if (idx != 0 && idx != 1) n.fail(el, "first index is " + std::to_string(idx) + ", expected 0 or 1");
      base = idx;
    } else if (idx != base + i) {
      n.fail(el, "index " + std::to_string(idx) + " is out of sequence (expected " +
                     std::to_string(base + i) + ")");
    }
    m.points.push_back({n.number(1, el), n.number(2, el), n.number(3, el)});
    if (nattr > 0) m.scalars.push_back(n.number(4, el));
  }
  if (n.next()) n.fail("", "unexpected data after the " + std::to_string(np) + " points");

  TextLines e(ele_path);
  if (!e.next()) e.fail("header", "file is empty (expected '<#tetrahedra> 4 <#attributes>')");
  const int64_t nt = e.integer(0, "header");
  const int64_t per = e.tokens().size() > 1 ? e.integer(1, "header") : 4;
  const int64_t eattr = e.tokens().size() > 2 ? e.integer(2, "header") : 0;
  if (nt < 0 || 4 * nt >= (int64_t(1) << 31)) e.fail("header", "tetrahedron count " + std::to_string(nt) + " is out of range");
  if (per == 10) e.fail("header", "10-node (second-order) tetrahedra are not supported");
  if (per != 4) e.fail("header", "nodes per tetrahedron is " + std::to_string(per) + ", expected 4");
  if (eattr < 0 || eattr > 1000) e.fail("header", "attribute count " + std::to_string(eattr) + " is out of range");
  e.require_fits(nt, 10, "header", "tetrahedron count");  // "0 0 1 2 3\n"
  const size_t cap = e.capacity_for(nt, 10);  // "0 0 1 2 3\n"
  m.types.reserve(cap);
  m.offsets.reserve(cap + 1);
  m.conn.reserve(4 * cap);
  // TetGen lists each tetrahedron with its fourth point on the side the right-hand normal
  // of the first three points to, i.e. VTK's tetra order (face 0,2,1 faces outwards):
  // checked on TetGen 1.5 output, so indices are copied unchanged and an inverted
  // tetrahedron is reported by validation, not reordered.
  for (int64_t t = 0; t < nt; ++t) {
    const std::string el = "tetrahedron " + std::to_string(t);
    if (!e.next())
      throw InputError(ele_path, el, "file ends early: the header promises " + std::to_string(nt) +
                                         " tetrahedra, found " + std::to_string(t));
    e.need(5 + eattr, el, std::to_string(5 + eattr) + " values (index, 4 points" +
                              (eattr ? ", attributes" : "") + ")");
    const int64_t idx = e.integer(0, el);
    if (idx != base + t)
      e.fail(el, "index " + std::to_string(idx) + " is out of sequence (expected " +
                     std::to_string(base + t) + ")");
    int32_t ids[4];
    for (int q = 0; q < 4; ++q) {
      const int64_t v = e.integer(1 + q, el);
      if (v < base || v >= base + np)
        e.fail(el, "point index " + std::to_string(v) + " is out of range [" + std::to_string(base) +
                       ", " + std::to_string(base + np - 1) + "]");
      ids[q] = static_cast<int32_t>(v - base);
    }
    m.add_cell(CellType::Tetra, ids);
  }
  if (e.next()) e.fail("", "unexpected data after the " + std::to_string(nt) + " tetrahedra");
  return m;
}

namespace {
struct FileCloser {
  void operator()(FILE* f) const { if (f) std::fclose(f); }
};
using File = std::unique_ptr<FILE, FileCloser>;

File open_for_write(const std::string& tmp, const std::string& path) {
  File f(std::fopen(tmp.c_str(), "w"));
  if (!f) throw InputError(path, "file", "cannot be written");
  return f;
}
void finish(File& f, const std::string& path) {
  if (std::ferror(f.get()) || std::fclose(f.release()) != 0)
    throw InputError(path, "file", "write failed (disk full?)");
}
}  // namespace

void write_tetgen(const CellMesh& m, const std::string& node_path) {
  for (size_t c = 0; c < m.num_cells(); ++c)
    if (m.types[c] != CellType::Tetra)
      throw InputError(node_path, "cell " + std::to_string(c),
                       std::string("is a ") + cell_type_name(m.types[c]) +
                           "; TetGen files hold tetrahedra only");
  const std::string ele_path = tetgen_partner(node_path, ".ele");
  // The .ele goes first: a reader that finds the .node finds its .ele complete.
  write_atomically(ele_path, [&](const std::string& tmp) {
    File f = open_for_write(tmp, ele_path);
    std::fprintf(f.get(), "%zu 4 0\n", m.num_cells());
    for (size_t c = 0; c < m.num_cells(); ++c) {
      const int32_t* p = m.cell_points(c);
      std::fprintf(f.get(), "%zu %d %d %d %d\n", c, p[0], p[1], p[2], p[3]);
    }
    finish(f, ele_path);
  });
  write_atomically(node_path, [&](const std::string& tmp) {
    File f = open_for_write(tmp, node_path);
    const bool attr = !m.scalars.empty();
    std::fprintf(f.get(), "%zu 3 %d 0\n", m.num_points(), attr ? 1 : 0);
    for (size_t i = 0; i < m.num_points(); ++i) {
      const Vec3 q = m.points[i];
      if (attr)
        std::fprintf(f.get(), "%zu %.17g %.17g %.17g %.17g\n", i, q.x, q.y, q.z, m.scalars[i]);
      else
        std::fprintf(f.get(), "%zu %.17g %.17g %.17g\n", i, q.x, q.y, q.z);
    }
    finish(f, node_path);
  });
}

}  // namespace vob

#include "datasets/io/off_io.h"

#include <cstdio>
#include <memory>
#include <vector>

#include "datasets/io/file_util.h"
#include "datasets/io/text_lines.h"
#include "harness/scene/input_error.h"

namespace vob {

TriangleSoup read_off(const std::string& path) {
  TextLines in(path);
  if (!in.next()) in.fail("header", "file is empty (expected OFF)");
  std::string_view key = in.tokens()[0];
  const bool known = key.size() >= 3 && key.substr(key.size() - 3) == "OFF";
  std::string_view prefix = known ? key.substr(0, key.size() - 3) : key;
  for (const char* p : {"ST", "C", "N"})
    if (prefix.substr(0, std::string_view(p).size()) == p) prefix.remove_prefix(std::string_view(p).size());
  if (!known || !prefix.empty())
    in.fail("header", "'" + std::string(key) + "' is not an OFF header (OFF, COFF, NOFF, STOFF; 4OFF and nOFF are not supported)");
  size_t count_token = 1;  // the counts may follow the keyword on the same line
  if (in.tokens().size() == 1) {
    if (!in.next()) in.fail("header", "file ends before the vertex and face counts");
    count_token = 0;
  }
  in.need(count_token + 2, "counts", "vertex and face counts");
  const int64_t nv = in.integer(count_token, "counts"), nf = in.integer(count_token + 1, "counts");
  if (nv < 0 || nv >= (int64_t(1) << 31)) in.fail("counts", "vertex count " + std::to_string(nv) + " is out of range");
  if (nf < 0 || nf >= (int64_t(1) << 30)) in.fail("counts", "face count " + std::to_string(nf) + " is out of range");
  in.require_fits(nv, 6, "counts", "vertex count");  // "0 0 0\n"
  in.require_fits(nf, 8, "counts", "face count");    // "3 0 1 2\n"
  TriangleSoup s;
  s.points.reserve(in.capacity_for(nv, 6));  // "0 0 0\n"
  s.tris.reserve(in.capacity_for(nf, 8));    // "3 0 1 2\n"
  for (int64_t i = 0; i < nv; ++i) {
    const std::string el = "vertex " + std::to_string(i);
    if (!in.next())
      throw InputError(path, el, "file ends early: the header promises " + std::to_string(nv) +
                                     " vertices, found " + std::to_string(i));
    in.need(3, el, "3 coordinates");
    s.points.push_back({in.number(0, el), in.number(1, el), in.number(2, el)});
  }
  std::vector<int32_t> ids;
  for (int64_t f = 0; f < nf; ++f) {
    const std::string el = "face " + std::to_string(f);
    if (!in.next())
      throw InputError(path, el, "file ends early: the header promises " + std::to_string(nf) +
                                     " faces, found " + std::to_string(f));
    const int64_t n = in.integer(0, el);
    if (n < 3) in.fail(el, "has " + std::to_string(n) + " vertices; a face needs at least 3");
    in.need(1 + n, el, std::to_string(n) + " vertex indices after the count");
    ids.clear();
    for (int64_t q = 0; q < n; ++q) {
      const int64_t v = in.integer(1 + q, el);
      if (v < 0 || v >= nv)
        in.fail(el, "vertex index " + std::to_string(v) + " is out of range [0, " + std::to_string(nv - 1) + "]");
      ids.push_back(static_cast<int32_t>(v));
    }
    append_polygon(s, ids.data(), ids.size(), path, in.where(el));
  }
  return s;
}

void write_off(const TriangleSoup& s, const std::string& path) {
  write_atomically(path, [&](const std::string& tmp) {
    std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(tmp.c_str(), "w"), &std::fclose);
    if (!f) throw InputError(path, "file", "cannot be written");
    std::fprintf(f.get(), "OFF\n%zu %zu 0\n", s.points.size(), s.tris.size());
    for (const Vec3& p : s.points) std::fprintf(f.get(), "%.17g %.17g %.17g\n", p.x, p.y, p.z);
    for (const auto& t : s.tris) std::fprintf(f.get(), "3 %d %d %d\n", t[0], t[1], t[2]);
    if (std::ferror(f.get()) || std::fclose(f.release()) != 0)
      throw InputError(path, "file", "write failed (disk full?)");
  });
}

}  // namespace vob

#include "datasets/io/tetgen_bridge.h"

#include <stdlib.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <regex>
#include <unordered_map>
#include <vector>

#include "datasets/io/data_cache.h"
#include "datasets/io/off_io.h"
#include "datasets/io/subprocess.h"
#include "datasets/io/tetgen_files.h"
#include "harness/geometry/predicates.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace fs = std::filesystem;

namespace {
constexpr double kTetgenTimeout = 1800;  // seconds; a hung tetgen is killed, not waited on

std::string checked_switches(const std::string& given, const std::string& source) {
  std::string s = given.empty() ? kDefaultTetgenSwitches : given;
  if (!s.empty() && s[0] == '-') s.erase(0, 1);
  for (char c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '/')
      throw InputError(source, "tetgen switches '" + given + "'", std::string("character '") + c + "' is not a switch");
  // Letters of numbers (like 1e-3) are not possible here: TetGen numbers are plain decimals.
  if (s.find('p') == std::string::npos)
    throw InputError(source, "tetgen switches '" + given + "'", "need 'p' to mesh the surface");
  const std::pair<char, const char*> refused[] = {
      {'d', "only detects intersections, makes no tetrahedra"},
      {'r', "refines an existing mesh"},
      {'N', "suppresses the .node output"},
      {'E', "suppresses the .ele output"},
      {'I', "changes the output file names"},
      {'o', "second-order (10-node) output is not supported"}};
  for (const auto& [bad, why] : refused)
    if (s.find(bad) != std::string::npos)
      throw InputError(source, "tetgen switches '" + given + "'", std::string("'") + bad + "' is not allowed: " + why);
  return s;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Runs tetgen in `dir` on dir/surface.off; leaves surface.1.node/.ele there or throws.
void run_tetgen(const std::string& dir, const std::string& source, const std::string& sw) {
  const std::string tetgen = VOB_TETGEN;
  const ProcessResult r = run_process({tetgen, "-" + sw, "surface.off"}, dir, dir + "/tetgen.log",
                                      dir + "/tetgen.err", kTetgenTimeout);
  if (r.timed_out)
    throw InputError(source, "tetgen", "did not finish within " + std::to_string(int(kTetgenTimeout)) + " s");
  if (r.signal != 0) {
    // TetGen aborts (uncaught exception) on self-intersecting input; -d names the facets.
    run_process({tetgen, "-d", "surface.off"}, dir, dir + "/detect.log", "", kTetgenTimeout);
    const std::string log = read_text(dir + "/detect.log");
    std::smatch m;
    if (std::regex_search(log, m, std::regex(R"(Found (\d+) pairs of faces are intersecting)"))) {
      std::string first;
      std::smatch f;
      if (std::regex_search(log, f, std::regex(R"(Facet #(\d+) intersects facet #(\d+))")))
        first = "tetgen facets #" + f[1].str() + " and #" + f[2].str();
      throw InputError(source, first.empty() ? "surface" : first,
                       "the surface intersects itself (tetgen -d found " + m[1].str() +
                           " pairs of intersecting faces; tetgen -p aborts on such input)");
    }
    throw InputError(source, "tetgen", "aborted by signal " + std::to_string(r.signal) + " (" +
                                           strsignal(r.signal) + ")" +
                                           [&] { const std::string l = last_line_of(dir + "/tetgen.err");
                                                 return l.empty() ? std::string() : ": " + l; }());
  }
  if (!r.exited || r.exit_code != 0) {
    std::string why = last_line_of(dir + "/tetgen.err");
    if (why.empty()) why = last_line_of(dir + "/tetgen.log");
    throw InputError(source, "tetgen", "failed with exit code " + std::to_string(r.exit_code) +
                                           (why.empty() ? "" : ": " + why));
  }
  std::error_code ec;
  const std::string ele = dir + "/surface.1.ele";
  bool empty = !fs::exists(ele, ec);
  if (!empty) {
    std::ifstream in(ele);
    long long n = -1;
    in >> n;
    empty = n <= 0;
  }
  if (empty)
    throw InputError(source, "surface", "tetgen produced no tetrahedra (the surface is open or encloses no volume)");
}

std::string make_temp_dir(const std::string& parent) {
  std::error_code ec;
  fs::create_directories(parent, ec);
  std::string pattern = parent + "/.tetgen-" + std::string(6, 'X');  // mkdtemp template
  std::vector<char> buf(pattern.begin(), pattern.end());
  buf.push_back('\0');
  if (!mkdtemp(buf.data())) throw InputError(parent, "folder", std::string("cannot create a temporary folder: ") + std::strerror(errno));
  return buf.data();
}
}  // namespace

void check_closed_surface(const TriangleSoup& s, const std::string& source) {
  std::unordered_map<uint64_t, int32_t> uses;  // undirected edge -> triangle count
  uses.reserve(s.tris.size() * 2);
  for (const auto& t : s.tris)
    for (int e = 0; e < 3; ++e) {
      const int32_t a = t[e], b = t[(e + 1) % 3];
      ++uses[(uint64_t(uint32_t(std::min(a, b))) << 32) | uint32_t(std::max(a, b))];
    }
  // Report the smallest offending edge, so the message does not depend on hash order.
  uint64_t worst = ~0ull;
  int32_t count = 0;
  for (const auto& [key, n] : uses)
    if (n % 2 != 0 && key < worst) {
      worst = key;
      count = n;
    }
  if (worst != ~0ull)
    throw InputError(source, "edge (" + std::to_string(worst >> 32) + "," + std::to_string(worst & 0xffffffffu) + ")",
                     "belongs to " + std::to_string(count) + " triangle" + (count == 1 ? "" : "s") +
                         ": the surface is not closed (TetGen needs a closed surface)");
}

void check_encloses_volume(const TriangleSoup& s, const std::string& source) {
  // A triangle given twice: the same three points in any order.
  std::vector<std::pair<std::array<int32_t, 3>, size_t>> sorted(s.tris.size());
  for (size_t t = 0; t < s.tris.size(); ++t) {
    std::array<int32_t, 3> k = s.tris[t];
    std::sort(k.begin(), k.end());
    sorted[t] = {k, t};
  }
  std::sort(sorted.begin(), sorted.end());
  for (size_t i = 1; i < sorted.size(); ++i)
    if (sorted[i].first == sorted[i - 1].first)
      throw InputError(source, "triangles " + std::to_string(sorted[i - 1].second) + " and " + std::to_string(sorted[i].second),
                       "have the same three points: a surface around a volume holds each triangle once "
                       "(TetGen cannot mesh it)");
  // Connected pieces (triangles sharing a point), each against the plane of its first triangle.
  std::vector<int32_t> parent(s.points.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const auto& t : s.tris)
    for (int e = 1; e < 3; ++e) {
      const int32_t a = root(t[0]), b = root(t[e]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  std::unordered_map<int32_t, size_t> first;  // piece root -> its first triangle
  std::vector<size_t> pieces;                 // first triangles, in order
  for (size_t t = 0; t < s.tris.size(); ++t)
    if (first.emplace(root(s.tris[t][0]), t).second) pieces.push_back(t);
  std::unordered_map<int32_t, bool> off_plane;
  for (const auto& t : s.tris) {
    const int32_t r = root(t[0]);
    bool& off = off_plane[r];
    if (off) continue;
    const auto& p = s.tris[first[r]];
    for (int32_t v : t)
      if (orient3d(s.points[p[0]], s.points[p[1]], s.points[p[2]], s.points[v]) != 0) off = true;
  }
  for (size_t t : pieces)
    if (!off_plane[root(s.tris[t][0])])
      throw InputError(source, pieces.size() == 1 ? std::string("surface") : "the piece with triangle " + std::to_string(t),
                       "all its points lie in one plane: it encloses no volume (TetGen needs a closed surface "
                       "around a volume)");
}

CellMesh tetrahedralize_surface(const TriangleSoup& surface, const std::string& source,
                                const std::string& switches, const std::string& cache_key) {
  const std::string sw = checked_switches(switches, source);
  check_encloses_volume(surface, source);
  std::error_code ec;
  if (!cache_key.empty()) {
    const std::string parent = cache_dir() + "/tetgen";
    const std::string final_dir = parent + "/" + cache_key + "-" + stable_hash(sw);
    if (fs::exists(final_dir + "/mesh.node", ec))
      return read_tetgen(final_dir + "/mesh.node", final_dir + "/mesh.ele");
    const std::string tmp = make_temp_dir(parent);
    try {
      write_off(surface, tmp + "/surface.off");
      run_tetgen(tmp, source, sw);
      // Keep only the mesh; a complete folder appears under its final name at once.
      const std::string keep = tmp + "/keep";
      fs::create_directory(keep);
      fs::rename(tmp + "/surface.1.ele", keep + "/mesh.ele");
      fs::rename(tmp + "/surface.1.node", keep + "/mesh.node");
      fs::rename(keep, final_dir, ec);  // fails harmlessly if another process won the race
    } catch (...) {
      fs::remove_all(tmp, ec);
      throw;
    }
    fs::remove_all(tmp, ec);
    return read_tetgen(final_dir + "/mesh.node", final_dir + "/mesh.ele");
  }
  const char* t = std::getenv("TMPDIR");
  const std::string tmp = make_temp_dir(t && *t ? t : "/tmp");
  try {
    write_off(surface, tmp + "/surface.off");
    run_tetgen(tmp, source, sw);
    CellMesh m = read_tetgen(tmp + "/surface.1.node", tmp + "/surface.1.ele");
    fs::remove_all(tmp, ec);
    return m;
  } catch (...) {
    fs::remove_all(tmp, ec);
    throw;
  }
}

}  // namespace vob

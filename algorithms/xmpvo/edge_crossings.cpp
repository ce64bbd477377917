// XMPVO's crossings indexed along each edge (Arrangement::index_crossings), and one edge's list
// sorted by its position along the edge for the sweep (sort_edge_crossings).
#include "algorithms/xmpvo/arrangement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace vob::xmpvo {

namespace {
// Lists up to this long are sorted by counting places (98% of the edges on the 200k helix).
constexpr int32_t kRankedMax = 64;
}  // namespace

// Each record's place is the number of smaller keys, counted with no data-dependent
// branch (24 crossings an edge on average on the 200k helix): the insertion sort this
// replaces moved about 4 items per item and mispredicted its loop exit at nearly every
// one, about 40% of index_crossings' time. Equal keys share a count, which the places'
// sum shows (it falls short of 0 + 1 + ... + n - 1); those lists, the longer ones and any
// with a NaN key go to std::stable_sort.
__attribute__((target_clones("avx2", "default"))) void sort_edge_crossings(const EdgeCrossing* p, int32_t n,
                                                                          std::vector<EdgeCrossing>& out) {
  auto stable = [&] {
    out.assign(p, p + n);
    if (n > 1 && p[0].key > p[n - 1].key) std::reverse(out.begin(), out.end());
    std::stable_sort(out.begin(), out.end(), [](const EdgeCrossing& a, const EdgeCrossing& b) { return a.key < b.key; });
  };
  if (n < 2 || n > kRankedMax) return stable();
  // Four keys a compare (GCC's vector types: one AVX2 compare in the avx2 clone, two SSE2
  // ones otherwise); a true compare is all ones, -1 as an integer.
  typedef double Keys __attribute__((vector_size(32)));
  typedef int64_t Counts __attribute__((vector_size(32)));
  Keys key4[kRankedMax / 4];  // key i in lane i % 4 of key4[i / 4]
  bool nan = false;
  for (int32_t i = 0; i < n; ++i) key4[i / 4][i % 4] = p[i].key, nan |= std::isnan(p[i].key);
  if (nan) return stable();
  const int32_t groups = (n + 3) / 4;
  for (int32_t i = n; i < 4 * groups; ++i) key4[i / 4][i % 4] = INFINITY;  // never smaller than a key
  int64_t place[kRankedMax], sum = 0;
  for (int32_t i = 0; i < n; ++i) {
    const double x = p[i].key;
    Counts count = {0, 0, 0, 0};
    for (int32_t g = 0; g < groups; ++g) count -= key4[g] < x;
    const int64_t r = count[0] + count[1] + count[2] + count[3];
    place[i] = r;
    sum += r;
  }
  if (sum != int64_t(n) * (n - 1) / 2) return stable();
  out.resize(static_cast<size_t>(n));
  for (int32_t i = 0; i < n; ++i) out[place[i]] = p[i];
}

// Per edge: its two faces when it has one on each side (the sweep's swaps), and whether it
// is an inner edge of the unswept sheet (both faces facing that way).
void Arrangement::mark_edges(const Projection& proj) {
  swap_.resize(edges.size());
  unswept_.assign(edges.size(), 0);
  for (size_t e = 0; e < edges.size(); ++e) {
    const int32_t x = edge_face_off[e];
    const bool two_sides = edge_face_off[e + 1] - x == 2 &&
                           edge_face_dir[x] * proj.facing[edge_faces[x]] == -edge_face_dir[x + 1] * proj.facing[edge_faces[x + 1]];
    swap_[e] = two_sides ? std::array<int32_t, 2>{edge_faces[x], edge_faces[x + 1]} : std::array<int32_t, 2>{-1, -1};
    unswept_[e] = unswept_sheet != 0 && two_sides && proj.facing[edge_faces[x]] == unswept_sheet &&
                  proj.facing[edge_faces[x + 1]] == unswept_sheet;
  }
}

// The crossings on each edge, for the edge sweep of ray_queries: each exact crossing lies
// in its vertex box, so its position along the edge (a dot product with the edge's
// projected direction, monotone along the exact edge) lies within the box's extent,
// widened by the rounding.
void Arrangement::index_crossings(const Projection& proj) {
  // edge_vertex_off holds each edge's crossing count (build() counted them as it found them;
  // none for the unswept edges).
  for (size_t e = 1; e < edge_vertex_off.size(); ++e) edge_vertex_off[e] += edge_vertex_off[e - 1];
  edge_crossings.resize(edge_vertex_off.back());
  std::vector<int32_t> fill(edge_vertex_off.begin(), edge_vertex_off.end() - 1);
  for (size_t v = projected_vertices; v < vertices.size(); ++v) {
    const Box& b = vertices[v].box;
    const double xc = 0.5 * (b.x0 + b.x1), yc = 0.5 * (b.y0 + b.y1);
    const double hw = 0.5 * (b.x1 - b.x0), hh = 0.5 * (b.y1 - b.y0);
    const int32_t e1 = vertices[v].e1, e2 = vertices[v].e2;
    for (const auto& [e, other] : {std::array{e1, e2}, std::array{e2, e1}}) {
      if (unswept_[e]) continue;
      const int32_t slot = fill[e]++;
      const auto [ax, ay] = proj.uv[edges[e].first];
      const auto [bx, by] = proj.uv[edges[e].second];
      const double dx = bx - ax, dy = by - ay;
      const double ext = std::fabs(dx) * hw + std::fabs(dy) * hh +
                         1e-14 * (std::fabs(dx) * (std::fabs(xc) + std::fabs(ax)) + std::fabs(dy) * (std::fabs(yc) + std::fabs(ay))) +
                         1e-300;
      edge_crossings[slot] = {dx * (xc - ax) + dy * (yc - ay), ext, static_cast<int32_t>(v), other};
    }
  }
}

}  // namespace vob::xmpvo

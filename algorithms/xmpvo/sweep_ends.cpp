// XMPVO's point queries after a sweep that ended at the point (edge_sweep.cpp): the sweep's
// last covering faces stand for the point's gather and sort.
#include <algorithm>

#include "algorithms/xmpvo/query_worker.h"

namespace vob::xmpvo::detail {

// The strictly covering faces of a point are those of the last segment of a sweep ending
// there but the faces having it as a vertex, in the same depth order: on a conforming
// surface no two of them meet on the point's ray, and a face with the point on its boundary
// but not as a vertex would lie on the line of an edge the arrangement tested against the
// swept one, or (sharing the sweep's first point) fail the sweep's start (start_list).
// Only the faces around the point are classified, as gather() would.
void Worker::run_query_after_sweep(int32_t vi) {
  rechecked_ = false;
  ++stats_.sweep_end_queries;
  begin(vi);
  const ArrVertex& v = *current_;
  const int32_t* around = &view_->point_faces[static_cast<size_t>(view_->point_face_off[vi])];
  const int32_t n_around = view_->point_face_off[vi + 1] - view_->point_face_off[vi];
  const int32_t* ended = &ended_[static_cast<size_t>(ended_at_[vi])];
  inside_.clear();
  for (const int32_t* f = ended + 1; f < ended + 1 + ended[0]; ++f)
    if (std::find(around, around + n_around, *f) == around + n_around) inside_.push_back(*f);
  wedges_.clear();
  for (int32_t x = 0; x < n_around; ++x)
    if (in_->proj.face_box[around[x]].overlaps(v.box)) classify(v, around[x]);
  undecided_ = false;
  if (!wedges_.empty()) emit_at_point(v);
  stats_.queries_rechecked += rechecked_;
}

// After a sweep of e = (a, b) that decided every crossing: b's covering faces for its own
// query (run_query_after_sweep), kept once per point, unless the arrangement marked b.
void Worker::keep_end_list(int32_t e) {
  if (ended_at_.empty()) return;
  const int32_t b = in_->arr.edges[e].second, vb = view_->point_vertex[b];
  if (vb < 0 || ended_at_[vb] >= 0 || in_->arr.point_on_line[b]) return;
  const size_t at = ended_.size();
  ended_at_[vb] = static_cast<int32_t>(at);
  ended_.push_back(static_cast<int32_t>(list_.size()));
  ended_.insert(ended_.end(), list_.begin(), list_.end());
}

// The kept faces around each projected point (CSR by point vertex).
void index_point_faces(const QueryInput& in, ViewTables& view) {
  const std::vector<int32_t>& point_vertex = view.point_vertex;
  const size_t np = in.arr.projected_vertices;
  std::vector<int32_t>& off = view.point_face_off;
  off.assign(np + 2, 0);
  for (int32_t f : in.proj.kept)
    for (int k = 0; k < in.ext.size[f]; ++k) ++off[point_vertex[in.ext.vertex[4 * f + k]] + 2];
  for (size_t v = 2; v < off.size(); ++v) off[v] += off[v - 1];
  view.point_faces.resize(static_cast<size_t>(off.back()));
  for (int32_t f : in.proj.kept)
    for (int k = 0; k < in.ext.size[f]; ++k) view.point_faces[off[point_vertex[in.ext.vertex[4 * f + k]] + 1]++] = f;
  off.pop_back();
}

}  // namespace vob::xmpvo::detail

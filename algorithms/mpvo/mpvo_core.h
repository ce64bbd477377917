// MpvoCore: the two phases of Williams' MPVO (Cook et al., SXMPVO paper, section 3.2) as a
// library for the MPVO family (MPVO, MPVONC, SXMPVO, XMPVO, stencil-XMPVO).
//
// Phase I (create_partial_order): every face gets a sign per view, +1 when the eye is on the
// side its plane normal points to (out of cell0: into cell1, or out of the mesh for a
// boundary face), -1 on the other side, 0 exactly on the plane. For a shared face the sign
// is the MPVO arrow: +1 means cell1 is in front of cell0. The double sign n.eye + d (or
// -n.dir for orthographic views) is trusted when it clears an error bound; otherwise the
// exact predicate decides on the face's first three vertices, which both cells share since
// faces are stored once (for a non-planar quad that triangle and the Newell plane may
// disagree near the plane; the triangle wins and the disagreement counts as
// double_sign_wrong). Per cell the number of outbound arrows (neighbours in front) is
// kept; cells with none are MPVO's sink cells.
//
// Phase II (dfs_*): iterative depth-first search against the arrows. The eligible
// neighbours of a cell are the cells behind it: across shared faces, plus the caller's
// ExtraRelations (SXMPVO pseudo-neighbours, XMPVO exterior-face relations). Post-order
// output is back to front. An eligible neighbour that is still on the stack closes a
// visibility cycle: the cycle is reported in Ordering::cycles and broken by ignoring that
// edge. dfs_unvisited() finishes with every cell not yet output, so the result is always
// a complete permutation.
//
// Renumbering (prepare with renumber.on): the core works on its own copy of the mesh, cells
// in Hilbert (or Morton) order of their centroids and points by first use (space_curve.h), with
// faces and planes built from it, so the DFS walks neighbours that lie close in memory. Every
// cell id the core takes or keeps (roots, signs, ExtraRelations, faces(), scene()) is then
// in that numbering; only what it writes into an Ordering (order, cycle members) is mapped
// back to the input's ids, as it is written.
//
// Typical frame:
//   core.create_partial_order(view);                 // phase I
//   Ordering out;
//   core.begin_dfs(out, &extra_or_null);             // phase II (or III, IV, ...)
//   for (int32_t c : my_start_cells) core.dfs_from(c, out);
//   core.dfs_sinks(out);
//   core.dfs_unvisited(out);
//   core.add_counters(out);  // exact_sign_calls, double_sign_wrong, arrows, sink_cells, ...
#pragma once
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "harness/bench/orderer.h"
#include "harness/bench/param_spec.h"
#include "harness/scene/scene.h"
#include "harness/scene/space_curve.h"
#include "harness/view/camera.h"

namespace vob::mpvo {

// Relations beyond the face arrows, in CSR form. behind[offsets[c] .. offsets[c+1]) are
// cells that must be drawn before c (eligible neighbours of c); not_sink[c] != 0 marks a
// cell that has something in front of it through such a relation.
struct ExtraRelations {
  std::vector<int32_t> offsets;   // cells+1 entries, or empty for none
  std::vector<int32_t> behind;
  std::vector<uint8_t> not_sink;  // one per cell, or empty for none
  // The sparse form, for relations on few cells (SXMPVO's, a frame at a time), where the
  // dense arrays would cost passes over every cell: with `offsets` empty, each cell c of
  // `cells` has behind[span[c].first, span[c].second), no other cell has any (their span
  // entries are never read, so span needs no clearing between frames), and every cell in
  // `behind` is no sink. span has one entry per cell.
  std::vector<int32_t> cells;
  std::vector<std::pair<int32_t, int32_t>> span;
  bool sparse() const { return offsets.empty() && !cells.empty(); }

  // Builds the CSR and the not_sink flags from (front, behind) pairs; each pair means
  // `behind` must be drawn before `front`. Ids must be in [0, cells).
  void build_from_pairs(size_t cells, const std::vector<std::pair<int32_t, int32_t>>& pairs);
  void clear();
  size_t bytes() const;
};

// Sorts relation pairs and removes repeats, as std::sort and std::unique would. Where the
// ids span at most a few times as many values as there are pairs, by two stable counting
// passes (second id, then first; ids must then be in [0, cells)); else by std::sort.
void sort_unique_pairs(std::vector<std::pair<int32_t, int32_t>>& pairs, size_t cells);
// The counting passes' buffers, kept by a caller that sorts every frame.
struct PairSortScratch {
  std::vector<std::pair<int32_t, int32_t>> by_second;
  std::vector<int32_t> start;
  size_t bytes() const { return by_second.capacity() * 8 + start.capacity() * 4; }
};
void sort_unique_pairs(std::vector<std::pair<int32_t, int32_t>>& pairs, size_t cells, PairSortScratch& scratch);

// The parameters `renumber` (bool, default true), `curve` (hilbert|morton) and
// `keep_coherent` (bool, default true) of the plugins that renumber through prepare():
// declared here once for mpvo, mpvonc and sxmpvo. With keep_coherent, prepare renumbers
// only when the curve's numbering has fewer far point reuses than the input's
// (far_reuse_fraction, space_curve.h): generators number some meshes better than a curve.
struct RenumberOption {
  bool on = false;
  Curve curve = Curve::Hilbert;
  bool keep_coherent = true;
};
std::vector<ParamSpec> renumber_params();
RenumberOption renumber_option(const ResolvedParams& p);

// The claims of an orderer built on MpvoCore: it detects (and breaks) cycles.
inline Claims core_claims(bool object_exact, bool image_exact) {
  Claims c;
  c.object_exact = object_exact;
  c.image_exact = image_exact;
  c.detects_cycles = true;
  return c;
}

class MpvoCore {
 public:
  // Relative error bound of the double sign test, as a fraction of the magnitudes of the
  // summands: |n.eye + d| <= kRelativeBound * |n|_1 * (|eye| + R), R bounding every face
  // point. It is conservative while face edges are longer than ~1e-6 of R (the Newell
  // normal's rounding grows with R / edge length); generous otherwise.
  static constexpr double kRelativeBound = 1e-9;

  // Binds the scene's unique faces and face planes; builds them if the caller has not
  // (callers build them first inside their own prepare phases so the time is attributed).
  // Keeps a copy of the Scene handle, which shares the data and the derived structures.
  void bind(const Scene& scene);
  // bind() after the prepare phases "unique faces" and "face planes" (timed in `clock`):
  // the start of every MPVO-family plugin's prepare. With renumber.on, first the phase
  // "renumber along a space curve" makes the core's own renumbered scene, which it binds.
  void prepare(const Scene& scene, PhaseClock& clock, RenumberOption renumber = {});
  // The scene the core works on: the input's, or its renumbered copy.
  const Scene& scene() const { return scene_; }
  bool renumbered() const { return !input_id_.empty(); }
  // far_reuse_fraction of the input's numbering and of the curve's, as prepare measured
  // them to choose (-1: not measured, renumber off or keep_coherent off).
  double far_reuse_input() const { return far_input_; }
  double far_reuse_curve() const { return far_curve_; }
  // Input cell id of a core cell id.
  int32_t input_id(int32_t c) const { return input_id_.empty() ? c : input_id_[c]; }
  size_t num_cells() const { return outbound_.size(); }
  const MeshFaces& faces() const { return *faces_; }

  // ---- Phase I ----
  void create_partial_order(const Camera& view);
  // Stability studies only: trust the double sign everywhere (no bound, no exact call).
  // Off by default; double_sign_wrong then stays 0 because nothing is checked.
  void set_plain_double_signs(bool on) { plain_double_ = on; }
  int face_sign(int32_t f) const { return sign_[f]; }
  // Replaces face f's sign for this view (after create_partial_order), moving its arrow:
  // for callers whose rasterizer sees the face from the other side than the exact test
  // (stencil-xmpvo on llvmpipe's snapped coordinates, snapped_signs.h).
  void set_face_sign(int32_t f, int s);
  const std::vector<int8_t>& face_signs() const { return sign_; }
  // Boundary face whose outside faces the eye.
  bool front_facing_boundary(int32_t f) const { return faces_->cell1[f] < 0 && sign_[f] > 0; }
  int outbound_arrows(int32_t c) const { return outbound_[c]; }
  int64_t exact_sign_calls() const { return exact_calls_; }
  int64_t double_sign_wrong() const { return double_wrong_; }
  int64_t arrows() const { return arrows_; }

  // ---- Phase II ----
  // Starts a traversal writing into out.order / out.cycles. `extra` (may be null) must
  // stay alive and unchanged until the traversal's last dfs_* call.
  void begin_dfs(Ordering& out, const ExtraRelations* extra = nullptr);
  // Sink: no outbound arrow and not marked not_sink by the extra relations (after begin_dfs).
  bool is_sink(int32_t c) const { return outbound_[c] == 0 && !(state_[c] & kNotSink); }
  bool visited(int32_t c) const { return (state_[c] & kStateMask) != kNew; }
  // DFS from `root` unless it was already visited; returns whether a search started.
  bool dfs_from(int32_t root, Ordering& out);
  void dfs_sinks(Ordering& out);      // every sink, in cell-id order
  void dfs_unvisited(Ordering& out);  // every cell not yet output (cycles without a sink)
  // The whole phase for orderers with no root order of their own: begin_dfs, every sink,
  // then every cell left by cycles.
  void dfs_all(Ordering& out, const ExtraRelations* extra = nullptr) {
    begin_dfs(out, extra);
    dfs_sinks(out);
    dfs_unvisited(out);
  }
  // Adds exact_sign_calls, double_sign_wrong, arrows, sink_cells, cycle_roots, renumbered
  // (0 or 1) and, when prepare measured them, far_reuse_input and far_reuse_curve.
  void add_counters(Ordering& out) const;

  // Memory held: slot adjacency, face signs, per-cell arrow counts and masks, DFS flags
  // and stack (the scene's faces and planes are counted by the scene), and when renumbered
  // the id map, the renumbered mesh and the structures derived from it.
  size_t bytes() const;

 private:
  // A cell's DFS state (kNew -> kOnStack -> kDone, by increments) and, in bit 2, whether
  // it has extra relations: most cells have none, and the flag, read with the state, spares
  // the DFS a look at the extra offsets of every cell (a cache miss in 4 bytes a cell); in
  // bit 3, whether an extra relation puts something in front of it (no sink).
  enum : uint8_t { kNew = 0, kOnStack = 1, kDone = 2, kStateMask = 3, kHasExtra = 4, kNotSink = 8 };
  static constexpr int32_t kExtraSlot = 8;  // slots 0..7 are faces, then extra relations
  struct Frame {
    int32_t cell;
    int32_t next;  // next eligible-neighbour slot to look at
  };
  int exact_sign(int32_t f, const Camera& view, Vec3 dir) const;
  void report_cycle(int32_t closing, Ordering& out);
  // The DFS, with or without extra relations: without them no cell has kHasExtra, and the
  // state is written with plain stores (kOnStack, kDone) rather than increments, which need
  // the cell's state byte loaded first (a cache miss when the cell was visited long ago).
  template <bool kExtra>
  void dfs_walk(int32_t root, Ordering& out);

  Scene scene_;  // keeps the derived structures below alive
  std::vector<int32_t> input_id_;  // core cell id -> input cell id; empty: the same
  double far_input_ = -1, far_curve_ = -1;
  const CellMesh* mesh_ = nullptr;
  const MeshFaces* faces_ = nullptr;
  const FacePlanes* planes_ = nullptr;
  double coord_bound_ = 0;  // R: bounds |p| for every mesh point

  // View-independent adjacency in cell-face slot order (slot k of cell c is
  // cell_faces[cell_face_offsets[c] + k]): the DFS then reads one cell's neighbours from
  // one place instead of chasing cell0/cell1 of every face.
  std::vector<int32_t> neighbour_;  // per slot: the cell across, or -1
  std::vector<uint8_t> face_slot_;  // per face: its slot in cell0, then in cell1
  bool tet_slots_ = false;          // cell c's slots are 4c .. 4c+3 (spares the DFS a load)

  std::vector<int8_t> sign_;          // per face, per view
  std::vector<uint8_t> outbound_;     // per cell: arrows to neighbours in front
  std::vector<uint8_t> behind_mask_;  // per cell: bit k = the neighbour at slot k is behind
  int64_t exact_calls_ = 0, double_wrong_ = 0, arrows_ = 0;
  bool plain_double_ = false;

  const ExtraRelations* extra_ = nullptr;
  std::vector<uint8_t> state_;  // kNew / kOnStack / kDone, | kHasExtra | kNotSink
  std::vector<Frame> stack_;
  int64_t sinks_ = 0, cycle_roots_ = 0;
};

}  // namespace vob::mpvo

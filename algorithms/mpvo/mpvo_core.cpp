#include "algorithms/mpvo/mpvo_core.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "harness/geometry/predicates.h"
#include "harness/scene/space_curve.h"

namespace vob::mpvo {

std::vector<ParamSpec> renumber_params() {
  return {ParamSpec::boolean("renumber", true,
                             "renumber cells and points along a space-filling curve of the cell "
                             "centroids in prepare (orders in input ids either way)"),
          ParamSpec::choice("curve", "hilbert", {"hilbert", "morton"}, "the curve renumber follows"),
          ParamSpec::boolean("keep_coherent", true,
                             "with renumber: keep the input numbering unless the curve's has fewer "
                             "far point reuses (cache-miss estimate in prepare; false: always renumber)")};
}

RenumberOption renumber_option(const ResolvedParams& p) {
  return {p.get_bool("renumber"), p.get_choice("curve") == "morton" ? Curve::Morton : Curve::Hilbert,
          p.get_bool("keep_coherent")};
}

void ExtraRelations::build_from_pairs(size_t cells,
                                      const std::vector<std::pair<int32_t, int32_t>>& pairs) {
  offsets.assign(cells + 1, 0);
  not_sink.assign(cells, 0);
  for (const auto& [front, behind_cell] : pairs) {
    if (front < 0 || static_cast<size_t>(front) >= cells || behind_cell < 0 ||
        static_cast<size_t>(behind_cell) >= cells)
      throw std::out_of_range("ExtraRelations: cell id out of range");
    ++offsets[front + 1];
    not_sink[behind_cell] = 1;
  }
  for (size_t c = 0; c < cells; ++c) offsets[c + 1] += offsets[c];
  behind.resize(pairs.size());
  // Placed from each list's end backwards (the pairs' order kept within a list, no cursor
  // array to allocate every frame): offsets[c + 1] ends as c's start, then moves to c.
  for (auto p = pairs.rbegin(); p != pairs.rend(); ++p) behind[--offsets[p->first + 1]] = p->second;
  std::copy(offsets.begin() + 1, offsets.end(), offsets.begin());
  offsets[cells] = static_cast<int32_t>(pairs.size());
}

void sort_unique_pairs(std::vector<std::pair<int32_t, int32_t>>& pairs, size_t cells) {
  PairSortScratch scratch;
  sort_unique_pairs(pairs, cells, scratch);
}

void sort_unique_pairs(std::vector<std::pair<int32_t, int32_t>>& pairs, size_t cells, PairSortScratch& scratch) {
  // Two passes cost O(pairs + cells), std::sort O(pairs log pairs). With 291k pairs on 200k
  // cells (XMPVO, 200k-cell helix, view 4) the ray queries took 145-149 ms with std::sort,
  // 130-136 with the passes.
  if (cells > 4 * pairs.size() + 1024) {
    std::sort(pairs.begin(), pairs.end());
  } else {
    std::vector<std::pair<int32_t, int32_t>>& by_second = scratch.by_second;
    std::vector<int32_t>& start = scratch.start;
    by_second.resize(pairs.size());
    start.resize(cells + 1);
    const auto pass = [&](const std::vector<std::pair<int32_t, int32_t>>& from,
                          std::vector<std::pair<int32_t, int32_t>>& to, auto id) {
      std::fill(start.begin(), start.end(), 0);
      for (const auto& p : from) {
        const int32_t c = id(p);
        if (c < 0 || static_cast<size_t>(c) >= cells) throw std::out_of_range("sort_unique_pairs: cell id out of range");
        ++start[c + 1];
      }
      for (size_t c = 0; c < cells; ++c) start[c + 1] += start[c];
      for (const auto& p : from) to[start[id(p)]++] = p;
    };
    pass(pairs, by_second, [](const std::pair<int32_t, int32_t>& p) { return p.second; });
    pass(by_second, pairs, [](const std::pair<int32_t, int32_t>& p) { return p.first; });
  }
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

void ExtraRelations::clear() {
  offsets.clear();
  behind.clear();
  not_sink.clear();
  cells.clear();
}

size_t ExtraRelations::bytes() const {
  return offsets.capacity() * sizeof(int32_t) + behind.capacity() * sizeof(int32_t) +
         not_sink.capacity() + cells.capacity() * sizeof(int32_t) +
         span.capacity() * sizeof(span[0]);
}

void MpvoCore::prepare(const Scene& scene, PhaseClock& clock, RenumberOption renumber) {
  Scene work = scene;
  std::vector<int32_t> input_id;
  double far_input = -1, far_curve = -1;
  if (renumber.on) {
    std::vector<int32_t> order;
    { auto p = clock.phase("renumber along a space curve"); order = curve_cell_order(scene.mesh(), renumber.curve); }
    bool better = true;
    if (renumber.keep_coherent) {
      auto p = clock.phase("numbering coherence");
      far_input = far_reuse_fraction(scene.mesh(), {});
      far_curve = far_reuse_fraction(scene.mesh(), order);
      better = far_curve < far_input;
    }
    if (better) {
      auto p = clock.phase("renumber along a space curve");
      RenumberedMesh r = permute_cells(scene.mesh(), order);
      input_id = std::move(r.input_cell);
      work = Scene::from_mesh(scene.name(), std::move(r.mesh), scene.params());
    }
  }
  { auto p = clock.phase("unique faces"); work.faces(); }
  { auto p = clock.phase("face planes"); work.face_planes(); }
  bind(work);
  input_id_ = std::move(input_id);
  far_input_ = far_input;
  far_curve_ = far_curve;
}

void MpvoCore::bind(const Scene& scene) {
  scene_ = scene;
  input_id_.clear();
  mesh_ = &scene_.mesh();
  faces_ = &scene_.faces();
  planes_ = &scene_.face_planes();
  const Aabb box = mesh_->bounds();
  coord_bound_ = box.empty() ? 0.0
                             : length(Vec3{std::max(std::fabs(box.lo.x), std::fabs(box.hi.x)),
                                           std::max(std::fabs(box.lo.y), std::fabs(box.hi.y)),
                                           std::max(std::fabs(box.lo.z), std::fabs(box.hi.z))});
  const size_t nf = faces_->num_faces(), nc = mesh_->num_cells();
  neighbour_.assign(faces_->cell_faces.size(), -1);
  face_slot_.assign(2 * nf, 0xff);
  for (size_t c = 0; c < nc; ++c) {
    const int32_t begin = faces_->cell_face_offsets[c], count = faces_->cell_face_offsets[c + 1] - begin;
    if (count > kExtraSlot) throw std::logic_error("MpvoCore: a cell has more than 8 faces");
    for (int32_t k = 0; k < count; ++k) {
      const int32_t f = faces_->cell_faces[begin + k];
      neighbour_[begin + k] = faces_->other(f, static_cast<int32_t>(c));
      face_slot_[2 * f + (faces_->cell0[f] == static_cast<int32_t>(c) ? 0 : 1)] = static_cast<uint8_t>(k);
    }
  }
  // Every cell with four slots (a tetrahedral mesh): cell c's slots start at 4c.
  tet_slots_ = true;
  for (size_t c = 0; c <= nc && tet_slots_; ++c) tet_slots_ = faces_->cell_face_offsets[c] == int32_t(4 * c);
  sign_.assign(nf, 0);
  outbound_.assign(nc, 0);
  behind_mask_.assign(nc, 0);
  state_.assign(mesh_->num_cells(), kNew);
  stack_.clear();
  extra_ = nullptr;
}

int MpvoCore::exact_sign(int32_t f, const Camera& view, Vec3 dir) const {
  const int32_t* v = faces_->face_points(f);
  const Vec3 a = mesh_->points[v[0]], b = mesh_->points[v[1]], c = mesh_->points[v[2]];
  // Eye at infinity behind the view direction: its side is the side of -dir.
  return view.ortho ? -orient_direction(a, b, c, dir) : orient3d(a, b, c, view.eye);
}

void MpvoCore::create_partial_order(const Camera& view) {
  if (!faces_) throw std::logic_error("MpvoCore: create_partial_order before bind");
  const size_t nf = faces_->num_faces();
  std::fill(outbound_.begin(), outbound_.end(), 0);
  std::fill(behind_mask_.begin(), behind_mask_.end(), 0);
  const Vec3* normal = planes_->normal.data();
  const double* offset = planes_->offset.data();
  const int32_t* cell0 = faces_->cell0.data();
  const int32_t* cell1 = faces_->cell1.data();
  const uint8_t* slot = face_slot_.data();
  int8_t* sign = sign_.data();
  uint8_t* outbound = outbound_.data();
  uint8_t* behind = behind_mask_.data();

  // Perspective: s = sign(n.eye + d). Orthographic: the eye is at infinity along -dir,
  // s = sign(-n.dir). Both: value = n.w + w0 with w, w0 fixed per view.
  const Vec3 dir = view.forward();
  const Vec3 w = view.ortho ? -dir : view.eye;
  const double w0_scale = view.ortho ? 0.0 : 1.0;
  const double k = kRelativeBound * (view.ortho ? length(dir) : length(view.eye) + coord_bound_);

  // Counters and the mode in locals: the byte stores below may alias any member. A face's
  // sign is a coin toss on meshes numbered along a curve (which of its cells is cell0 is
  // not coherent there), so the arrow's direction is chosen by selects, not a branch.
  const bool plain = plain_double_;
  int64_t exact_calls = 0, double_wrong = 0, arrows = 0;
  for (size_t f = 0; f < nf; ++f) {
    const Vec3 n = normal[f];
    const double value = n.x * w.x + n.y * w.y + n.z * w.z + w0_scale * offset[f];
    const double bound = (std::fabs(n.x) + std::fabs(n.y) + std::fabs(n.z)) * k;
    int s = (value > 0) - (value < 0);
    if (!plain && !(std::fabs(value) > bound)) {
      const int ds = s;
      s = exact_sign(static_cast<int32_t>(f), view, dir);
      ++exact_calls;
      double_wrong += (ds != s);
    }
    sign[f] = static_cast<int8_t>(s);
    const int32_t c1 = cell1[f];
    if (c1 >= 0 && s != 0) {
      // s > 0: eye on cell1's side, cell1 in front, the arrow leaves cell0.
      const int32_t c0 = cell0[f];
      const int32_t front1 = s > 0, swap = (c0 ^ c1) & -(front1 ^ 1);  // by arithmetic: GCC branches on ?:
      const int32_t from = c0 ^ swap, to = c1 ^ swap;
      ++outbound[from];
      behind[to] |= static_cast<uint8_t>(1u << slot[2 * f + front1]);
      ++arrows;
    }
  }
  exact_calls_ = exact_calls, double_wrong_ = double_wrong, arrows_ = arrows;
}

void MpvoCore::set_face_sign(int32_t f, int s) {
  s = (s > 0) - (s < 0);
  const int old = sign_[f];
  if (old == s) return;
  const int32_t c0 = faces_->cell0[f], c1 = faces_->cell1[f];
  if (c1 >= 0) {
    const uint8_t bit0 = static_cast<uint8_t>(1u << face_slot_[2 * f]);
    const uint8_t bit1 = static_cast<uint8_t>(1u << face_slot_[2 * f + 1]);
    if (old > 0) --outbound_[c0], behind_mask_[c1] &= static_cast<uint8_t>(~bit1), --arrows_;
    if (old < 0) --outbound_[c1], behind_mask_[c0] &= static_cast<uint8_t>(~bit0), --arrows_;
    if (s > 0) ++outbound_[c0], behind_mask_[c1] |= bit1, ++arrows_;
    if (s < 0) ++outbound_[c1], behind_mask_[c0] |= bit0, ++arrows_;
  }
  sign_[f] = static_cast<int8_t>(s);
}

void MpvoCore::begin_dfs(Ordering& out, const ExtraRelations* extra) {
  if (!faces_) throw std::logic_error("MpvoCore: begin_dfs before bind");
  const size_t n = num_cells();
  if (extra && !extra->offsets.empty() && extra->offsets.size() != n + 1)
    throw std::invalid_argument("ExtraRelations: offsets must have cells+1 entries");
  if (extra && !extra->not_sink.empty() && extra->not_sink.size() != n)
    throw std::invalid_argument("ExtraRelations: not_sink must have one entry per cell");
  if (extra && extra->sparse() && extra->span.size() != n)
    throw std::invalid_argument("ExtraRelations: span must have one entry per cell");
  extra_ = extra;
  if (extra && !extra->offsets.empty()) {
    const int32_t* off = extra->offsets.data();
    for (size_t c = 0; c < n; ++c) state_[c] = off[c + 1] != off[c] ? kHasExtra : kNew;
  } else {
    std::fill(state_.begin(), state_.end(), kNew);
  }
  if (extra && !extra->not_sink.empty()) {
    const uint8_t* ns = extra->not_sink.data();
    for (size_t c = 0; c < n; ++c) state_[c] |= ns[c] ? kNotSink : 0;
  }
  if (extra && extra->sparse()) {  // touches only the cells named
    for (int32_t c : extra->cells) state_[c] |= kHasExtra;
    for (int32_t c : extra->behind) state_[c] |= kNotSink;
  }
  out.order.clear();
  out.order.reserve(n);
  sinks_ = cycle_roots_ = 0;
}

void MpvoCore::report_cycle(int32_t closing, Ordering& out) {
  // The cycle is the stack slice from `closing` to the top. Walk it only while the report
  // has room, so a long stack costs at most kMaxReported steps per cycle.
  const size_t room = out.cycles.primitives.size() < CycleReport::kMaxReported
                          ? CycleReport::kMaxReported - out.cycles.primitives.size()
                          : 0;
  std::vector<int32_t> members;
  for (size_t i = stack_.size(); i-- > 0 && members.size() < room;) {
    members.push_back(input_id(stack_[i].cell));
    if (stack_[i].cell == closing) break;
  }
  std::reverse(members.begin(), members.end());
  out.cycles.add(members);
}

template <bool kExtra>
void MpvoCore::dfs_walk(int32_t root, Ordering& out) {
  const int32_t* cfo = faces_->cell_face_offsets.data();
  const int32_t* nbr = neighbour_.data();
  const uint8_t* behind = behind_mask_.data();
  const bool tet = tet_slots_;
  const int32_t* xoff = kExtra ? extra_->offsets.data() : nullptr;
  const std::pair<int32_t, int32_t>* xspan = kExtra && !xoff ? extra_->span.data() : nullptr;
  const int32_t* xbehind = kExtra ? extra_->behind.data() : nullptr;
  // With extra relations the state carries kHasExtra: step it by increments.
  auto advance = [&](int32_t cell, uint8_t to) {
    if constexpr (kExtra) ++state_[cell]; else state_[cell] = to;
  };
  const int32_t* in_id = input_id_.empty() ? nullptr : input_id_.data();

  stack_.clear();
  stack_.push_back({root, 0});
  advance(root, kOnStack);
  while (!stack_.empty()) {
    const int32_t c = stack_.back().cell;
    int32_t next = stack_.back().next;
    int32_t child = -1;
    const int32_t* row = nbr + (tet ? 4 * c : cfo[c]);  // c's neighbours, by slot
    if (next == 0) {
      // First look at c: ask for what the search reads at each behind neighbour (its state,
      // mask and slots), so that the misses of the next levels overlap instead of queueing.
      // A cell with extra relations reads its span once its faces' searches are done.
      if (kExtra && xspan && (state_[c] & kHasExtra)) __builtin_prefetch(&xspan[c]);
      for (unsigned bits = behind[c]; bits; bits &= bits - 1) {
        const int32_t nb = row[__builtin_ctz(bits)];
        __builtin_prefetch(&state_[nb], 1);
        __builtin_prefetch(&behind[nb]);
        __builtin_prefetch(tet ? &nbr[4 * nb] : &cfo[nb]);
      }
    }
    if (next < kExtraSlot) {
      // Behind neighbours across faces: the set bits of the mask from slot `next` on.
      unsigned bits = behind[c] & (0xffu << next);
      while (bits) {
        const int slot = __builtin_ctz(bits);
        bits &= bits - 1;
        const int32_t nb = row[slot];
        const uint8_t st = state_[nb] & kStateMask;
        if (st == kNew) {
          child = nb;
          next = slot + 1;
          break;
        }
        if (st == kOnStack) report_cycle(nb, out);  // back edge: ignore it, keep going
      }
      if (child < 0) next = kExtraSlot;
    }
    if (kExtra && child < 0 && (state_[c] & kHasExtra)) {
      const int32_t first = xspan ? xspan[c].first : xoff[c];
      const int32_t count = (xspan ? xspan[c].second : xoff[c + 1]) - first;
      while (next - kExtraSlot < count) {
        const int32_t nb = xbehind[first + (next++ - kExtraSlot)];
        const uint8_t st = state_[nb] & kStateMask;
        if (st == kNew) {
          child = nb;
          break;
        }
        if (st == kOnStack) report_cycle(nb, out);
      }
    }
    if (child >= 0) {
      stack_.back().next = next;
      advance(child, kOnStack);
      stack_.push_back({child, 0});
    } else {
      out.order.push_back(in_id ? in_id[c] : c);
      advance(c, kDone);
      stack_.pop_back();
    }
  }
}

bool MpvoCore::dfs_from(int32_t root, Ordering& out) {
  if ((state_[root] & kStateMask) != kNew) return false;
  if (extra_ && (!extra_->offsets.empty() || extra_->sparse()))
    dfs_walk<true>(root, out);
  else
    dfs_walk<false>(root, out);
  return true;
}

// The root loops look at every cell but start a search at few (sinks are rare, and after
// the sinks' searches only cells of cycles are left): they skip eight cells a word at a time
// rather than call dfs_from for each (a call per cell cost about 10% of a frame's DFS).
namespace {
constexpr uint64_t kBytes01 = 0x0101010101010101ull;
uint64_t word_at(const uint8_t* p) {
  uint64_t w;
  std::memcpy(&w, p, sizeof w);
  return w;
}
bool has_zero_byte(uint64_t w) { return ((w - kBytes01) & ~w & (kBytes01 << 7)) != 0; }
}  // namespace

void MpvoCore::dfs_sinks(Ordering& out) {
  const int32_t n = static_cast<int32_t>(num_cells());
  const uint8_t* outbound = outbound_.data();
  for (int32_t c0 = 0; c0 < n; c0 += 8) {
    const int32_t c1 = std::min(n, c0 + 8);
    if (c1 - c0 == 8 && !has_zero_byte(word_at(outbound + c0))) continue;  // no sink among them
    for (int32_t c = c0; c < c1; ++c)
      if (is_sink(c)) {
        ++sinks_;
        dfs_from(c, out);
      }
  }
}

void MpvoCore::dfs_unvisited(Ordering& out) {
  const int32_t n = static_cast<int32_t>(num_cells());
  const uint64_t done = kDone * kBytes01, mask = kStateMask * kBytes01;
  for (int32_t c0 = 0; c0 < n; c0 += 8) {
    const int32_t c1 = std::min(n, c0 + 8);
    if (c1 - c0 == 8 && (word_at(state_.data() + c0) & mask) == done) continue;  // all output
    for (int32_t c = c0; c < c1; ++c)
      if (dfs_from(c, out)) ++cycle_roots_;
  }
}

void MpvoCore::add_counters(Ordering& out) const {
  out.counters["exact_sign_calls"] = static_cast<double>(exact_calls_);
  out.counters["double_sign_wrong"] = static_cast<double>(double_wrong_);
  out.counters["arrows"] = static_cast<double>(arrows_);
  out.counters["sink_cells"] = static_cast<double>(sinks_);
  out.counters["cycle_roots"] = static_cast<double>(cycle_roots_);
  out.counters["renumbered"] = renumbered() ? 1.0 : 0.0;
  if (far_input_ >= 0) {
    out.counters["far_reuse_input"] = far_input_;
    out.counters["far_reuse_curve"] = far_curve_;
  }
}

size_t MpvoCore::bytes() const {
  return neighbour_.capacity() * sizeof(int32_t) + face_slot_.capacity() + sign_.capacity() +
         outbound_.capacity() + behind_mask_.capacity() + state_.capacity() +
         stack_.capacity() * sizeof(Frame) +
         (renumbered() ? input_id_.capacity() * sizeof(int32_t) + scene_.bytes() + scene_.derived_bytes() : 0);
}

}  // namespace vob::mpvo

#include "algorithms/voxel/grid_traversal.h"

#include <algorithm>
#include <cmath>

namespace vob::voxel {

namespace {

double axis_of(Vec3 v, int a) { return a == 0 ? v.x : a == 1 ? v.y : v.z; }

// The two other axes of a, ascending.
std::array<int, 2> others(int a) {
  return a == 0 ? std::array<int, 2>{1, 2} : a == 1 ? std::array<int, 2>{0, 2} : std::array<int, 2>{0, 1};
}

// One part of an axis: [lo, hi) traversed upwards (up) or downwards.
struct Part {
  int lo, hi;
  bool up;
};
int parts_of(const AxisSplit& a, Part p[2]) {
  int m = 0;
  if (a.kv > 0) p[m++] = {0, a.kv, true};
  if (a.kv < a.n) p[m++] = {a.kv, a.n, false};
  return m;
}

// Row of the runs along `inner` holding the voxel whose other coordinates are (ca, cb) on
// axes (a, b), in either order.
int64_t row_of(const RunIndex& r, int inner, int a, int64_t ca, int64_t cb) {
  const AxisRuns& ar = r.runs[inner];
  return ar.p == a ? ca + int64_t(r.n[ar.p]) * cb : cb + int64_t(r.n[ar.p]) * ca;
}

}  // namespace

size_t RunIndex::bytes() const {
  size_t b = 0;
  for (const AxisRuns& a : runs)
    b += a.row_start.capacity() * 8 + (a.start.capacity() + a.len.capacity()) * 4;
  return b;
}

RunIndex build_run_index(const VoxelGrid& g) {
  RunIndex r;
  r.n = g.dims;
  r.stride = {1, int64_t(g.dims[0]), int64_t(g.dims[0]) * g.dims[1]};
  r.values = g.values.data();
  r.threshold = g.threshold;
  r.lo = g.dims;
  const int nx = g.dims[0], ny = g.dims[1], nz = g.dims[2];
  for (int a = 0; a < 3; ++a) {
    AxisRuns& ar = r.runs[a];
    ar.axis = a;
    ar.p = others(a)[0];
    ar.q = others(a)[1];
    ar.row_start.assign(int64_t(r.n[ar.p]) * r.n[ar.q] + 1, 0);
  }
  // Memory order visits every row of every axis in ascending order along it, so one scan
  // finds run starts (significant, previous along the axis not) for all three axes.
  auto scan = [&](auto&& on_voxel) {
    int64_t id = 0;
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i, ++id) {
          if (!(g.values[id] > g.threshold)) continue;
          const int c[3] = {i, j, k};
          for (int a = 0; a < 3; ++a) r.lo[a] = std::min(r.lo[a], c[a]), r.hi[a] = std::max(r.hi[a], c[a]);
          const int64_t rows[3] = {j + int64_t(ny) * k, i + int64_t(nx) * k, i + int64_t(nx) * j};
          for (int a = 0; a < 3; ++a) {
            const bool starts = c[a] == 0 || !(g.values[id - r.stride[a]] > g.threshold);
            on_voxel(a, rows[a], starts, c[a]);
          }
        }
  };
  int64_t sig = 0;
  scan([&](int a, int64_t row, bool starts, int) {
    if (starts) ++r.runs[a].row_start[row + 1];
    if (a == 0) ++sig;
  });
  r.significant = sig;
  std::array<std::vector<int64_t>, 3> cursor;
  for (int a = 0; a < 3; ++a) {
    AxisRuns& ar = r.runs[a];
    for (size_t i = 1; i < ar.row_start.size(); ++i) ar.row_start[i] += ar.row_start[i - 1];
    ar.start.resize(ar.row_start.back());
    ar.len.assign(ar.row_start.back(), 0);
    cursor[a].assign(ar.row_start.begin(), ar.row_start.end() - 1);
  }
  scan([&](int a, int64_t row, bool starts, int c) {
    AxisRuns& ar = r.runs[a];
    if (starts) ar.start[cursor[a][row]++] = c;
    ++ar.len[cursor[a][row] - 1];
  });
  return r;
}

Splits eye_splits(const VoxelGrid& g, const Camera& cam) {
  if (cam.ortho) return view_direction_splits(g, cam);
  Splits s;
  for (int a = 0; a < 3; ++a) {
    s[a].n = g.dims[a];
    s[a].e = (axis_of(cam.eye, a) - axis_of(g.origin, a)) / axis_of(g.spacing, a);
    // Clamp in doubles first: a far eye must not overflow the int conversion.
    const double kv = std::clamp(std::floor(s[a].e + 0.5), 0.0, double(g.dims[a]));
    s[a].kv = static_cast<int>(kv);
    if (s[a].split()) s[a].m2 = static_cast<int64_t>(std::floor(2 * s[a].e));
  }
  return s;
}

Splits view_direction_splits(const VoxelGrid& g, const Camera& cam) {
  const Vec3 f = cam.forward();
  Splits s;
  for (int a = 0; a < 3; ++a) {
    s[a].n = g.dims[a];
    // Looking towards +a, the far voxels have high indices: one part traversed downwards.
    s[a].kv = axis_of(f, a) > 0 ? 0 : g.dims[a];
  }
  return s;
}

int split_axes(const Splits& s) {
  return int(s[0].split()) + int(s[1].split()) + int(s[2].split());
}

int occupied_split_axes(const Splits& s, const RunIndex& r) {
  int m = 0;
  for (int a = 0; a < 3; ++a) m += s[a].split() && r.lo[a] < s[a].kv && r.hi[a] >= s[a].kv;
  return m;
}

Permutation fixed_permutation() { return {2, 1, 0}; }

Permutation wbtf_permutation(const Camera& cam) {
  const Vec3 f = cam.forward();
  Permutation p{0, 1, 2};
  std::stable_sort(p.begin(), p.end(),
                   [&](int a, int b) { return std::fabs(axis_of(f, a)) > std::fabs(axis_of(f, b)); });
  return p;
}

Permutation ip_permutation(const Camera& cam, const Splits& s) {
  Permutation p = wbtf_permutation(cam);
  // The first unsplit axis in WBTF order goes outermost; volume-on keeps WBTF's choice.
  for (int i = 0; i < 3; ++i)
    if (!s[p[i]].split()) {
      std::rotate(p.begin(), p.begin() + i, p.begin() + i + 1);
      break;
    }
  return p;
}

void traverse_subvolumes(const RunIndex& r, const Splits& s, const Permutation& perm,
                         int32_t* out, TraversalStats& st) {
  const int ao = perm[0], am = perm[1], ai = perm[2];
  const AxisRuns& ar = r.runs[ai];
  Part po[2], pm[2], pi[2];
  const int no = parts_of(s[ao], po), nm = parts_of(s[am], pm), ni = parts_of(s[ai], pi);
  int64_t w = 0;
  for (int x = 0; x < no; ++x)
    for (int y = 0; y < nm; ++y)
      for (int z = 0; z < ni; ++z) {
        const Part O = po[x], M = pm[y], I = pi[z];
        ++st.subvolumes;
        for (int oi = 0; oi < O.hi - O.lo; ++oi) {
          const int o = O.up ? O.lo + oi : O.hi - 1 - oi;
          for (int mi = 0; mi < M.hi - M.lo; ++mi) {
            const int m = M.up ? M.lo + mi : M.hi - 1 - mi;
            const int64_t base = o * r.stride[ao] + m * r.stride[am];
            const int64_t row = row_of(r, ai, ao, o, m);
            const int64_t r0 = ar.row_start[row], r1 = ar.row_start[row + 1];
            const int64_t step = r.stride[ai];
            if (I.up) {
              for (int64_t q = r0; q < r1; ++q) {
                const int lo = std::max<int>(ar.start[q], I.lo), hi = std::min<int>(ar.start[q] + ar.len[q], I.hi);
                if (lo >= hi) continue;
                ++st.runs;
                for (int c = lo; c < hi; ++c) out[w++] = static_cast<int32_t>(base + c * step);
              }
            } else {
              for (int64_t q = r1 - 1; q >= r0; --q) {
                const int lo = std::max<int>(ar.start[q], I.lo), hi = std::min<int>(ar.start[q] + ar.len[q], I.hi);
                if (lo >= hi) continue;
                ++st.runs;
                for (int c = hi - 1; c >= lo; --c) out[w++] = static_cast<int32_t>(base + c * step);
              }
            }
          }
        }
      }
  st.visited += w;
}

std::vector<int32_t> interleaved_sequence(const AxisSplit& a) {
  std::vector<int32_t> seq;
  seq.reserve(a.n);
  int lo = 0, hi = a.n - 1;  // lower part walks up to kv - 1, upper part down to kv
  while (lo < a.kv && hi >= a.kv)
    seq.push_back(lo + hi <= a.m2 ? lo++ : hi--);
  while (lo < a.kv) seq.push_back(lo++);
  while (hi >= a.kv) seq.push_back(hi--);
  return seq;
}

void traverse_interleaved_explicit(const RunIndex& r, const Splits& s, const Permutation& perm,
                                   int32_t* out, TraversalStats& st) {
  const auto so = interleaved_sequence(s[perm[0]]), sm = interleaved_sequence(s[perm[1]]),
             si = interleaved_sequence(s[perm[2]]);
  const int64_t step_o = r.stride[perm[0]], step_m = r.stride[perm[1]], step_i = r.stride[perm[2]];
  const float* v = r.values;
  const float t = r.threshold;
  int64_t w = 0;
  for (int32_t o : so)
    for (int32_t m : sm) {
      const int64_t base = o * step_o + m * step_m;
      for (int32_t c : si) {
        const int64_t id = base + c * step_i;
        if (v[id] > t) out[w++] = static_cast<int32_t>(id);
      }
    }
  st.visited += int64_t(so.size()) * sm.size() * si.size();
  st.subvolumes += 1;
}

void traverse_interleaved_implicit(const RunIndex& r, const Splits& s, const Permutation& perm,
                                   int32_t* out, TraversalStats& st) {
  const int ao = perm[0], am = perm[1], ai = perm[2];
  const auto so = interleaved_sequence(s[ao]), sm = interleaved_sequence(s[am]);
  const AxisRuns& ar = r.runs[ai];
  const int kv = s[ai].kv;
  const int64_t m2 = s[ai].m2;
  const int32_t* rs = ar.start.data();
  const int32_t* rl = ar.len.data();
  const int64_t step = r.stride[ai];
  int64_t w = 0, runs = 0;
  for (int32_t o : so)
    for (int32_t m : sm) {
      const int64_t base = o * r.stride[ao] + m * r.stride[am];
      const int64_t row = row_of(r, ai, ao, o, m);
      const int64_t r0 = ar.row_start[row], r1 = ar.row_start[row + 1];
      if (r0 == r1) continue;
      // Two run pointers (Algorithm 4), one per part of the inner axis, each walking towards
      // the dividing plane; the farther one is emitted first, the lower on a tie. Each turn
      // emits the whole stretch that stays farther than the other pointer's voxel.
      int64_t qa = r0, qb = r1 - 1;
      int64_t ca = rs[qa], cb = rs[qb] + rl[qb] - 1;
      bool la = ca < kv, lb = cb >= kv;
      runs += int64_t(la) + int64_t(lb);
      while (la && lb) {
        if (ca + cb <= m2) {
          const int64_t end = std::min<int64_t>({rs[qa] + rl[qa], m2 - cb + 1, kv});
          for (; ca < end; ++ca) out[w++] = static_cast<int32_t>(base + ca * step);
          if (ca == rs[qa] + rl[qa]) {
            if (++qa == r1) { la = false; break; }
            ca = rs[qa];
            ++runs;
          }
          la = ca < kv;
        } else {
          const int64_t stop = std::max<int64_t>({rs[qb] - 1, m2 - ca, kv - 1});
          for (; cb > stop; --cb) out[w++] = static_cast<int32_t>(base + cb * step);
          if (cb < rs[qb]) {
            if (--qb < r0) { lb = false; break; }
            cb = rs[qb] + rl[qb] - 1;
            ++runs;
          }
          lb = cb >= kv;
        }
      }
      // One part left: its runs in a tight loop, up to the dividing plane.
      if (la)
        for (;;) {
          const int64_t end = std::min<int64_t>(rs[qa] + rl[qa], kv);
          for (; ca < end; ++ca) out[w++] = static_cast<int32_t>(base + ca * step);
          if (ca >= kv || ++qa == r1 || rs[qa] >= kv) break;
          ca = rs[qa];
          ++runs;
        }
      if (lb)
        for (;;) {
          const int64_t stop = std::max<int64_t>(rs[qb] - 1, kv - 1);
          for (; cb > stop; --cb) out[w++] = static_cast<int32_t>(base + cb * step);
          if (cb < kv || --qb < r0 || rs[qb] + rl[qb] - 1 < kv) break;
          cb = rs[qb] + rl[qb] - 1;
          ++runs;
        }
    }
  st.visited += w;
  st.runs += runs;
  st.subvolumes += 1;
}

}  // namespace vob::voxel

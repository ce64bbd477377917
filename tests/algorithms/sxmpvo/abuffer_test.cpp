// SXMPVO's A-buffer, PN lists and PIX-list pairing, on hand-made lists.
#include <gtest/gtest.h>

#include "algorithms/sxmpvo/abuffer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <random>

using namespace vob::sxmpvo;

namespace {

int32_t front(int32_t cell) { return cell * 2 + 1; }
int32_t back(int32_t cell) { return cell * 2; }

// Entries as a batch, as the scans record them (each its own face).
ABuffer::RawBatch batch_of(std::vector<ABuffer::Raw>::const_iterator b, std::vector<ABuffer::Raw>::const_iterator e) {
  ABuffer::RawBatch c;
  for (; b != e; ++b) c.push_back(*b);
  return c;
}
ABuffer::RawBatch batch_of(const std::vector<ABuffer::Raw>& v) { return batch_of(v.begin(), v.end()); }

std::vector<double> depths(const ABuffer& a, int64_t pixel) {
  std::vector<double> t;
  for (int32_t i = a.head(pixel); i >= 0; i = a.entry(i).next) t.push_back(a.entry(i).t);
  return t;
}

// The PN relations as (occluding, occluded) pairs, by occluding cell, from the sparse form.
std::vector<std::pair<int32_t, int32_t>> relations(const PnLists& pn, size_t cells) {
  vob::mpvo::ExtraRelations x;
  pn.to_relations(x);
  EXPECT_TRUE(x.offsets.empty());
  EXPECT_EQ(x.span.size(), cells);
  std::vector<std::pair<int32_t, int32_t>> r;
  for (int32_t c : x.cells)
    for (int32_t k = x.span[c].first; k < x.span[c].second; ++k) r.emplace_back(c, x.behind[k]);
  std::stable_sort(r.begin(), r.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return r;
}

// What pair_pix_list writes to and reuses, for `cells` cells; pair() pairs one pixel's list.
struct Pairing {
  PnLists pn;
  PairStats st;
  std::vector<PixEntry> scratch;
  explicit Pairing(size_t cells) { pn.reset(cells); }
  void pair(const ABuffer& buf, int64_t pixel, double tie_eps = 1e-9) {
    pair_pix_list(buf, pixel, tie_eps, scratch, pn, st);
  }
};

}  // namespace

TEST(ABuffer, KeepsDecreasingDepthAndCountsHeadInsertions) {
  ABuffer a;
  a.reset(2);
  a.insert(0, 1.0, back(0));
  a.insert(0, 3.0, back(1));  // farther: head
  a.insert(0, 2.0, back(2));  // between: walks one link
  a.insert(0, 0.5, back(3));  // nearest: walks to the tail
  a.insert(1, 7.0, front(4));
  a.finish();
  EXPECT_EQ(depths(a, 0), (std::vector<double>{3.0, 2.0, 1.0, 0.5}));
  EXPECT_EQ(depths(a, 1), (std::vector<double>{7.0}));
  EXPECT_EQ(a.entries(), 5);
  EXPECT_EQ(a.head_insertions(), 3);
  EXPECT_EQ(a.walk_steps(), 1 + 3);
  a.reset(1);
  EXPECT_EQ(a.entries(), 0);
  EXPECT_EQ(a.head(0), -1);
}

// Batches recorded in any order (faces scanned in storage order) give the lists and counts
// of the arrivals in rank order (the sorted face order).
TEST(ABuffer, ReplaysArrivalsByRank) {
  ABuffer by_rank, shuffled;
  by_rank.reset(2);
  by_rank.insert(0, 1.0, back(0));
  by_rank.insert(0, 3.0, back(1));
  by_rank.insert(1, 5.0, back(1));
  by_rank.insert(0, 2.0, front(2));
  by_rank.insert(0, 0.5, back(3));
  by_rank.finish();
  // The same entries with their ranks, recorded last rank first, in two batches.
  const ABuffer::RawBatch b1 = batch_of({{0.5, back(3), 0, 4}, {2.0, front(2), 0, 3}});
  const ABuffer::RawBatch b2 = batch_of({{5.0, back(1), 1, 2}, {3.0, back(1), 0, 1}, {1.0, back(0), 0, 0}});
  shuffled.reset(2);
  shuffled.append(b1);
  shuffled.append(b2);
  shuffled.finish();
  for (int64_t p = 0; p < 2; ++p) {
    EXPECT_EQ(depths(shuffled, p), depths(by_rank, p));
    for (int32_t i = shuffled.head(p), j = by_rank.head(p); i >= 0; i = shuffled.entry(i).next, j = by_rank.entry(j).next)
      EXPECT_EQ(shuffled.entry(i).item, by_rank.entry(j).item);
  }
  EXPECT_EQ(shuffled.entries(), 5);
  EXPECT_EQ(shuffled.head_insertions(), by_rank.head_insertions());
  EXPECT_EQ(shuffled.head_insertions(), 3);  // 1.0, 3.0 on pixel 0; 5.0 on pixel 1
  EXPECT_EQ(shuffled.walk_steps(), by_rank.walk_steps());
}

namespace {

// Entries (ranks unset) given ranks in a shuffled arrival order, recorded in two shuffled
// batches and ordered in two pixel ranges, as SXMPVO does: the lists and counts must be
// those of the paper's linked-list insertion, done naively. Returns the walk steps.
int64_t expect_naive_lists(std::vector<ABuffer::Raw> all, int64_t pixels, std::mt19937& rng) {
  std::shuffle(all.begin(), all.end(), rng);  // arrival order
  for (size_t r = 0; r < all.size(); ++r) all[r].rank = int32_t(r);
  std::vector<std::vector<std::pair<double, int32_t>>> naive(pixels);  // far to near
  int64_t heads = 0, walks = 0;
  for (const ABuffer::Raw& r : all) {
    auto& l = naive[r.pixel];
    size_t j = 0;
    while (j < l.size() && l[j].first > r.t) ++j;  // behind every entry farther than itself
    heads += j == 0;
    walks += int64_t(j);
    l.insert(l.begin() + j, {r.t, r.item});
  }
  std::shuffle(all.begin(), all.end(), rng);  // recorded in any order
  const ABuffer::RawBatch b1 = batch_of(all.begin(), all.begin() + all.size() / 3),
                         b2 = batch_of(all.begin() + all.size() / 3, all.end());
  ABuffer a;
  a.reset(pixels);
  a.append(b2);
  a.append(b1);
  a.gather();
  a.order(0, pixels / 4);
  a.order(pixels / 4, pixels);
  const auto as_text = [](const std::vector<std::pair<double, int32_t>>& l) {  // NaN equals NaN
    std::string s;
    for (const auto& [t, item] : l) s += std::to_string(t) + ":" + std::to_string(item) + " ";
    return s;
  };
  for (int64_t p = 0; p < pixels; ++p) {
    std::vector<std::pair<double, int32_t>> got;
    for (int32_t i = a.head(p); i >= 0; i = a.entry(i).next) got.emplace_back(a.entry(i).t, a.entry(i).item);
    EXPECT_EQ(as_text(got), as_text(naive[p])) << "pixel " << p;
  }
  EXPECT_EQ(a.head_insertions(), heads);
  EXPECT_EQ(a.walk_steps(), walks);
  return walks;
}

}  // namespace

// Lists of 0 to 79 entries, depths with ties and, in every 7th list, a NaN.
TEST(ABuffer, ListsMatchLinkedListInsertion) {
  std::mt19937 rng(3);
  const int64_t pixels = 80;
  std::vector<ABuffer::Raw> all;
  for (int64_t p = 0; p < pixels; ++p)
    for (int64_t i = 0; i < p; ++i)
      all.push_back({p % 7 == 3 && i == p / 2 ? std::nan("") : double(rng() % 12), back(int32_t(i)), int32_t(p), 0});
  EXPECT_GT(expect_naive_lists(all, pixels, rng), 1000);
}

// Many short lists (1 to 16 entries, as on a fine mesh's image) whose depths are drawn from
// a few values, signed zeros and infinities among them, so that most entries tie.
TEST(ABuffer, ShortListsWithTiesMatchLinkedListInsertion) {
  std::mt19937 rng(11);
  const double values[] = {0.0, -0.0, 1.0, 2.5, 2.5000000000000004, HUGE_VAL, -HUGE_VAL};
  const int64_t pixels = 3000;
  std::vector<ABuffer::Raw> all;
  for (int64_t p = 0; p < pixels; ++p)
    for (int64_t i = 0, k = 1 + p % 16; i < k; ++i)
      all.push_back({values[rng() % 7], int32_t(rng() % 2 ? front(int32_t(i)) : back(int32_t(i))), int32_t(p), 0});
  EXPECT_GT(expect_naive_lists(all, pixels, rng), 10000);
}

// The lanes (lists of 2 to 16 entries sorted by rank in AVX2) against the scalar insertion
// sort: lists of 1 to 20 entries whose depths mostly grow with the rank (every arrival a
// head insertion, the lanes' case), with ties among few values and signed zeros, some with
// one pair out of order, some with a NaN or an infinity; ordered in ranges taken last first,
// so that a list written 8 or 16 entries wide must not spill over a range already ordered.
TEST(ABuffer, LanesGiveTheScalarListsAndCounts) {
  if (!__builtin_cpu_supports("avx2")) GTEST_SKIP() << "no AVX2 on this CPU";
  std::mt19937 rng(29);
  const int64_t pixels = 4000;
  std::vector<ABuffer::Raw> all;
  int32_t next_rank = 0;
  for (int64_t p = 0; p < pixels; ++p) {
    const int k = 1 + int(p % 20);
    std::vector<double> t(k);
    double d = double(rng() % 4);
    for (int i = 0; i < k; ++i) {
      d += double(rng() % 3) * 0.5;  // steps of 0, 0.5 or 1: many ties
      t[i] = d;
    }
    if (p % 5 == 1 && k > 1) std::swap(t[rng() % k], t[rng() % k]);
    if (p % 13 == 2) t[rng() % k] = std::nan("");
    if (p % 17 == 3) t[k - 1] = HUGE_VAL;
    if (p % 11 == 4) t[0] = -0.0;
    if (p % 11 == 5 && k > 1) t[0] = 0.0, t[1] = -0.0;
    for (int i = 0; i < k; ++i)  // rank order = i order; ranks spread, not consecutive
      all.push_back({t[i], int32_t(rng() % 2 ? front(i) : back(i)), int32_t(p), next_rank += 1 + int32_t(rng() % 3)});
  }
  std::shuffle(all.begin(), all.end(), rng);  // recorded in any order
  const ABuffer::RawBatch b1 = batch_of(all.begin(), all.begin() + all.size() / 2),
                         b2 = batch_of(all.begin() + all.size() / 2, all.end());
  ABuffer lanes, scalar;
  scalar.set_lanes(false);
  for (ABuffer* a : {&lanes, &scalar}) {
    a->reset(pixels);
    a->append(b1);
    a->append(b2);
    a->gather();
  }
  const int64_t cuts[] = {0, 7, 1000, 1001, 2500, pixels};
  for (int r = 4; r >= 0; --r) lanes.order(cuts[r], cuts[r + 1]);
  scalar.order(0, pixels);
  EXPECT_GT(lanes.lane_lists(), pixels / 2);
  EXPECT_EQ(scalar.lane_lists(), 0);
  for (int64_t p = 0; p < pixels; ++p) {
    ASSERT_EQ(lanes.end(p) - lanes.begin(p), scalar.end(p) - scalar.begin(p));
    for (int32_t i = lanes.head(p), j = scalar.head(p); j >= 0; i = lanes.entry(i).next, j = scalar.entry(j).next) {
      ASSERT_GE(i, 0) << "pixel " << p;
      EXPECT_EQ(std::memcmp(&lanes.entry(i).t, &scalar.entry(j).t, sizeof(double)), 0) << "pixel " << p;
      EXPECT_EQ(lanes.entry(i).item, scalar.entry(j).item) << "pixel " << p;
    }
  }
  EXPECT_EQ(lanes.head_insertions(), scalar.head_insertions());
  EXPECT_EQ(lanes.walk_steps(), scalar.walk_steps());
  EXPECT_GT(scalar.walk_steps(), 100);
}

TEST(PnLists, NoDuplicatesAndMoveToFront) {
  PnLists pn;
  pn.reset(4);
  pn.add(0, 1);
  pn.add(0, 2);  // list of 0: 2, 1
  pn.add(0, 2);  // at the head
  pn.add(0, 1);  // below the head: moved to the front, list 1, 2
  pn.add(3, 1);
  EXPECT_EQ(pn.relations(), 3);
  EXPECT_EQ(pn.queries(), 5);
  EXPECT_EQ(pn.found_at_head(), 1);
  EXPECT_EQ(pn.moved_to_front(), 1);
  EXPECT_EQ(relations(pn, 4), (std::vector<std::pair<int32_t, int32_t>>{{0, 1}, {0, 2}, {3, 1}}));
  vob::mpvo::ExtraRelations x;
  pn.to_relations(x);
  std::vector<int32_t> occluded = x.behind;  // the cells that are no sinks
  std::sort(occluded.begin(), occluded.end());
  EXPECT_EQ(occluded, (std::vector<int32_t>{1, 1, 2}));
  pn.reset(4);  // a new frame forgets the old lists
  EXPECT_EQ(pn.relations(), 0);
  EXPECT_TRUE(relations(pn, 4).empty());
}

// Cook et al.'s Fig. 6, pixel D: far to near b1 a3 c2 c3 d1 d3 e2 e3 (back-facing faces at
// odd positions from the far end). Pairs (a3, c2), (c3, d1), (d3, e2): c occludes a, d
// occludes c, e occludes d.
// Random queries, repeats among them, over two frames: the same lists and counts as naive
// move-to-front lists.
TEST(PnLists, MatchNaiveMoveToFrontLists) {
  std::mt19937 rng(5);
  const size_t cells = 3 * 4096;
  PnLists pn;
  for (int frame = 0; frame < 2; ++frame) {
    pn.reset(cells);
    std::vector<std::vector<int32_t>> naive(cells);  // head first
    int64_t at_head = 0, moved = 0, steps = 0;
    for (int q = 0; q < 20000; ++q) {
      const int32_t occluding = int32_t(rng() % 3) * 4096 + int32_t(rng() % 8);
      const int32_t occluded = int32_t(rng() % 5);
      std::vector<int32_t>& l = naive[occluding];
      const auto it = std::find(l.begin(), l.end(), occluded);
      steps += it == l.end() ? int64_t(l.size()) : int64_t(it - l.begin()) + 1;
      if (it == l.begin() && !l.empty()) {
        ++at_head;
      } else if (it != l.end()) {
        l.erase(it);
        l.insert(l.begin(), occluded);
        ++moved;
      } else {
        l.insert(l.begin(), occluded);
      }
      if (q % 3 == 0) pn.add(occluding, occluded), pn.add(occluding, occluded);  // a repeat
      else pn.add(occluding, occluded);
      if (q % 3 == 0) ++at_head, ++steps;
    }
    EXPECT_EQ(pn.found_at_head(), at_head);
    EXPECT_EQ(pn.moved_to_front(), moved);
    EXPECT_EQ(pn.search_steps(), steps);
    vob::mpvo::ExtraRelations x;
    pn.to_relations(x);
    for (size_t c = 0; c < cells; ++c) {
      const std::vector<int32_t> got(x.behind.begin() + x.span[c].first, x.behind.begin() + x.span[c].second);
      EXPECT_EQ(got, naive[c]) << "cell " << c;
    }
  }
}

TEST(PairPixList, Figure6PixelD) {
  enum { a, b, c, d, e };
  ABuffer buf;
  buf.reset(1);
  const std::pair<double, int32_t> list[] = {{8, back(b)},  {7, front(a)}, {6, back(c)},
                                             {5, front(c)}, {4, back(d)},  {3, front(d)},
                                             {2, back(e)},  {1, front(e)}};
  for (const auto& [t, item] : list) buf.insert(0, t, item);  // nearest first: never at head
  buf.finish();
  Pairing p(5);
  p.pair(buf, 0);
  EXPECT_EQ(p.st.pairs, 3);
  EXPECT_EQ(p.st.tie_reorders, 0);
  EXPECT_EQ(p.st.unpaired, 0);
  EXPECT_EQ(relations(p.pn, 5), (std::vector<std::pair<int32_t, int32_t>>{{c, a}, {d, c}, {e, d}}));
}

// Touching faces: the exit face of the near cell 1 and the entry face of the far cell 0
// lie at the same depth and arrive in the wrong order; the tie is reordered so that 0 is
// behind 1. A ray through a silhouette edge of cell 2 in the gap: its two faces at one
// depth, in the wrong order; reordered, giving 3 behind 2 behind 1.
TEST(PairPixList, TiesAreReorderedToRestoreAlternation) {
  ABuffer buf;
  buf.reset(2);
  // Pixel 0, far to near: back(0) 9, [back(1), front(0)] at 5 in the wrong order, front(1) 1.
  buf.insert(0, 1, front(1));
  buf.insert(0, 5, front(0));
  buf.insert(0, 5, back(1));  // equal depth: goes before front(0), the wrong order
  buf.insert(0, 9, back(0));
  // Pixel 1, far to near: back(3) 9, front(3) 7, [front(2), back(2)] at 5, back(1) 3, front(1) 1.
  buf.insert(1, 1, front(1));
  buf.insert(1, 3, back(1));
  buf.insert(1, 5, back(2));
  buf.insert(1, 5 + 1e-12, front(2));  // rounding put the entry face just behind
  buf.insert(1, 7, front(3));
  buf.insert(1, 9, back(3));
  buf.finish();
  Pairing p(4);
  p.pair(buf, 0);
  EXPECT_EQ(relations(p.pn, 4), (std::vector<std::pair<int32_t, int32_t>>{{1, 0}}));
  p.pn.reset(4);
  p.pair(buf, 1);
  EXPECT_EQ(relations(p.pn, 4), (std::vector<std::pair<int32_t, int32_t>>{{1, 2}, {2, 3}}));
  EXPECT_EQ(p.st.tie_reorders, 2);
  EXPECT_EQ(p.st.unpaired, 0);
  // Two reorders in one list, the second within the range the first rotated (so on the
  // copy the first made), and the list itself left as it was. Far to near: back(0) 9,
  // [back(1), back(2), front(0), front(1)] at 7, front(2) 1.
  ABuffer two;
  two.reset(1);
  two.insert(0, 1, front(2));
  two.insert(0, 7, front(1));  // equal depths: each later one goes farther
  two.insert(0, 7, front(0));
  two.insert(0, 7, back(2));
  two.insert(0, 7, back(1));
  two.insert(0, 9, back(0));
  two.finish();
  std::vector<int32_t> before;
  for (int32_t i = two.head(0); i >= 0; i = two.entry(i).next) before.push_back(two.entry(i).item);
  EXPECT_EQ(before, (std::vector<int32_t>{back(0), back(1), back(2), front(0), front(1), front(2)}));
  Pairing q(3);
  q.pair(two, 0);
  EXPECT_EQ(relations(q.pn, 3), (std::vector<std::pair<int32_t, int32_t>>{{1, 0}, {2, 1}}));
  EXPECT_EQ(q.st.tie_reorders, 2);
  EXPECT_EQ(q.st.unpaired, 0);
  std::vector<int32_t> after;
  for (int32_t i = two.head(0); i >= 0; i = two.entry(i).next) after.push_back(two.entry(i).item);
  EXPECT_EQ(after, before);
  // Without a tolerance the rounding case is no tie: alternation breaks and is counted.
  Pairing strict(4);
  strict.pair(buf, 1, 0.0);
  EXPECT_EQ(strict.st.tie_reorders, 0);
  EXPECT_GT(strict.st.unpaired, 0);
}

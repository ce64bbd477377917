// SXMPVO's per-frame image-space structures (Cook et al., section 4.1): the A-buffer of
// exterior-face entries per pixel (PIX lists, kept in decreasing depth by insertion), the
// pairing of consecutive front-facing / back-facing entries into pseudo-neighbour (PN)
// relations, and the PN lists, kept free of duplicates by a move-to-front search.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/mpvo/mpvo_core.h"

namespace vob::sxmpvo {

// One PIX entry: ray parameter t of the hit, the owning cell and whether the face is
// front-facing (item = cell * 2 + front), and the next (nearer) entry of the list or -1.
struct PixEntry {
  double t;
  int32_t item;
  int32_t next;
  PixEntry() {}  // left unset: gather() writes every entry of a frame's lists
  PixEntry(double t_, int32_t item_, int32_t next_) : t(t_), item(item_), next(next_) {}
  int32_t cell() const { return item >> 1; }
  bool front() const { return item & 1; }
};

// The PIX lists. Entries arrive in face order (nearest centroid first) and each list is
// kept in decreasing depth as if every entry were inserted into it on arrival, exactly as
// the paper's linked lists: same order, same head-insertion count. They are laid out in
// one array per range of pixels (SXMPVO: a band of rows), each pixel's list contiguous,
// because walking linked entries that lie far apart in a pool cost one cache miss per
// entry (87% of the pairing time).
// An entry's arrival is its rank, not the moment it is recorded: faces may be scanned in
// any order (storage order, where their data lie close together) and finish() replays the
// arrivals of each list by rank (gather() stages the lists in a second array, which
// order() reads).
class ABuffer {
 public:
  // Empties every list (keeps the storage) for `pixels` pixels: pixels [first, first +
  // pixels) of the frame (entries name frame pixels; head(), begin() and end() take the
  // pixel's place in that range).
  void reset(int64_t pixels, int64_t first = 0);
  // An entry as it is recorded: depth, item, pixel, and its arrival rank (the rank of its
  // face in the sorted face order).
  struct Raw {
    double t;
    int32_t item, pixel, rank;
  };
  // A batch of recorded entries, as the scans write them: two columns, each entry's depth
  // and its key, pixel | slot << 32, the slot naming its face in the batch's face table
  // (item and rank are the face's). 16 bytes an entry in two lane vectors: with 24-byte
  // records {t, item, pixel, rank} the tiny-face kernel took 49.3 ns a face against 43.4,
  // in shuffles and stores (BM_TinyEntries/2/0). Entries [0, size) are in use; the columns
  // stay allocated past it, so that a kernel may write whole lane vectors beyond its last
  // entry (reserve_more()).
  struct RawBatch {
    struct Face {
      int32_t item, rank;
    };
    std::vector<Face> faces;
    std::vector<double> t;
    std::vector<uint64_t> key;
    size_t size = 0;
    // Where entry i of each column is.
    struct Out {
      double* t;
      uint64_t* key;
      Out operator+(ptrdiff_t k) const { return {t + k, key + k}; }
    };
    static uint64_t make_key(int32_t pixel, int32_t slot) {
      return static_cast<uint32_t>(pixel) | uint64_t(static_cast<uint32_t>(slot)) << 32;
    }
    Out at(size_t i) { return {t.data() + i, key.data() + i}; }
    void clear() {
      size = 0;
      faces.clear();
    }
    // A face's slot, for its entries' keys.
    int32_t add_face(int32_t item, int32_t rank) {
      faces.push_back({item, rank});
      return static_cast<int32_t>(faces.size() - 1);
    }
    // Room for n more entries past size: the columns are grown (doubled), never shrunk.
    void reserve_more(size_t n) {
      if (t.size() < size + n) grow(std::max(2 * t.size(), size + n + 64));
    }
    void push_back(double t_, int32_t pixel, int32_t slot) {
      reserve_more(1);
      t[size] = t_, key[size] = make_key(pixel, slot);
      ++size;
    }
    void push_back(const Raw& r) { push_back(r.t, r.pixel, add_face(r.item, r.rank)); }  // a face of its own
    Raw operator[](size_t i) const {
      const Face& f = faces[key[i] >> 32];
      return {t[i], f.item, static_cast<int32_t>(static_cast<uint32_t>(key[i])), f.rank};
    }
    size_t bytes() const {
      return faces.capacity() * sizeof(Face) + t.capacity() * sizeof(double) + key.capacity() * sizeof(uint64_t);
    }

   private:
    void grow(size_t n) { t.resize(n), key.resize(n); }
  };
  // Records an entry of pixel `pixel` that arrives after every entry recorded so far.
  void insert(int64_t pixel, double t, int32_t item) {
    raw_.push_back({t, item, static_cast<int32_t>(pixel), static_cast<int32_t>(entries_++)});
  }
  // Records a batch of entries with their own ranks (faces scanned in parallel chunks, in
  // any order: the ranks, not the batches, decide the arrival order). Ranks of one pixel's
  // entries must differ, except for entries of one face (which never share a pixel). The
  // batch is read in place by finish(): it must stay alive and unchanged until then.
  void append(const RawBatch& batch) {
    batches_.push_back(&batch);
    entries_ += static_cast<int64_t>(batch.size);
  }
  // Builds the lists: per pixel, the entries by increasing rank inserted one by one so that
  // the list stays in decreasing t; an entry at least as far as the head becomes the head
  // (a head insertion), otherwise it goes behind every entry farther than itself.
  // finish() = gather() and order(0, pixels()): a caller may order pixel ranges one at a
  // time and use each while its lists are in cache.
  void finish() {
    gather();
    order(0, pixels_);
  }
  void gather();                    // every entry into its pixel's list, by rank (once after reset())
  void order(int64_t p0, int64_t p1);  // the lists of pixels [p0, p1) after gather()
  // order() sorts lists of up to 16 entries by rank in AVX2 lanes when the CPU has them,
  // and replays a two-entry list by one compare (the same lists and counts); false keeps
  // the scalar insertion sort (tests compare them).
  void set_lanes(bool on) { lanes_ = on; }
  int64_t lane_lists() const { return lane_lists_; }  // lists order() took without the scalar replay since reset()
  int64_t pixels() const { return pixels_; }
  // First (farthest) entry of a pixel's list, or -1; entries link to the next nearer one.
  int32_t head(int64_t pixel) const {
    return offsets_[pixel] < offsets_[pixel + 1] ? offsets_[pixel] : -1;
  }
  const PixEntry& entry(int32_t id) const { return list_[id]; }
  // A pixel's list as one range, farthest first (the same entries as from head()).
  const PixEntry* begin(int64_t pixel) const { return list_.data() + offsets_[pixel]; }
  const PixEntry* end(int64_t pixel) const { return list_.data() + offsets_[pixel + 1]; }
  int64_t entries() const { return entries_; }
  int64_t head_insertions() const { return head_insertions_; }
  int64_t walk_steps() const { return walk_steps_; }  // entries passed by non-head inserts
  size_t bytes() const {
    return offsets_.capacity() * sizeof(int32_t) +
           raw_.bytes() +
           (staged_.capacity() + list_.capacity()) * sizeof(PixEntry);
  }

 private:
  int64_t pixels_ = 0, first_ = 0;
  int64_t entries_ = 0;
  RawBatch raw_;                          // insert()ed
  std::vector<const RawBatch*> batches_;  // append()ed, read in place
  void order_scalar(int32_t b, int32_t e);  // one list: staged_[b, e) into list_[b, e)
  std::vector<int32_t> offsets_;   // pixels + 1
  std::vector<PixEntry> staged_;   // per pixel, as gathered (rank in `next`)
  std::vector<PixEntry> list_;     // per pixel, decreasing t (and room for a 16-entry write past the last)
  int64_t head_insertions_ = 0, walk_steps_ = 0, lane_lists_ = 0;
  bool lanes_ = true;
  bool ranks_fit_ = true;  // every rank in [0, 2^27): the lanes' keys are rank << 4 | place
};

class PnLists {
 public:
  // Empties the lists of the previous frame (only the cells that had one) for `cells` cells.
  void reset(size_t cells);
  // Records "occluded is behind occluding" unless already recorded. A duplicate found
  // below the head is moved to the head, where the next, coherent query finds it at once.
  void add(int32_t occluding, int32_t occluded);
  // Asks for the list head of `cell` ahead of an add() for it (a cache miss per new pair).
  void prefetch(int32_t cell) const { __builtin_prefetch(&head_[cell]); }
  // The lists as MPVO extra relations (occluded = eligible neighbour of occluding), in the
  // sparse form (touching only the cells with a list).
  void to_relations(mpvo::ExtraRelations& out) const;

  int64_t relations() const { return static_cast<int64_t>(pool_.size()); }
  int64_t queries() const { return queries_; }
  int64_t found_at_head() const { return found_at_head_; }
  int64_t moved_to_front() const { return moved_; }
  int64_t search_steps() const { return steps_; }
  size_t bytes() const {
    return head_.capacity() * sizeof(int32_t) + pool_.capacity() * sizeof(Entry) +
           touched_.capacity() * sizeof(int32_t);
  }

 private:
  struct Entry {
    int32_t cell, next;
  };
  std::vector<int32_t> head_;     // per cell, or -1
  std::vector<Entry> pool_;
  std::vector<int32_t> touched_;  // cells with a list
  int64_t queries_ = 0, found_at_head_ = 0, moved_ = 0, steps_ = 0;
};

inline void PnLists::add(int32_t occluding, int32_t occluded) {
  ++queries_;
  int32_t* link = &head_[occluding];
  if (*link < 0) touched_.push_back(occluding);
  for (int32_t prev = -1, i = *link; i >= 0; prev = i, i = pool_[i].next) {
    ++steps_;
    if (pool_[i].cell != occluded) continue;
    if (prev < 0) {
      ++found_at_head_;
    } else {  // move to front
      pool_[prev].next = pool_[i].next;
      pool_[i].next = *link;
      *link = i;
      ++moved_;
    }
    return;
  }
  pool_.push_back({occluded, *link});
  *link = static_cast<int32_t>(pool_.size() - 1);
}

struct PairStats {
  int64_t lists = 0;          // non-empty PIX lists
  int64_t pairs = 0;          // front-facing / back-facing pairs found (before de-duplication)
  int64_t tie_reorders = 0;   // entries moved within a depth tie to restore alternation
  int64_t unpaired = 0;       // entries that broke alternation with no tie to explain it
  int64_t self_pairs = 0;     // pairs of two faces of one cell (skipped)
  int64_t max_list = 0;
};

// Pairs the PIX list of `pixel`. Far to near, a closed boundary alternates back-facing
// (the ray, going backwards, enters the mesh) and front-facing entries; each front-facing
// entry of cell F followed by a back-facing entry of cell B is a ray gap, and F must be
// drawn before B. Entries whose depths differ by at most `tie` may stand in either order
// (faces that touch, a ray through a silhouette edge): when one breaks the alternation, the
// next entry of the expected kind within the tie is moved up in its place.
// The pairs go to add(occluding, occluded), in the list's order; pairs of two faces of one
// cell are counted and skipped.
template <class AddPair>
void for_each_pix_pair(const ABuffer& abuf, int64_t pixel, double tie, std::vector<PixEntry>& scratch,
                       PairStats& stats, AddPair&& add) {
  if (abuf.head(pixel) < 0) return;
  // Read in place; copied to `scratch` only when a tie is reordered (rare).
  const PixEntry* e = abuf.begin(pixel);
  const size_t k = static_cast<size_t>(abuf.end(pixel) - e);
  ++stats.lists;
  stats.max_list = std::max<int64_t>(stats.max_list, static_cast<int64_t>(k));
  // Far to near: beyond the farthest entry the ray is outside the mesh, so the first entry
  // expected is back-facing.
  bool want_front = false;
  int32_t occluded = -1;  // cell of the last front-facing entry, while in a ray gap
  for (size_t i = 0; i < k; ++i) {
    if (e[i].front() != want_front) {
      size_t j = i + 1;
      while (j < k && e[j].t >= e[i].t - tie && e[j].front() != want_front) ++j;
      if (j < k && e[j].t >= e[i].t - tie) {
        if (e != scratch.data()) {
          scratch.assign(e, e + k);
          e = scratch.data();
        }
        std::rotate(scratch.begin() + i, scratch.begin() + j, scratch.begin() + j + 1);
        ++stats.tie_reorders;
      } else {
        ++stats.unpaired;  // taken as it is: the state follows the entry's own kind
      }
    }
    if (e[i].front()) {
      occluded = e[i].cell();
      want_front = false;
    } else {
      if (occluded >= 0) {
        const int32_t occluding = e[i].cell();
        ++stats.pairs;
        if (occluding == occluded) {
          ++stats.self_pairs;
        } else {
          add(occluding, occluded);
        }
      }
      occluded = -1;
      want_front = true;
    }
  }
}

// The same pairs recorded in `pn` at once.
inline void pair_pix_list(const ABuffer& abuf, int64_t pixel, double tie, std::vector<PixEntry>& scratch,
                          PnLists& pn, PairStats& stats) {
  for_each_pix_pair(abuf, pixel, tie, scratch, stats, [&](int32_t occluding, int32_t occluded) {
    pn.add(occluding, occluded);
  });
}


}  // namespace vob::sxmpvo

#include "harness/oracle/k_metric.h"

#include <algorithm>

namespace vob {

namespace {
// Below this length the quadratic count is faster than sorting and a tree.
constexpr int kQuadraticMax = 48;
}  // namespace

int KCounter::max_k(const double* key_in, const double* key_query, int n) {
  return n <= kQuadraticMax ? quadratic(key_in, key_query, n) : fenwick(key_in, key_query, n);
}

int KCounter::quadratic(const double* key_in, const double* key_query, int n) const {
  int best = 0;
  for (int j = 1; j < n; ++j) {
    int k = 0;
    for (int i = 0; i < j; ++i) k += key_in[i] < key_query[j];
    best = std::max(best, k);
  }
  return best;
}

int KCounter::fenwick(const double* key_in, const double* key_query, int n) {
  sorted_.resize(n);
  for (int i = 0; i < n; ++i) sorted_[i] = {key_in[i], i};
  std::sort(sorted_.begin(), sorted_.end());
  keys_.resize(n);
  rank_.resize(n);
  for (int r = 0; r < n; ++r) {
    keys_[r] = sorted_[r].first;
    rank_[sorted_[r].second] = r;
  }
  tree_.assign(n + 1, 0);
  int best = 0;
  for (int j = 0; j < n; ++j) {
    // Earlier fragments with key_in < key_query[j] hold ranks [0, p).
    const int p = int(std::lower_bound(keys_.begin(), keys_.end(), key_query[j]) - keys_.begin());
    int k = 0;
    for (int i = p; i > 0; i -= i & -i) k += tree_[i];
    best = std::max(best, k);
    for (int i = rank_[j] + 1; i <= n; i += i & -i) ++tree_[i];
  }
  return best;
}

}  // namespace vob

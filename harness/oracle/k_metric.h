// The per-sample k of HAVS Table 2: how many positions a fragment must move to reach its
// sorted place, i.e. the number of fragments drawn before it that are nearer than it.
// A sample's k is the largest over its fragments (0 = drawn in exact back-to-front order).
//
// "Nearer" is decided with two keys per fragment: fragment e drawn earlier is nearer than f
// when key_in(e) < key_query(f). The oracle uses t_in / segment midpoint for cells and
// depth / depth - tolerance for triangles and voxels (see oracle.cpp), so k > 0 exactly
// when the z-buffer test flags a violation.
#pragma once
#include <utility>
#include <vector>

namespace vob {

class KCounter {
 public:
  // Fragments 0..n-1 in drawing order. O(n^2) for short lists, O(n log n) (Fenwick tree
  // over the ranks of key_in) for long ones.
  int max_k(const double* key_in, const double* key_query, int n);

 private:
  int quadratic(const double* key_in, const double* key_query, int n) const;
  int fenwick(const double* key_in, const double* key_query, int n);

  std::vector<std::pair<double, int>> sorted_;
  std::vector<double> keys_;
  std::vector<int> rank_, tree_;
};

}  // namespace vob

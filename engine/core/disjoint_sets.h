#pragma once
// Union-find over 0..n-1 with path halving. A union keeps the smaller root, so the roots (and
// anything numbered by them) do not depend on the order of the unions.

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace linesurf {

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t Find(std::size_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void Union(std::size_t a, std::size_t b) {
    a = Find(a);
    b = Find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }
  /// Number of sets among the first `n` elements.
  std::size_t CountRoots(std::size_t n) {
    std::size_t roots = 0;
    for (std::size_t i = 0; i < n; ++i) roots += Find(i) == i ? 1 : 0;
    return roots;
  }

 private:
  std::vector<std::size_t> parent_;
};

}  // namespace linesurf

// Fixed-radius neighbour search in the plane (paper Section 2.5): every pair of points closer
// than a radius, each pair once. A uniform grid of bins (a cell list) rather than a KD-tree: it
// gives the same pairs, its counting sort maps one-to-one onto the GPU's binning, and its cost is
// linear in the number of points.
#pragma once

#include <vector>

#include "thin_ice_sim/physics/vec2.hpp"

namespace thin_ice {

struct CandidatePair {
  int i;  ///< lower index
  int j;  ///< higher index
  bool operator==(const CandidatePair& o) const { return i == o.i && j == o.j; }
};

/// Reusable search: keeps its buffers between rebuilds so a rebuild allocates nothing once warm.
class FixedRadiusNeighbourSearch {
 public:
  /// All pairs (i < j) with |p_i - p_j| <= radius, sorted by (i, j). Points with non-finite
  /// coordinates take part in no pair. radius must be finite and > 0 (std::invalid_argument).
  /// With threads > 1 the points are split into that many contiguous ranges of i, searched in
  /// parallel and joined in order: the list is the same for any number of threads.
  const std::vector<CandidatePair>& findPairs(const std::vector<Vec2>& points, double radius, int threads = 1);

 private:
  /// Appends the pairs (i, j > i) of point i to `out`, sorted by j.
  void appendPairsOf(int i, const std::vector<Vec2>& points, double radius_squared,
                     std::vector<CandidatePair>& out) const;

  int bins_x_ = 0, bins_y_ = 0;
  std::vector<int> bin_of_point_;
  std::vector<int> bin_start_;      ///< (bins + 1) prefix sums of the counting sort
  std::vector<int> bin_cursor_;     ///< (bins) next free slot per bin during the sort
  std::vector<int> points_by_bin_;  ///< point indices grouped by bin
  std::vector<CandidatePair> pairs_;
  std::vector<std::vector<CandidatePair>> range_pairs_;  ///< (threads) pairs of each range of i
};

/// Brute force O(N^2) reference for tests: same contract as findPairs().
std::vector<CandidatePair> findPairsBruteForce(const std::vector<Vec2>& points, double radius);

}  // namespace thin_ice

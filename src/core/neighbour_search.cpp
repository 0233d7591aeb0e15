// Cell-list neighbour search:
//   box   <- bounding box of the finite points
//   bin   <- square bins of side >= radius, at most ~4 N of them (a far outlier widens the bins
//            instead of blowing up memory: still correct, only more candidates per bin)
//   counting sort of the points by bin
//   for each point i: test the points of the 3 x 3 bins around it, keep j > i within radius
//                     (in parallel over contiguous ranges of i, joined in order)
#include "thin_ice_sim/neighbour_search.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace thin_ice {

const std::vector<CandidatePair>& FixedRadiusNeighbourSearch::findPairs(const std::vector<Vec2>& points,
                                                                        double radius, int threads) {
  if (!(std::isfinite(radius) && radius > 0.0)) {
    std::ostringstream msg;
    msg << "neighbour search: radius = " << radius << " is invalid; allowed: finite > 0 m";
    throw std::invalid_argument(msg.str());
  }
  pairs_.clear();
  const int n = static_cast<int>(points.size());
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  int finite_count = 0;
  for (const Vec2& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    x0 = std::min(x0, p.x); x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y); y1 = std::max(y1, p.y);
    ++finite_count;
  }
  if (finite_count < 2) return pairs_;

  const double max_bins = 4.0 * finite_count + 16.0;
  double bin = radius;
  const double span_x = x1 - x0, span_y = y1 - y0;
  if ((span_x / bin + 1.0) * (span_y / bin + 1.0) > max_bins) {
    // Smallest bin side s with (span_x/s + 1)(span_y/s + 1) <= max_bins, approximately.
    bin = std::max(radius, std::sqrt(span_x * span_y / max_bins) + (span_x + span_y) / max_bins);
    while ((span_x / bin + 1.0) * (span_y / bin + 1.0) > max_bins) bin *= 1.25;
  }
  const int nx = static_cast<int>(span_x / bin) + 1;
  const int ny = static_cast<int>(span_y / bin) + 1;
  const int bins = nx * ny;

  bin_of_point_.assign(n, -1);
  bin_start_.assign(bins + 1, 0);
  for (int k = 0; k < n; ++k) {
    const Vec2 p = points[k];
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    const int bx = std::min(nx - 1, static_cast<int>((p.x - x0) / bin));
    const int by = std::min(ny - 1, static_cast<int>((p.y - y0) / bin));
    bin_of_point_[k] = by * nx + bx;
    ++bin_start_[bin_of_point_[k] + 1];
  }
  for (int b = 0; b < bins; ++b) bin_start_[b + 1] += bin_start_[b];
  points_by_bin_.assign(finite_count, -1);
  bin_cursor_.assign(bin_start_.begin(), bin_start_.end() - 1);
  for (int k = 0; k < n; ++k) {
    if (bin_of_point_[k] >= 0) points_by_bin_[bin_cursor_[bin_of_point_[k]]++] = k;
  }

  bins_x_ = nx;
  bins_y_ = ny;
  const double r2 = radius * radius;
  if (threads <= 1) {
    for (int i = 0; i < n; ++i) appendPairsOf(i, points, r2, pairs_);
    return pairs_;
  }
  range_pairs_.resize(threads);
#pragma omp parallel for num_threads(threads) schedule(static, 1)
  for (int t = 0; t < threads; ++t) {
    std::vector<CandidatePair>& out = range_pairs_[t];
    out.clear();
    const int first = static_cast<int>(static_cast<long>(n) * t / threads);
    const int end = static_cast<int>(static_cast<long>(n) * (t + 1) / threads);
    for (int i = first; i < end; ++i) appendPairsOf(i, points, r2, out);
  }
  for (const std::vector<CandidatePair>& range : range_pairs_) pairs_.insert(pairs_.end(), range.begin(), range.end());
  return pairs_;
}

void FixedRadiusNeighbourSearch::appendPairsOf(int i, const std::vector<Vec2>& points, double radius_squared,
                                               std::vector<CandidatePair>& out) const {
  const int b = bin_of_point_[i];
  if (b < 0) return;
  const int bx = b % bins_x_, by = b / bins_x_;
  const size_t begin = out.size();
  for (int dy = -1; dy <= 1; ++dy) {
    const int cy = by + dy;
    if (cy < 0 || cy >= bins_y_) continue;
    for (int dx = -1; dx <= 1; ++dx) {
      const int cx = bx + dx;
      if (cx < 0 || cx >= bins_x_) continue;
      const int c = cy * bins_x_ + cx;
      for (int s = bin_start_[c]; s < bin_start_[c + 1]; ++s) {
        const int j = points_by_bin_[s];
        if (j <= i) continue;
        const Vec2 d = points[j] - points[i];
        if (d.x * d.x + d.y * d.y <= radius_squared) out.push_back({i, j});
      }
    }
  }
  std::sort(out.begin() + static_cast<long>(begin), out.end(),
            [](const CandidatePair& p, const CandidatePair& q) { return p.j < q.j; });
}

std::vector<CandidatePair> findPairsBruteForce(const std::vector<Vec2>& points, double radius) {
  std::vector<CandidatePair> pairs;
  const double r2 = radius * radius;
  const int n = static_cast<int>(points.size());
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y)) continue;
    for (int j = i + 1; j < n; ++j) {
      if (!std::isfinite(points[j].x) || !std::isfinite(points[j].y)) continue;
      const Vec2 d = points[j] - points[i];
      if (d.x * d.x + d.y * d.y <= r2) pairs.push_back({i, j});
    }
  }
  return pairs;
}

}  // namespace thin_ice

// Per-cell index lists of pairs (bonds or contacts), built on the host: for each cell, the entries
// 2 x pair (+1 when the cell is the pair's j) in pair order, so that a gather over them sums in a
// fixed order whatever the number of threads.
#pragma once

#include <vector>

namespace thin_ice {

/// Index lists: for each cell, the entries (pair index, side) of the pairs it belongs to.
struct Incidence {
  std::vector<int> offsets;  ///< (cells + 1)
  std::vector<int> entries;  ///< 2 * pair + (1 if the cell is j else 0)

  void build(int cells, const std::vector<int>& first, const std::vector<int>& second) {
    offsets.assign(cells + 1, 0);
    for (size_t p = 0; p < first.size(); ++p) {
      ++offsets[first[p] + 1];
      ++offsets[second[p] + 1];
    }
    for (int c = 0; c < cells; ++c) offsets[c + 1] += offsets[c];
    entries.assign(offsets[cells], 0);
    std::vector<int> cursor(offsets.begin(), offsets.end() - 1);
    for (size_t p = 0; p < first.size(); ++p) {  // pair order: each cell's list is sorted
      entries[cursor[first[p]]++] = 2 * static_cast<int>(p);
      entries[cursor[second[p]]++] = 2 * static_cast<int>(p) + 1;
    }
  }
};

}  // namespace thin_ice

// Contact list rebuild on the device: see contact_list.cuh.
#include "contact_list.cuh"

#include <cub/cub.cuh>

#include <algorithm>

#include "thin_ice_sim/physics/pair_separation.hpp"

namespace thin_ice {
namespace cuda {
namespace {


/// Bin coordinates of a point for bins of side `bin` [m].
__device__ void binOf(const CellMotion& m, double bin, long long& bx, long long& by) {
  bx = (long long)floor(m.x / bin);
  by = (long long)floor(m.y / bin);
}

__device__ unsigned int hashBin(long long bx, long long by, unsigned int table_mask) {
  return (static_cast<unsigned int>(bx * 73856093LL) ^ static_cast<unsigned int>(by * 19349663LL)) & table_mask;
}

__global__ void hashCells(int n, const CellMotion* motion, double bin, unsigned int table_mask, unsigned int* keys,
                          int* cells) {
  const int k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k >= n) return;
  long long bx, by;
  binOf(motion[k], bin, bx, by);
  keys[k] = hashBin(bx, by, table_mask);
  cells[k] = k;
}

__global__ void binBounds(int n, const unsigned int* sorted_keys, int* bin_start, int* bin_end) {
  const int s = blockIdx.x * blockDim.x + threadIdx.x;
  if (s >= n) return;
  const unsigned int key = sorted_keys[s];
  if (s == 0 || sorted_keys[s - 1] != key) bin_start[key] = s;
  if (s == n - 1 || sorted_keys[s + 1] != key) bin_end[key] = s + 1;
}

struct RebuildView {  // CandidateInputs plus the sorted bins
  int n;
  const CellMotion* motion;
  const double* radius;
  double search_radius, margin, bin;
  unsigned int table_mask;
  const int* bin_start;
  const int* bin_end;
  const int* sorted_cells;
  const int* bond_offsets;
  const int* bond_entries;
  const int* bond_i;
  const int* bond_j;
  const unsigned char* bond_broken;
};

/// Calls visit(j) for every j > i that is a contact candidate of i: centroids within the search
/// radius and bounding circles (radius + margin) that meet, and no intact bond between them
/// (the CPU's rebuildContacts()). Bins that hash alike are visited once.
template <class Visit>
__device__ void forEachCandidate(const RebuildView& v, int i, Visit visit) {
  const CellMotion& a = v.motion[i];
  long long bx, by;
  binOf(a, v.bin, bx, by);
  unsigned int seen[9];
  int seen_count = 0;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const unsigned int key = hashBin(bx + dx, by + dy, v.table_mask);
      bool repeated = false;
      for (int s = 0; s < seen_count; ++s) repeated = repeated || seen[s] == key;
      if (repeated) continue;
      seen[seen_count++] = key;
      const int begin = v.bin_start[key], end = v.bin_end[key];
      for (int s = begin; s < end; ++s) {
        const int j = v.sorted_cells[s];
        if (j <= i) continue;
        const double ex = v.motion[j].x - a.x, ey = v.motion[j].y - a.y;
        const double d2 = ex * ex + ey * ey;
        if (d2 > v.search_radius * v.search_radius) continue;
        const double reach = v.radius[i] + v.radius[j] + v.margin;
        if (d2 > reach * reach) continue;
        bool bonded = false;
        for (int e = v.bond_offsets[i]; e < v.bond_offsets[i + 1] && !bonded; ++e) {
          const int b = v.bond_entries[e] >> 1;
          bonded = !v.bond_broken[b] && (v.bond_i[b] == j || v.bond_j[b] == j);
        }
        if (!bonded) visit(j);
      }
    }
  }
}

__global__ void countCandidates(RebuildView v, int* count) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= v.n) return;
  int c = 0;
  forEachCandidate(v, i, [&](int) { ++c; });
  count[i] = c;
}

__global__ void writeCandidates(RebuildView v, const int* offsets, int* pair_i, int* pair_j) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= v.n) return;
  const int begin = offsets[i];
  int c = 0;
  forEachCandidate(v, i, [&](int j) {
    pair_i[begin + c] = i;
    pair_j[begin + c] = j;
    ++c;
  });
  for (int a = begin + 1; a < begin + c; ++a) {  // insertion sort by j: the list is sorted by (i, j)
    const int key = pair_j[a];
    int b = a - 1;
    while (b >= begin && pair_j[b] > key) {
      pair_j[b + 1] = pair_j[b];
      --b;
    }
    pair_j[b + 1] = key;
  }
}

/// S_ref and the separating edge of each new pair: the old list's when the pair was there, else
/// -1 (new) and kNoSeparatingEdge.
__global__ void carryReferences(int pairs, const int* pair_i, const int* pair_j, int old_count, const int* old_i,
                                const int* old_j, const double* old_reference, const int* old_separating_edge,
                                double* reference, int* separating_edge) {
  const int p = blockIdx.x * blockDim.x + threadIdx.x;
  if (p >= pairs) return;
  const int i = pair_i[p], j = pair_j[p];
  int lo = 0, hi = old_count;  // first old entry not below (i, j)
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    if (old_i[mid] < i || (old_i[mid] == i && old_j[mid] < j)) lo = mid + 1;
    else hi = mid;
  }
  const bool kept = lo < old_count && old_i[lo] == i && old_j[lo] == j;
  reference[p] = kept ? old_reference[lo] : -1.0;
  separating_edge[p] = kept ? old_separating_edge[lo] : kNoSeparatingEdge;
}

__global__ void countIncidence(int pairs, const int* pair_i, const int* pair_j, int* count) {
  const int p = blockIdx.x * blockDim.x + threadIdx.x;
  if (p >= pairs) return;
  atomicAdd(&count[pair_i[p]], 1);
  atomicAdd(&count[pair_j[p]], 1);
}

__global__ void writeIncidence(int pairs, const int* pair_i, const int* pair_j, const int* offsets, int* cursor,
                               int* entries) {
  const int p = blockIdx.x * blockDim.x + threadIdx.x;
  if (p >= pairs) return;
  const int i = pair_i[p], j = pair_j[p];
  entries[offsets[i] + atomicAdd(&cursor[i], 1)] = 2 * p;
  entries[offsets[j] + atomicAdd(&cursor[j], 1)] = 2 * p + 1;
}

/// Each cell's entries in pair order (the CPU's order): the gather then sums alike on both.
__global__ void sortIncidence(int n, const int* offsets, int* entries) {
  const int k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k >= n) return;
  for (int a = offsets[k] + 1; a < offsets[k + 1]; ++a) {
    const int key = entries[a];
    int b = a - 1;
    while (b >= offsets[k] && entries[b] > key) {
      entries[b + 1] = entries[b];
      --b;
    }
    entries[b + 1] = key;
  }
}

}  // namespace

DeviceContactList::DeviceContactList(int cells) : cells_(cells) {
  while (table_size_ < 2u * static_cast<unsigned int>(std::max(cells, 1))) table_size_ <<= 1;
  bin_start_.resize(table_size_);
  bin_end_.resize(table_size_);
  keys_.resize(cells);
  sorted_keys_.resize(cells);
  cell_ids_.resize(cells);
  sorted_cells_.resize(cells);
  count_per_cell_.resize(cells + 1);
  candidate_offsets_.resize(cells + 1);
  cursor_.resize(cells + 1);
  offsets_.resize(cells + 1);
  reserve(static_cast<size_t>(8) * std::max(cells, 1));
}

bool DeviceContactList::reserve(size_t pairs) {
  if (pairs <= pair_i_.size() && pair_i_.size() > 0) return false;
  const size_t capacity = std::max(pairs + pairs / 2, static_cast<size_t>(1024));
  // Contents dropped: rebuild() copies the new list in after reserving.
  pair_i_.resize(capacity);
  pair_j_.resize(capacity);
  reference_area_.resize(capacity);
  separating_edge_.resize(capacity);
  touching_.resize(capacity);
  load_.resize(capacity);
  entries_.resize(2 * capacity);
  return true;
}

bool DeviceContactList::seed(const std::vector<int>& i, const std::vector<int>& j,
                             const std::vector<double>& reference) {
  const bool moved = reserve(i.size());
  if (!i.empty()) {
    TIS_CUDA_CHECK(cudaMemcpy(pair_i_.get(), i.data(), i.size() * sizeof(int), cudaMemcpyHostToDevice));
    TIS_CUDA_CHECK(cudaMemcpy(pair_j_.get(), j.data(), j.size() * sizeof(int), cudaMemcpyHostToDevice));
    TIS_CUDA_CHECK(cudaMemcpy(reference_area_.get(), reference.data(), reference.size() * sizeof(double),
                              cudaMemcpyHostToDevice));
    // Checkpoints hold no edges: every byte 0xff is kNoSeparatingEdge (-1) in each int.
    TIS_CUDA_CHECK(cudaMemset(separating_edge_.get(), 0xff, i.size() * sizeof(int)));
  }
  count_ = static_cast<int>(i.size());
  return moved;
}

void DeviceContactList::download(std::vector<int>& i, std::vector<int>& j, std::vector<double>& reference) const {
  i.resize(count_);
  j.resize(count_);
  reference.resize(count_);
  if (count_ == 0) return;
  TIS_CUDA_CHECK(cudaMemcpy(i.data(), pair_i_.get(), count_ * sizeof(int), cudaMemcpyDeviceToHost));
  TIS_CUDA_CHECK(cudaMemcpy(j.data(), pair_j_.get(), count_ * sizeof(int), cudaMemcpyDeviceToHost));
  TIS_CUDA_CHECK(cudaMemcpy(reference.data(), reference_area_.get(), count_ * sizeof(double), cudaMemcpyDeviceToHost));
}

long DeviceContactList::pairsKeptApart() const {
  std::vector<int> edge(count_);
  if (count_ > 0) {
    TIS_CUDA_CHECK(cudaMemcpy(edge.data(), separating_edge_.get(), count_ * sizeof(int), cudaMemcpyDeviceToHost));
  }
  return static_cast<long>(edge.size()) - std::count(edge.begin(), edge.end(), kNoSeparatingEdge);
}

bool DeviceContactList::rebuild(const CandidateInputs& in, cudaStream_t stream) {
  const int n = cells_;
  const int grid = blocksFor(n);
  // Bins of the search radius, hashed; cells sorted by bin.
  hashCells<<<grid, kThreads, 0, stream>>>(n, in.motion, in.search_radius, table_size_ - 1, keys_.get(),
                                            cell_ids_.get());
  size_t temp_bytes = 0;
  int end_bit = 0;
  while ((1u << end_bit) < table_size_) ++end_bit;
  TIS_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(nullptr, temp_bytes, keys_.get(), sorted_keys_.get(), cell_ids_.get(),
                                                 sorted_cells_.get(), n, 0, end_bit, stream));
  temp_.resize(temp_bytes);
  TIS_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(temp_.get(), temp_bytes, keys_.get(), sorted_keys_.get(),
                                                 cell_ids_.get(), sorted_cells_.get(), n, 0, end_bit, stream));
  TIS_CUDA_CHECK(cudaMemsetAsync(bin_start_.get(), 0, bin_start_.bytes(), stream));
  TIS_CUDA_CHECK(cudaMemsetAsync(bin_end_.get(), 0, bin_end_.bytes(), stream));
  binBounds<<<grid, kThreads, 0, stream>>>(n, sorted_keys_.get(), bin_start_.get(), bin_end_.get());

  const RebuildView view = {n,
                            in.motion,
                            in.radius,
                            in.search_radius,
                            in.margin,
                            in.search_radius,
                            table_size_ - 1,
                            bin_start_.get(),
                            bin_end_.get(),
                            sorted_cells_.get(),
                            in.bond_offsets,
                            in.bond_entries,
                            in.bond_i,
                            in.bond_j,
                            in.bond_broken};
  // Count and scan the candidates; the total is the one number the host needs.
  TIS_CUDA_CHECK(cudaMemsetAsync(count_per_cell_.get(), 0, count_per_cell_.bytes(), stream));
  countCandidates<<<grid, kThreads, 0, stream>>>(view, count_per_cell_.get());
  TIS_CUDA_CHECK(cub::DeviceScan::ExclusiveSum(nullptr, temp_bytes, count_per_cell_.get(), candidate_offsets_.get(),
                                               n + 1, stream));
  temp_.resize(temp_bytes);
  TIS_CUDA_CHECK(cub::DeviceScan::ExclusiveSum(temp_.get(), temp_bytes, count_per_cell_.get(),
                                               candidate_offsets_.get(), n + 1, stream));
  int total = 0;
  TIS_CUDA_CHECK(cudaMemcpyAsync(&total, candidate_offsets_.get() + n, sizeof(int), cudaMemcpyDeviceToHost, stream));
  TIS_CUDA_CHECK(cudaStreamSynchronize(stream));
  // Write the new list into scratch, sorted by (i, j), with S_ref carried from the old list.
  new_i_.resize(total);
  new_j_.resize(total);
  new_reference_.resize(total);
  new_separating_edge_.resize(total);
  writeCandidates<<<grid, kThreads, 0, stream>>>(view, candidate_offsets_.get(), new_i_.get(), new_j_.get());
  carryReferences<<<blocksFor(total), kThreads, 0, stream>>>(total, new_i_.get(), new_j_.get(), count_,
                                                              pair_i_.get(), pair_j_.get(), reference_area_.get(),
                                                              separating_edge_.get(), new_reference_.get(),
                                                              new_separating_edge_.get());
  TIS_CUDA_CHECK(cudaStreamSynchronize(stream));  // the old list is read; now it may be dropped
  const bool moved = reserve(static_cast<size_t>(total));
  if (total > 0) {
    TIS_CUDA_CHECK(cudaMemcpyAsync(pair_i_.get(), new_i_.get(), total * sizeof(int), cudaMemcpyDeviceToDevice, stream));
    TIS_CUDA_CHECK(cudaMemcpyAsync(pair_j_.get(), new_j_.get(), total * sizeof(int), cudaMemcpyDeviceToDevice, stream));
    TIS_CUDA_CHECK(cudaMemcpyAsync(reference_area_.get(), new_reference_.get(), total * sizeof(double),
                                   cudaMemcpyDeviceToDevice, stream));
    TIS_CUDA_CHECK(cudaMemcpyAsync(separating_edge_.get(), new_separating_edge_.get(), total * sizeof(int),
                                   cudaMemcpyDeviceToDevice, stream));
  }
  count_ = total;

  // Per-cell incidence lists in pair order.
  TIS_CUDA_CHECK(cudaMemsetAsync(count_per_cell_.get(), 0, count_per_cell_.bytes(), stream));
  countIncidence<<<blocksFor(total), kThreads, 0, stream>>>(total, pair_i_.get(), pair_j_.get(), count_per_cell_.get());
  TIS_CUDA_CHECK(cub::DeviceScan::ExclusiveSum(temp_.get(), temp_bytes, count_per_cell_.get(), offsets_.get(), n + 1,
                                               stream));
  TIS_CUDA_CHECK(cudaMemsetAsync(cursor_.get(), 0, cursor_.bytes(), stream));
  writeIncidence<<<blocksFor(total), kThreads, 0, stream>>>(total, pair_i_.get(), pair_j_.get(), offsets_.get(),
                                                             cursor_.get(), entries_.get());
  sortIncidence<<<grid, kThreads, 0, stream>>>(n, offsets_.get(), entries_.get());
  TIS_CUDA_CHECK(cudaGetLastError());
  return moved;
}

}  // namespace cuda
}  // namespace thin_ice
